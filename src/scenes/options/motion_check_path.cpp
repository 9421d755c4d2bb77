// The path motion's check (scenes/motion_checks.hpp): an upper die on a path of its own (-die_motion path, -die_path;
// -pass<N>_die_motion path, -pass<N>_die_path; its points, turns and pivot checked by the path kind's reader,
// tool/motion_path.cpp; a later pass's stroke set where its path ends, scenes/options/die_motion_options.cpp): the
// squaring scene's upper die, within a quarter turn, ending below its start, over a lower die that stays. The first
// pass's in place of -stroke and -stroke_path, in one pass, with no side dies, withdrawal or -die_offset (its U where
// its path ends: options_check.cpp); a later pass's with no side dies pressing by the stroke in any pass and, off its
// press's axis (sideways or turned), held by the rotation hold in the full model (the first pass's: model_options.cpp).
#include <cmath>

#include "tubeform/scenes/motion_checks.hpp"

namespace tf {

namespace {

// An upper die's turns along its path (degrees): a die turned by more than a quarter turn no longer presses along
// its press's y, along which its punch load is read.
constexpr double kMaxDieTurn = 90;

// Any pass's: the squaring scene's die, within a quarter turn, ending below its start, over a lower die that stays
// (`name`: -die_path, -pass<N>_die_path).
PetscErrorCode CheckUpperPath(MPI_Comm comm, const Options &opt, const MotionSpec &path, const std::string &name)
{
  PetscFunctionBeginUser;
  PetscCheck(PressesWithDie(opt), comm, PETSC_ERR_USER_INPUT,
             "%s: the squaring scene's upper die through x,y pairs (mm, from its start), in turn; not the %s scene's",
             name.c_str(), opt.scene.c_str());
  for (double turn : path.turns)
    PetscCheck(std::abs(turn) <= kMaxDieTurn, comm, PETSC_ERR_USER_INPUT,
               "%s_turn %g: each turn must be a number of degrees within +-%g", name.c_str(), turn, kMaxDieTurn);
  const double y = path.points.back()[1];
  PetscCheck(y < 0, comm, PETSC_ERR_USER_INPUT,
             "%s: the last point's y %g must be below the start: the press ends pressing (U = -y / 2)", name.c_str(),
             y);
  PetscCheck(LowerDieMoves(opt, LowerDieMove::Fixed), comm, PETSC_ERR_USER_INPUT,
             "%s: the path is the upper die's, relative to a lower die that stays: give -lower_die_motion fixed",
             name.c_str());
  PetscFunctionReturn(PETSC_SUCCESS);
}

// The first pass's (-die_path): in place of -stroke and -stroke_path, in one pass by the stroke it ends at.
PetscErrorCode CheckFirstPath(MPI_Comm comm, const Options &opt)
{
  PetscFunctionBeginUser;
  PetscCall(CheckUpperPath(comm, opt, FirstDies(opt).motion.spec, "-die_path"));
  PetscCheck(opt.stroke.path.empty() && opt.stroke.corner_radius <= 0 && PassCount(opt) == 1 &&
               FirstDies(opt).side.Is(DieFrom::None) && opt.release.unload != Unload::Withdraw &&
               ToolsOf(opt).model.die_offset == 0,
             comm, PETSC_ERR_USER_INPUT,
             "-die_path: in place of -stroke and -stroke_path, in one pass: not with -stroke_path, "
             "-stroke_corner_radius, -pass2_stroke, -side_die, -unload withdraw or -die_offset (a path sideways is "
             "its own offset)");
  PetscFunctionReturn(PETSC_SUCCESS);
}

// A later pass's (-pass<N>_die_path): no side dies in any pass (they press by the stroke); off the axis, the full
// model held by the rotation hold.
PetscErrorCode CheckPassPath(MPI_Comm comm, const Options &opt, int pass)
{
  const MotionSpec &path = LaterPass(opt, pass).dies.motion.spec;
  const std::string name = PassOption(pass, "die_path");
  bool side = false;
  PetscFunctionBeginUser;
  PetscCall(CheckUpperPath(comm, opt, path, name));
  for (int k = 0; k < PassCount(opt); ++k) side = side || !DiesOfPass(opt, k).side.Is(DieFrom::None);
  PetscCheck(!side, comm, PETSC_ERR_USER_INPUT,
             "%s: not with side dies (-side_die, -pass<N>_side_die), which press by the stroke", name.c_str());
  PetscCheck(!PassOffAxis(opt, pass) || HeldByRotation(opt, pass), comm, PETSC_ERR_USER_INPUT,
             "%s: a die off the axis (a sideways point or a turn) breaks the tube's mirror symmetry; use -model full "
             "(or auto) -full_hold rotation (or auto)",
             name.c_str());
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode CheckPath(MPI_Comm comm, const Options &opt, int pass)
{
  PetscFunctionBeginUser;
  PetscCall(pass == 0 ? CheckFirstPath(comm, opt) : CheckPassPath(comm, opt, pass));
  PetscFunctionReturn(PETSC_SUCCESS);
}

} // namespace

const MotionCheckKind &PathCheck()
{
  static const MotionCheckKind kind{"path", CheckPath};
  return kind;
}

} // namespace tf
