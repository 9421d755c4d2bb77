// The straight motion the fixed, stroke and force kinds share (motion_fixed.cpp, motion_stroke.cpp,
// motion_force.cpp): moved by the stroke s along a direction d, s d from its drawing (a zero d: it stays).
#pragma once

#include "tubeform/tool/motion.hpp"

namespace tf {

// A direction that moves the tool (stroke and force refuse one that does not).
inline bool Moves(const Vec2 &d) { return d[0] != 0 || d[1] != 0; }

class StraightMotion : public Motion {
public:
  explicit StraightMotion(const Vec2 &d) : d_(d) {}
  // (the stroke times the direction: a fixed tool's signed zeros are a stroke's along no direction)
  Vec2 Offset(double s) const override { return {s * d_[0], s * d_[1]}; }
  Vec2 Direction() const override { return d_; }
  double Travel(double s) const override { return Moves(d_) ? s : 0.0; }
  void Map(const TurnMap &map) override { d_ = map(d_); }

private:
  Vec2 d_;
};

} // namespace tf
