// A tool moved by the stroke along a direction (the dies' default: the upper die down, the lower one up, the side
// dies in; -lower_die_motion fixed: the upper die down by 2 per unit stroke).
#include "tubeform/tool/motion.hpp"

namespace tf {

namespace {
class Stroke : public Motion {
public:
  explicit Stroke(const Vec2 &d) : d_(d) {}
  std::unique_ptr<Motion> Clone() const override { return std::make_unique<Stroke>(*this); }
  std::string Kind() const override { return "stroke"; }
  Vec2 Offset(double s) const override { return {s * d_[0], s * d_[1]}; }
  Vec2 Direction() const override { return d_; }
  void Map(const TurnMap &map) override { d_ = map(d_); }

private:
  Vec2 d_;
};
} // namespace

std::unique_ptr<Motion> StrokeMotion(const Vec2 &direction) { return std::make_unique<Stroke>(direction); }

MotionHandle::MotionHandle() : m_(StrokeMotion({0, -1})) {}

} // namespace tf
