// A map of the plane onto itself that a press or a pass turns its tools by: a reflection, quarter turns, a turn
// by any angle. Pure geometry.
#pragma once

#include "tubeform/core/core.hpp"

namespace tf {

// One of the eight maps of a square onto itself: the reflection y -> -y (if `reflect`), then q quarter turns
// counter-clockwise about the origin; exact: it only swaps and negates coordinates. Then, without a reflection, a
// turn by `angle` (radians, counter-clockwise; 0 for the square's maps): a press turned by any angle.
struct TurnMap {
  bool reflect = false;
  int q = 0;          // 0..3
  double angle = 0.0; // |angle| < pi / 2 (the quarter turns are q's)

  static TurnMap Turn(int quarters) { return {false, ((quarters % 4) + 4) % 4}; }
  // The turn by `radians`: its whole quarter turns exact, the rest by angle.
  static TurnMap TurnBy(double radians);
  bool identity() const { return !reflect && q == 0 && angle == 0; }
  Vec2 operator()(const Vec2 &v) const;
  // The map that undoes this one (a reflection undoes itself).
  TurnMap Inverse() const { return reflect ? *this : TurnMap{false, ((4 - q) % 4), -angle}; }
  // Its determinant: -1 for a reflection (a moment changes sign).
  double det() const { return reflect ? -1.0 : 1.0; }
};

} // namespace tf
