// A force-controlled tool (-die_force, -side_force): moved along a direction by a stroke that is an unknown of
// each increment, found from the force it presses with (the contact set's extra unknown, contact/pad.cpp).
#include "tubeform/tool/motion.hpp"

namespace tf {

namespace {
class Force : public Motion {
public:
  explicit Force(const Vec2 &d) : d_(d) {}
  std::unique_ptr<Motion> Clone() const override { return std::make_unique<Force>(*this); }
  std::string Kind() const override { return "force"; }
  Vec2 Offset(double s) const override { return {s * d_[0], s * d_[1]}; }
  Vec2 Direction() const override { return d_; }
  bool Unknown() const override { return true; }
  void Map(const TurnMap &map) override { d_ = map(d_); }

private:
  Vec2 d_;
};
} // namespace

std::unique_ptr<Motion> ForceMotion(const Vec2 &direction) { return std::make_unique<Force>(direction); }

} // namespace tf
