// A tool that stays where it is drawn (-lower_die_motion fixed, the symmetry walls).
#include "tubeform/tool/motion.hpp"

namespace tf {

namespace {
class Fixed : public Motion {
public:
  std::unique_ptr<Motion> Clone() const override { return std::make_unique<Fixed>(*this); }
  std::string Kind() const override { return "fixed"; }
  // (the stroke times a zero motion, as a stroke along no direction: the same signed zeros)
  Vec2 Offset(double s) const override { return {s * d_[0], s * d_[1]}; }
  Vec2 Direction() const override { return d_; }
  void Map(const TurnMap &map) override { d_ = map(d_); }

private:
  Vec2 d_{0, 0};
};
} // namespace

std::unique_ptr<Motion> FixedMotion() { return std::make_unique<Fixed>(); }

} // namespace tf
