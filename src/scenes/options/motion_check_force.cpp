// The force motion's check (scenes/motion_checks.hpp): a pass pressed with a force (-die_motion force, -die_force;
// -pass<N>_die_motion force, -pass<N>_die_force; PassExtent::Forced; the force itself checked by the force kind's
// reader, tool/motion_force.cpp) goes with the other options: a press scene's die, a lower die that stays in the half
// and full models, the last pass, not withdrawn, in place of the pass's stroke; the first pass's not with
// -stroke_corner_radius.
#include "tubeform/scenes/motion_checks.hpp"

namespace tf {

namespace {
PetscErrorCode CheckForce(MPI_Comm comm, const Options &opt, int pass)
{
  const PassExtent e = Extent(opt, pass);
  const std::string name = e.Option();
  PetscFunctionBeginUser;
  PetscCheck(PressesWithTools(opt), comm, PETSC_ERR_USER_INPUT,
             "%s %g: the %s scene presses with no dies (the squaring and flattening scenes' option)", name.c_str(),
             e.force, opt.scene.c_str());
  // Force control drives one die; the stroke is its outcome.
  PetscCheck(QuarterModel(opt) || LowerDieMoves(opt, LowerDieMove::Fixed), comm, PETSC_ERR_USER_INPUT,
             "%s %g: with the half or full model the lower die must stay (-lower_die_motion fixed); a "
             "lower die moving by the upper one's unknown stroke is not available",
             name.c_str(), e.force);
  PetscCheck(PassCount(opt) == pass + 1, comm, PETSC_ERR_USER_INPUT, "%s %g: not with a %s pass (%s); %s", name.c_str(),
             e.force, PassOrdinal(pass + 1).c_str(), PassOption(pass + 1, "stroke").c_str(),
             pass == 0 ? "press one pass by force" : "a pass by force is the last");
  PetscCheck(opt.release.unload != Unload::Withdraw, comm, PETSC_ERR_USER_INPUT,
             "%s %g: -unload withdraw moves the die back by its stroke; use -unload reverse or none", name.c_str(),
             e.force);
  PetscCheck(pass == 0 || LaterPass(opt, pass).stroke == 0, comm, PETSC_ERR_USER_INPUT,
             "%s %g: in place of %s (the pass ends at that punch load, its stroke the outcome); give one of them",
             name.c_str(), e.force, PassOption(pass, "stroke").c_str());
  PetscCheck(pass > 0 || opt.stroke.corner_radius <= 0, comm, PETSC_ERR_USER_INPUT,
             "%s %g: the stroke is its outcome; -stroke_corner_radius sets a stroke", name.c_str(), e.force);
  PetscFunctionReturn(PETSC_SUCCESS);
}
} // namespace

const MotionCheckKind &ForceCheck()
{
  static const MotionCheckKind kind{"force", CheckForce};
  return kind;
}

} // namespace tf
