// A force-controlled tool (-die_force, -side_force): moved along a direction by a stroke that is an unknown of
// each increment, found from the force it presses with (the contact set's extra unknown, contact/pad.cpp).
#include "tubeform/tool/motion_straight.hpp"

namespace tf {

namespace {
class Force : public StraightMotion {
public:
  using StraightMotion::StraightMotion;
  std::unique_ptr<Motion> Clone() const override { return std::make_unique<Force>(*this); }
  std::string Kind() const override { return "force"; }
  bool Unknown() const override { return true; }
};
} // namespace

std::unique_ptr<Motion> ForceMotion(const Vec2 &direction) { return std::make_unique<Force>(direction); }

const MotionKind &ForceKind()
{
  static const MotionKind kind{"force", {}, nullptr, [](const MotionSpec &s, MotionHandle &m) {
                                 return Moves(s.direction) ? (m = ForceMotion(s.direction), std::string())
                                                           : "a force along no direction";
                               }};
  return kind;
}

} // namespace tf
