// A tool's path of its own (-die_path): its displacement from where it starts, and its turn about its frame's
// origin (-die_path_turn), piecewise linear in turn through given points, over a stroke parameter s that runs
// along the path at half its length (so that a path straight down by 2 U is the stroke U of a die whose lower
// partner stays: the press's U, half the dies' closing). A turn counts in the length as the arc it moves a point
// at the path's reach from the centre (the tube's outer radius), so a piece that only turns has a length too.
// Each piece is taken with a constant motion and spin per unit s; the pieces' ends are kinks of the load path,
// where an increment ends (Scene's LoadPath::kinks). Pure geometry.
#pragma once

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "tubeform/core/core.hpp"

namespace tf {

class ToolPath {
public:
  ToolPath() = default;
  // Through `points` in turn after the start (0, 0), turned there by `turns` (radians, counter-clockwise; none:
  // no turn) after the start's 0, a turn counted at `reach` (> 0 with turns); consecutive points distinct in place
  // or turn (the options' check).
  explicit ToolPath(const std::vector<Vec2> &points, const std::vector<double> &turns = {}, double reach = 0)
  {
    if (!turns.empty() && !(reach > 0)) throw std::invalid_argument("ToolPath: turns need a reach > 0");
    to_ = {{0.0, 0.0}};
    to_.insert(to_.end(), points.begin(), points.end());
    turn_.assign(to_.size(), 0.0);
    for (size_t k = 0; k < turns.size() && k + 1 < to_.size(); ++k) turn_[k + 1] = turns[k];
    at_ = {0.0};
    for (size_t k = 1; k < to_.size(); ++k) {
      const double moved = std::hypot(to_[k][0] - to_[k - 1][0], to_[k][1] - to_[k - 1][1]);
      at_.push_back(at_.back() + 0.5 * std::hypot(moved, reach * (turn_[k] - turn_[k - 1])));
    }
  }
  bool empty() const { return to_.size() < 2; }
  // The stroke parameter at the path's end: half its length (mm).
  double end() const { return empty() ? 0.0 : at_.back(); }
  // The displacement at its last point (where the path ends; 0, 0 for none).
  Vec2 Last() const { return to_.empty() ? Vec2{0.0, 0.0} : to_.back(); }
  // The displacement at stroke s: on the piece that s is on (going forward), past the end along the last one.
  Vec2 At(double s) const
  {
    const size_t k = Piece(s);
    const Vec2 v = Slope(k);
    return {to_[k][0] + (s - at_[k]) * v[0], to_[k][1] + (s - at_[k]) * v[1]};
  }
  // The motion per unit stroke on the piece that a step from s forward runs on.
  Vec2 Motion(double s) const { return Slope(Piece(s)); }
  // The turn at stroke s (radians, counter-clockwise), and its rate per unit stroke on the piece ahead.
  double Turn(double s) const
  {
    const size_t k = Piece(s);
    return turn_[k] + (s - at_[k]) * TurnSlope(k);
  }
  double Spin(double s) const { return TurnSlope(Piece(s)); }
  // The strokes of the inner points (where the motion turns).
  std::vector<double> Turns() const
  {
    if (empty()) return {};
    return {at_.begin() + 1, at_.end() - 1};
  }
  // The largest of -y over the points (how deep the path presses, mm).
  double Deepest() const
  {
    double d = 0;
    for (const Vec2 &p : to_) d = std::max(d, -p[1]);
    return d;
  }
  // Each point mapped by `map` (a tool drawn in another frame), the turns with its orientation (map.det()).
  template <class Map>
  ToolPath Mapped(const Map &map) const
  {
    ToolPath m = *this;
    for (Vec2 &p : m.to_) p = map(p);
    for (double &t : m.turn_) t *= map.det();
    return m;
  }

private:
  std::vector<double> at_;   // the stroke at each point
  std::vector<Vec2> to_;     // the displacement there
  std::vector<double> turn_; // and the turn (radians)

  // A stroke this close to a point (relative to the path's end) is at it: a step starting there runs on the piece
  // after it (the stroke at a kink is the commits' sum, within round-off of the point's).
  static constexpr double kAtPoint = 1e-12;
  size_t Piece(double s) const
  {
    size_t k = 0;
    while (k + 2 < at_.size() && s >= at_[k + 1] - kAtPoint * at_.back()) ++k;
    return k;
  }
  double TurnSlope(size_t k) const { return (turn_[k + 1] - turn_[k]) / (at_[k + 1] - at_[k]); }
  Vec2 Slope(size_t k) const
  {
    const double ds = at_[k + 1] - at_[k];
    return {(to_[k + 1][0] - to_[k][0]) / ds, (to_[k + 1][1] - to_[k][1]) / ds};
  }
};

} // namespace tf
