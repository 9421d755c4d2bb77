// A force-controlled tool: moved along a direction by a stroke that is an unknown of each increment, found from the
// force it presses with (the contact set's extra unknown, contact/pad.cpp). Its option under its tool's prefix:
// -<prefix>force F (> 0, the force it presses with at the end, rising from 0 over the press; its scene says per
// what). The upper die's: -die_motion force, -die_force (docs/motions.md), and what it goes with in a press (its press
// check); the side dies': -side_motion force, -side_force (each side die's force on the whole tube).
#include <cmath>

#include "tubeform/tool/motion_straight.hpp"

namespace tf {

namespace {
class Force : public StraightMotion {
public:
  using StraightMotion::StraightMotion;
  std::unique_ptr<Motion> Clone() const override { return std::make_unique<Force>(*this); }
  std::string Kind() const override { return kForceMotion; }
  bool Unknown() const override { return true; }
};

PetscErrorCode ReadForce(PetscOptionItems *PetscOptionsObject, MotionSpec &spec)
{
  PetscReal f = spec.force;
  PetscBool set;
  const char *prefix = PetscOptionsObject->prefix ? PetscOptionsObject->prefix : "";

  PetscFunctionBeginUser;
  PetscCall(PetscOptionsReal("-force",
                             "a force motion: the force the tool presses with, rising from 0 to this over the press, "
                             "its stroke an unknown of each increment (N/mm: the upper die's punch load, as the "
                             "history's load; each side die's on the whole tube; docs/motions.md)",
                             "tubeform", f, &f, &set));
  if (PetscOptionsObject->printhelp) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCheck(set, PetscOptionsObject->comm, PETSC_ERR_USER_INPUT,
             "-%sforce: give the force %s presses with under -%smotion force (N/mm, more than 0)", prefix,
             spec.tool.c_str(), prefix);
  PetscCheck(std::isfinite(f) && f > 0, PetscOptionsObject->comm, PETSC_ERR_USER_INPUT,
             "-%sforce %g: the force %s presses with must be a positive number of N/mm (-%smotion stroke: by the "
             "stroke)",
             prefix, (double)f, spec.tool.c_str(), prefix);
  spec.force = f;
  PetscFunctionReturn(PETSC_SUCCESS);
}

// In a press (MotionKind::press_check): a scene's tools, a lower die that stays in the half and full models (force
// control drives one die), not withdrawn, in place of the pass's stroke; the first pass's not with
// -stroke_corner_radius (the force's own number is its reader's). Later passes may follow it: each starts from
// where the springback before it left the tube, whatever ended the pass before.
std::string CheckForceInPress(const MotionSpec &spec, const MotionPress &press)
{
  const std::string name = Formatted("%sforce %g", press.prefix.c_str(), spec.force);
  const std::string stroke = press.Option("stroke");
  if (!press.tools)
    return name + ": the " + press.scene + " scene presses with no dies (the squaring and flattening scenes' option)";
  if (!press.quarter && !press.lower_stays)
    return name + ": with the half or full model the lower die must stay (" + press.Option("lower_die_motion") +
           " fixed); a lower die moving by the upper one's unknown stroke is not available";
  if (!press.withdrawn_by.empty())
    return name + ": " + press.withdrawn_by +
           " withdraw moves the die back by its stroke; let the pass go by reverse (or none, the last pass)";
  if (press.stroke_given)
    return name + ": in place of " + stroke +
           " (the pass ends at that punch load, its stroke the outcome); give one "
           "of them";
  if (press.corner_radius) return name + ": the stroke is its outcome; -stroke_corner_radius sets a stroke";
  return "";
}
} // namespace

std::unique_ptr<Motion> ForceMotion(const Vec2 &direction) { return std::make_unique<Force>(direction); }

const MotionKind &ForceKind()
{
  static const MotionKind kind{kForceMotion,
                               {"force"},
                               ReadForce,
                               [](const MotionSpec &s, MotionHandle &m) {
                                 return Moves(s.direction) ? (m = ForceMotion(s.direction), std::string())
                                                           : "a force along no direction";
                               },
                               nullptr,
                               nullptr,
                               "force",
                               "force",
                               /*path=*/nullptr,
                               /*unknown_stroke=*/true,
                               CheckForceInPress};
  return kind;
}

} // namespace tf
