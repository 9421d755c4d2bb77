// A tool that strokes in pulses (a servo press's pulse motion): along its direction by the stroke U, less A times
// a triangle wave of period P in U, y(U) = U - A tri(U / P), tri rising from 0 to 1 over the first half of each
// period and back over the second. At each whole period it is where a plain stroke has it; half a period on it is
// A behind. Its slope is 1 - 2 A / P on the first half (with A > P / 2 it backs off) and 1 + 2 A / P on the second;
// each half period is a kink (a step runs on one piece: the motion is exact, linear on it). Options under its
// tool's prefix: -<prefix>pulse_amplitude A (mm, >= 0; 0: the plain stroke, no kinks), -<prefix>pulse_period P
// (mm of stroke, > 0). The lower die: -lower_die_motion pulse (docs/motions.md).
#include <cmath>

#include "tubeform/tool/motion.hpp"

namespace tf {

namespace {
// A stroke this close below a kink (in half periods) is at it: a step from there runs on the piece after it (the
// stroke at a kink is the commits' sum, within round-off of k P / 2 for the ten thousands of pieces a press holds).
constexpr double kAtKink = 1e-10;

class Pulse : public Motion {
public:
  Pulse(const Vec2 &d, double amplitude, double period) : d_(d), a_(amplitude), p_(period) { Follow(0); }
  std::unique_ptr<Motion> Clone() const override { return std::make_unique<Pulse>(*this); }
  std::string Kind() const override { return "pulse"; }
  Vec2 Offset(double s) const override
  {
    const double y = Travel(s);
    return {y * d_[0], y * d_[1]};
  }
  double Travel(double s) const override { return s - a_ * Wave(s); } // (a_ 0: s exactly, a plain stroke's)
  Vec2 Direction() const override { return {slope_ * d_[0], slope_ * d_[1]}; }
  Vec2 Axis() const override { return d_; }
  void Follow(double s) override
  {
    const double half = std::floor(2 * s / p_ + kAtKink);
    slope_ = a_ == 0 ? 1.0 : std::fmod(half, 2.0) == 0 ? 1 - 2 * a_ / p_ : 1 + 2 * a_ / p_;
  }
  std::vector<double> Kinks(double until) const override
  {
    std::vector<double> k;
    for (double n = 1; a_ != 0 && 0.5 * n * p_ < until; ++n) k.push_back(0.5 * n * p_);
    return k;
  }
  void Map(const TurnMap &map) override { d_ = map(d_); }

private:
  Vec2 d_;           // the direction per unit stroke
  double a_, p_;     // the amplitude (mm) and the period (mm of stroke)
  double slope_ = 1; // the travel per unit stroke on the piece followed

  // The triangle wave at s: 0 at each whole period, 1 half a period on.
  double Wave(double s) const
  {
    const double f = s / p_ - std::floor(s / p_);
    return f < 0.5 ? 2 * f : 2 * (1 - f);
  }
};

PetscErrorCode ReadPulse(PetscOptionItems *PetscOptionsObject, MotionSpec &spec)
{
  PetscReal a = 0, p = 1;
  const char *prefix = PetscOptionsObject->prefix ? PetscOptionsObject->prefix : "";

  PetscFunctionBeginUser;
  PetscCall(PetscOptionsReal("-pulse_amplitude",
                             "a pulse motion: how far behind a plain stroke the tool falls half a period on (mm, "
                             ">= 0; 0: a plain stroke)",
                             "tubeform", a, &a, nullptr));
  PetscCall(
    PetscOptionsReal("-pulse_period", "a pulse motion: its period (mm of stroke U, > 0)", "tubeform", p, &p, nullptr));
  if (PetscOptionsObject->printhelp) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCheck(std::isfinite(a) && a >= 0, PetscOptionsObject->comm, PETSC_ERR_USER_INPUT,
             "-%spulse_amplitude %g: a distance (mm), 0 or more", prefix, (double)a);
  PetscCheck(std::isfinite(p) && p > 0, PetscOptionsObject->comm, PETSC_ERR_USER_INPUT,
             "-%spulse_period %g: a stroke (mm), more than 0", prefix, (double)p);
  spec.own = {a, p};
  PetscFunctionReturn(PETSC_SUCCESS);
}

std::string MakePulse(const MotionSpec &s, MotionHandle &m)
{
  if (s.own.size() != 2 || !(s.own[0] >= 0 && s.own[1] > 0)) return "give an amplitude >= 0 and a period > 0";
  if (s.direction[0] == 0 && s.direction[1] == 0) return "a pulse along no direction";
  m = MotionHandle(std::make_unique<Pulse>(s.direction, s.own[0], s.own[1]));
  return "";
}
} // namespace

const MotionKind &PulseKind()
{
  static const MotionKind kind{
    "pulse", {"pulse_amplitude", "pulse_period"}, ReadPulse, MakePulse, "pulse", nullptr, nullptr, "pulse"};
  return kind;
}

} // namespace tf
