// A press's die path (-stroke_path): strokes in turn from 0, taken at the
// punch speed, so the load factor lambda in [0, 1] is the share of the travel
// done; the turns are kinks of the load path (an increment ends there).
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

namespace tf {

class StrokePath {
public:
  StrokePath() = default;
  // `strokes` in turn after 0 (empty: straight to `stroke`).
  StrokePath(const std::vector<double> &strokes, double stroke)
  {
    at_ = {0.0};
    at_.insert(at_.end(), strokes.begin(), strokes.end());
    if (at_.size() == 1) at_.push_back(stroke);
    for (size_t k = 1; k < at_.size(); ++k) travel_ += std::abs(at_[k] - at_[k - 1]);
  }
  double travel() const { return travel_; } // mm
  double deepest() const
  {
    double d = 0;
    for (double u : at_) d = std::max(d, u);
    return d;
  }
  // The stroke at the share lambda of the travel (a straight path: lambda x stroke, to the last bit).
  double Stroke(double lambda) const
  {
    if (at_.size() == 2) return lambda * at_[1];
    double left = lambda * travel_;
    for (size_t k = 1; k < at_.size(); ++k) {
      const double piece = std::abs(at_[k] - at_[k - 1]);
      if (left <= piece || k + 1 == at_.size()) return at_[k - 1] + std::copysign(left, at_[k] - at_[k - 1]);
      left -= piece;
    }
    return at_.back();
  }
  // The lambdas of the turns.
  std::vector<double> Kinks() const
  {
    std::vector<double> k;
    double done = 0;
    for (size_t i = 1; i + 1 < at_.size(); ++i) k.push_back((done += std::abs(at_[i] - at_[i - 1])) / travel_);
    return k;
  }

private:
  std::vector<double> at_ = {0.0, 0.0};
  double travel_ = 0;
};

} // namespace tf
