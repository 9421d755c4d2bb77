// A tool that stays where it is drawn (-lower_die_motion fixed, the symmetry walls): a straight motion along no
// direction.
#include "tubeform/tool/motion_straight.hpp"

namespace tf {

namespace {
class Fixed : public StraightMotion {
public:
  Fixed() : StraightMotion({0, 0}) {}
  std::unique_ptr<Motion> Clone() const override { return std::make_unique<Fixed>(*this); }
  std::string Kind() const override { return "fixed"; }
};
} // namespace

std::unique_ptr<Motion> FixedMotion() { return std::make_unique<Fixed>(); }

const MotionKind &FixedKind()
{
  static const MotionKind kind{
    "fixed", {},
    nullptr, [](const MotionSpec &, MotionHandle &m) { return m = FixedMotion(), std::string(); },
    "fixed", "stays (fixed; the upper die then travels 2 U, so U is half the dies' closing either way)",
    nullptr, "fixed"};
  return kind;
}

} // namespace tf
