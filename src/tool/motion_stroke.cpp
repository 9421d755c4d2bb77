// A tool moved by the stroke along a direction (the dies' default: the upper die down, the lower one up, the side
// dies in; -lower_die_motion fixed: the upper die down by 2 per unit stroke).
#include "tubeform/tool/motion_straight.hpp"

namespace tf {

namespace {
class Stroke : public StraightMotion {
public:
  using StraightMotion::StraightMotion;
  std::unique_ptr<Motion> Clone() const override { return std::make_unique<Stroke>(*this); }
  std::string Kind() const override { return kStrokeMotion; }
};
} // namespace

std::unique_ptr<Motion> StrokeMotion(const Vec2 &direction) { return std::make_unique<Stroke>(direction); }

const MotionKind &StrokeKind()
{
  static const MotionKind kind{kStrokeMotion,
                               {},
                               nullptr,
                               [](const MotionSpec &s, MotionHandle &m) {
                                 return Moves(s.direction) ? (m = StrokeMotion(s.direction), std::string())
                                                           : "a stroke along no direction";
                               },
                               "mirror",
                               "moves up by the stroke U (mirror)",
                               "stroke",
                               "stroke"};
  return kind;
}

MotionHandle::MotionHandle() : m_(StrokeMotion({0, -1})) {}

} // namespace tf
