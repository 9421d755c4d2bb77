// A press's die path (-stroke_path): strokes in turn from 0, taken at the
// punch speed, so the load factor lambda in [0, 1] is the share of the travel
// done; the turns are kinks of the load path (an increment ends there). Or the
// upper die's path of its own (-die_path, tool/path.hpp): the stroke is then
// its parameter, and the press's U half its depth.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include "tubeform/tool/tool.hpp"

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
  // The upper die's own path (its parameter runs over half its length: ToolPath), a lower die staying.
  explicit StrokePath(const ToolPath &die) : die_(die)
  {
    at_ = {0.0, die.end()};
    travel_ = die.end();
  }
  // The press's U at stroke s (the die's own path: half its depth, -y / 2) and the die's sideways displacement.
  // (0 - y / 2: at the start +0, as the stroke's, not -0)
  double U(double s) const { return die_.empty() ? s : 0.0 - 0.5 * die_.At(s)[1]; }
  double Sideways(double s) const { return die_.empty() ? 0.0 : die_.At(s)[0]; }
  // And its turn (degrees, counter-clockwise).
  double Turn(double s) const { return die_.empty() ? 0.0 : die_.Turn(s) * (180 / M_PI); }
  double travel() const { return travel_; } // mm
  // The deepest U.
  double deepest() const
  {
    if (!die_.empty()) return 0.5 * die_.Deepest();
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
  // The lambdas of the turns, and of the tools' kinks at `strokes` (Motion::Kinks, before the travel's end: on a
  // straight path or the die's own, whose stroke runs at the share lambda of the travel).
  std::vector<double> Kinks(const std::vector<double> &strokes) const
  {
    std::vector<double> k;
    for (double s : strokes)
      if (s < travel_) k.push_back(s / travel_);
    double done = 0;
    for (size_t i = 1; i + 1 < at_.size(); ++i) k.push_back((done += std::abs(at_[i] - at_[i - 1])) / travel_);
    return k;
  }

private:
  std::vector<double> at_ = {0.0, 0.0};
  double travel_ = 0;
  ToolPath die_;
};

} // namespace tf
