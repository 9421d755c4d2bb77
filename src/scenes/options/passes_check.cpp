// The validation of the passes after the first (-pass2_* to -pass9_*): one message per problem, naming the option
// and what it allows. Each pass is checked as the second is: a pass needs the one before it.
#include <cmath>

#include "tubeform/core/core.hpp"
#include "tubeform/scenes/motion_checks.hpp"
#include "tubeform/scenes/tool_options.hpp"
#include "tubeform/scenes/tool_scene.hpp"

namespace tf {

// Pass `pass`'s side dies (`name`: -side_die, -pass<N>_side_die): none, or with what side dies go with (not an upper
// die pressed by a force, not withdrawn dies; where the tube's sides differ: CheckSideDieOptions).
PetscErrorCode CheckSideDies(MPI_Comm comm, const Options &opt, int pass, const std::string &name,
                             const DieChoice &side)
{
  const std::string value = ShapeWord(side);
  PetscFunctionBeginUser;
  if (side.Is(DieFrom::None)) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCheck(!value.empty(), comm, PETSC_ERR_USER_INPUT, "%s: give none, mirror, flat, v or a profile file",
             name.c_str());
  PetscCheck(!Extent(opt, pass).Forced(), comm, PETSC_ERR_USER_INPUT,
             "%s %s: side dies are not with %s in their pass (they press by its stroke, which a force leaves an "
             "unknown)",
             name.c_str(), value.c_str(), PassOptionName(pass, "die_force").c_str());
  PetscCheck(ReleaseOfPass(opt, pass) != Unload::Withdraw, comm, PETSC_ERR_USER_INPUT,
             "%s %s: side dies are not withdrawn (%s withdraw); let them go by reverse", name.c_str(), value.c_str(),
             ReleaseOption(opt, pass).c_str());
  PetscFunctionReturn(PETSC_SUCCESS);
}

namespace {

// Pass `pass`'s upper die moved off its press's axis (-pass<N>_die_offset): as the first pass's, in the full model
// held by the rotation hold (the pins would hold the tube's slide against the die).
PetscErrorCode CheckPassOffset(MPI_Comm comm, const Options &opt, int pass)
{
  const std::string name = PassOptionName(pass, "die_offset");
  const double offset = LaterPass(opt, pass).dies.offset;
  const ModelChoice model = ModelOf(opt);
  PetscFunctionBeginUser;
  PetscCall(CheckDieOffset(comm, opt, name, offset));
  PetscCheck(offset == 0 || model.part == TubeModel::Full, comm, PETSC_ERR_USER_INPUT,
             "%s %g: a die off the axis breaks the tube's mirror symmetry; use -model full (or auto)", name.c_str(),
             offset);
  PetscCheck(offset == 0 || model.HeldByRotation(pass), comm, PETSC_ERR_USER_INPUT,
             "%s %g with -full_hold pins: the pins would hold the tube's slide against the die; use -full_hold "
             "rotation (or auto)",
             name.c_str(), offset);
  PetscFunctionReturn(PETSC_SUCCESS);
}

} // namespace

PetscErrorCode CheckPassStrokePath(MPI_Comm comm, const Options &opt, int pass)
{
  const PassSpec &p = ToolsOf(opt).passes[pass];
  const std::string name = PassOptionName(pass, "stroke_path");
  double at = 0;
  PetscFunctionBeginUser;
  if (p.stroke_path.empty()) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCheck(PressesWithTools(opt), comm, PETSC_ERR_USER_INPUT, "%s: the %s scene presses with no dies", name.c_str(),
             opt.scene.c_str());
  for (double u : p.stroke_path) {
    PetscCheck(std::isfinite(u) && u >= 0 && u != at, comm, PETSC_ERR_USER_INPUT,
               "%s: %g after %g: each stroke must be a non-negative number of mm, other than the one before it (from "
               "0)",
               name.c_str(), u, at);
    at = u;
  }
  PetscCheck(at > 0, comm, PETSC_ERR_USER_INPUT, "%s: the last stroke is the pass's final one and must be positive",
             name.c_str());
  PetscCheck(p.corner_radius <= 0, comm, PETSC_ERR_USER_INPUT, "%s: not with -stroke_corner_radius", name.c_str());
  // (a force named by its option, which its old spelling gives alone; another motion by its word)
  const std::string motion = MotionStrokeUnknown(p.dies.motion.kind) ? PassOptionName(pass, "die_force")
                                                                     : PassOptionName(pass, "die_motion") + " " +
                                                                         FindMotionKind(p.dies.motion.kind)->upper_word;
  PetscCheck(DieMoves(p.dies, kStrokeMotion), comm, PETSC_ERR_USER_INPUT,
             "%s: the upper die by the pass's stroke: not with %s", name.c_str(), motion.c_str());
  PetscCheck(!LowerDieMoves(opt, pass, LowerDieMove::Own), comm, PETSC_ERR_USER_INPUT,
             "%s %s: the lower die follows its motion as the stroke rises: not with %s",
             PassOptionName(pass, "lower_die_motion").c_str(), LowerDieAsGiven(opt, pass).word.c_str(), name.c_str());
  PetscFunctionReturn(PETSC_SUCCESS);
}

namespace {
// Pass `pass`'s stroke and dies (a pass given: PassExtent).
PetscErrorCode CheckPassStroke(MPI_Comm comm, const Options &opt, int pass)
{
  const PassSpec &p = LaterPass(opt, pass);
  const PassExtent e = Extent(opt, pass);
  const std::string stroke = PassOptionName(pass, "stroke"), ordinal = PassOrdinal(pass), given = e.Option();
  PetscFunctionBeginUser;
  PetscCheck(PressesWithDie(opt) || p.dies.upper.kind.empty(), comm, PETSC_ERR_USER_INPUT,
             "%s, %s: the %s scene presses with plates, not dies", PassOptionName(pass, "die_profile").c_str(),
             PassOptionName(pass, "die_angle").c_str(), opt.scene.c_str());
  PetscCheck(p.stroke >= 0 && std::isfinite(p.stroke), comm, PETSC_ERR_USER_INPUT,
             "%s %g: must be non-negative (0: %s)", stroke.c_str(), p.stroke,
             pass == 1 ? "one pass" : ("the " + PassOrdinal(pass - 1) + " pass the last").c_str());
  const Unload before = ReleaseOfPass(opt, pass - 1);
  PetscCheck(!e.Given() || before != Unload::None, comm, PETSC_ERR_USER_INPUT,
             "%s %g: a %s pass follows the %s pass's release; give %s reverse or withdraw (not none)", given.c_str(),
             e.Target(), ordinal.c_str(), PassOrdinal(pass - 1).c_str(), ReleaseOption(opt, pass - 1).c_str());
  PetscCheck(!e.Given() || pass == 1 || Extent(opt, pass - 1).Given(), comm, PETSC_ERR_USER_INPUT,
             "%s %g: the %s pass follows the %s; give %s", given.c_str(), e.Target(), ordinal.c_str(),
             PassOrdinal(pass - 1).c_str(), PassOptionName(pass - 1, "stroke").c_str());
  PetscCheck(
    e.Given() || (p.dies.upper.kind.empty() && !p.dies.lower.Given() && !p.dies.side.Given() && p.dies.offset == 0 &&
                  DieMoves(p.dies.side_motion, kStrokeMotion) && !p.release && !p.lower_motion),
    comm, PETSC_ERR_USER_INPUT, "%s (or its V-die's numbers), %s, %s, %s, %s, %s, %s, %s: give %s for the %s pass",
    PassOptionName(pass, "die_profile").c_str(), PassOptionName(pass, "lower_die").c_str(),
    PassOptionName(pass, "lower_die_motion").c_str(), PassOptionName(pass, "side_die").c_str(),
    PassOptionName(pass, "side_motion").c_str(), PassOptionName(pass, "die_offset").c_str(),
    PassOptionName(pass, "side_force").c_str(), PassOptionName(pass, "unload").c_str(), stroke.c_str(),
    ordinal.c_str());
  if (p.dies.side.Given() || e.Given()) // (its own side dies, or the first pass's)
    PetscCall(CheckSideDies(comm, opt, pass, PassOptionName(p.dies.side.Given() ? pass : 0, "side_die"),
                            DiesOfPass(opt, pass).side));
  PetscCall(CheckPassOffset(comm, opt, pass));
  PetscCall(CheckPassStrokePath(comm, opt, pass));
  if (e.Given()) PetscCall(CheckSideMotion(comm, opt, pass)); // (die_shape_options.cpp)
  PetscCall(CheckUpperMotion(comm, opt, pass));               // (its motion kind's check: motion_checks.hpp)
  PetscFunctionReturn(PETSC_SUCCESS);
}

// Pass `pass`'s turn (from the pass before's press; its dies drawn by the turns summed: PassTurnDegrees).
PetscErrorCode CheckPassTurn(MPI_Comm comm, const Options &opt, int pass)
{
  const PassSpec &p = LaterPass(opt, pass);
  const std::string turn = PassOptionName(pass, "turn");
  const ModelChoice model = ModelOf(opt);
  const int quarters = model.passes[pass].quarters;
  PetscFunctionBeginUser;
  PetscCheck(std::isfinite(p.turn) && std::abs(p.turn) <= 360, comm, PETSC_ERR_USER_INPUT,
             "%s %g: the tube turns by -360 to 360 degrees", turn.c_str(), p.turn);
  PetscCheck(model.passes[pass].quarter_turn || (model.part == TubeModel::Full && model.hold != FullHold::Pins), comm,
             PETSC_ERR_USER_INPUT,
             "%s %g: a turn that is no multiple of 90 degrees needs the full model held by the rotation hold "
             "(-model full or auto, -full_hold rotation or auto)",
             turn.c_str(), p.turn);
  PetscCheck(Extent(opt, pass).Given() || p.turn == 0, comm, PETSC_ERR_USER_INPUT, "%s %g: give %s for the %s pass",
             turn.c_str(), p.turn, PassOptionName(pass, "stroke").c_str(), PassOrdinal(pass).c_str());
  for (int before = 0; before < pass; ++before) {
    const bool odd = (quarters - model.passes[before].quarters) % 2 != 0;
    const std::string lower = before == 0 ? "-lower_die" : PassOptionName(before, "lower_die");
    PetscCheck(!odd || model.passes[before].mirrored || model.hold != FullHold::Pins, comm, PETSC_ERR_USER_INPUT,
               "%s %g with -full_hold pins: the %s pass's dies (%s %s, %s %s) leave the tube symmetric "
               "about the y axis only; a quarter turn presses it off that axis, which the pins would hold it against "
               "(use -full_hold rotation or auto)",
               turn.c_str(), p.turn, PassOrdinal(before).c_str(), lower.c_str(), PassLowerDie(opt, before).c_str(),
               PassOptionName(before, "lower_die_motion").c_str(), LowerDieOfPass(opt, before).word.c_str());
  }
  PetscCheck(ToolsOf(opt).model.part != TubeModel::Half || quarters % 2 == 0, comm, PETSC_ERR_USER_INPUT,
             "%s %g with -model half: the half model's plane x = 0 is no symmetry plane of a press turned by 90 "
             "degrees; use -model full (or auto)",
             turn.c_str(), p.turn);
  PetscFunctionReturn(PETSC_SUCCESS);
}

} // namespace

PetscErrorCode CheckPassStrokesAndDies(MPI_Comm comm, const Options &opt)
{
  PetscFunctionBeginUser;
  for (int pass = 1; pass < kMaxPasses; ++pass) PetscCall(CheckPassStroke(comm, opt, pass));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode CheckPassTurns(MPI_Comm comm, const Options &opt)
{
  PetscFunctionBeginUser;
  for (int pass = 1; pass < kMaxPasses; ++pass) PetscCall(CheckPassTurn(comm, opt, pass));
  PetscFunctionReturn(PETSC_SUCCESS);
}

} // namespace tf
