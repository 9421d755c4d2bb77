// The press's dies' motions from the options, made by the motion registry (tool/motion.hpp): the lower die's of
// -lower_die_motion (its kind and options read by the kind, scenes/options/die_motion_options.cpp), with the upper
// die's stroke that goes with it; the upper die's own motion (its path or its force: the first pass's -die_motion,
// UpperDie, and a later pass's alike, DiesOfPass); the side dies' (-side_motion, -pass<N>_side_motion).
#include "tubeform/scenes/die.hpp"

#include <iterator>

namespace tf {

namespace {
// How a lower die's motion goes with the upper die's (LowerDieMove; its kind and options: LowerDie, read by the kind,
// scenes/options/die_motion_options.cpp): the upper die's motion that goes with it (U: half the dies' closing either
// way), and whether the dies close as the closed forms of their reach say (CheckDieReach). A motion of its own: the
// upper die travels U, the lower one moves as its motion says.
struct LowerMotion {
  Vec2 upper;
  bool closing;
};
const LowerMotion kLowerMotions[] = {
  {{0.0, -1.0}, true},  // mirror: up by U, the mirror of the upper die's
  {{0.0, -2.0}, true},  // fixed: it stays; the upper die travels 2 U
  {{0.0, -1.0}, false}, // its own
};
static_assert(std::size(kLowerMotions) == static_cast<size_t>(LowerDieMove::Own) + 1, "one for each LowerDieMove");

const LowerMotion &LowerMotionOf(const Options &o, int pass)
{
  return kLowerMotions[static_cast<size_t>(LowerDieAsGiven(o, pass).move)];
}
} // namespace

PetscErrorCode SetMotion(MPI_Comm comm, const char *option, const std::string &kind, const MotionSpec &spec, Tool &t)
{
  PetscFunctionBeginUser;
  const std::string why = MakeMotion(kind, spec, t.motion);
  PetscCheck(why.empty(), comm, PETSC_ERR_USER_INPUT, "%s: the %s cannot move by %s", option, t.name.c_str(),
             why.c_str());
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode SetLowerMotion(MPI_Comm comm, const Options &o, int pass, Tool &upper, Tool &lower)
{
  const std::string option = PassOptionName(pass, "lower_die_motion");
  PetscFunctionBeginUser;
  const LowerDieSpec die = LowerDieOfPass(o, pass);
  PetscCall(SetMotion(comm, option.c_str(), die.kind, die.spec, lower));
  MotionSpec spec;
  spec.direction = LowerMotionOf(o, pass).upper;
  PetscCall(SetMotion(comm, option.c_str(), kStrokeMotion, spec, upper));
  PetscFunctionReturn(PETSC_SUCCESS);
}

MotionHandle LowerDieMotion(const Options &o, int pass)
{
  MotionHandle lower;
  const LowerDieSpec die = LowerDieOfPass(o, pass);
  if (!MakeMotion(die.kind, die.spec, lower).empty()) lower = StrokeMotion({0.0, 1.0});
  return lower;
}

double UpperTravel(const Options &o, int pass) { return -LowerMotionOf(o, pass).upper[1]; }

bool LowerDieClosing(const Options &o, int pass) { return LowerMotionOf(o, pass).closing; }

std::vector<double> UpperKinks(const DieMotion &die, double until)
{
  MotionHandle upper;
  if (!MakeMotion(die.kind, die.spec, upper).empty()) return {}; // (any kind's: a path's points, none of a stroke's)
  return upper->Kinks(until);
}

std::vector<double> ToolKinks(const Options &opt, int pass, double until)
{
  std::vector<double> kinks;
  MotionHandle lower, side;
  const LowerDieSpec die = LowerDieOfPass(opt, pass);
  if (!QuarterModel(opt) && MakeMotion(die.kind, die.spec, lower).empty()) kinks = lower->Kinks(until);
  const DieSet dies = DiesOfPass(opt, pass);
  MotionSpec in = dies.side_motion.spec;
  in.direction = {-1.0, 0.0}; // (any: its kinks are strokes)
  if (!dies.side.Is(DieFrom::None) && MakeMotion(dies.side_motion.kind, in, side).empty())
    for (double s : side->Kinks(until)) kinks.push_back(s);
  return kinks;
}

std::vector<double> PressKinks(const Options &opt, double until)
{
  std::vector<double> kinks = UpperKinks(UpperDie(opt), until);
  for (double s : ToolKinks(opt, 0, until)) kinks.push_back(s);
  return kinks;
}

PetscErrorCode SetUpperMotion(MPI_Comm comm, const char *option, const DieMotion &die, Tool &upper)
{
  PetscFunctionBeginUser;
  if (die.kind != kStrokeMotion) { // (the stroke: the lower die's word's, SetLowerMotion)
    MotionSpec spec = die.spec;
    spec.direction = upper.Direction(); // (force: along the stroke's)
    PetscCall(SetMotion(comm, option, die.kind, spec, upper));
  }
  if (!die.spec.turns.empty()) upper.origin = PivotOf(die.spec); // (-die_pivot, -pass<N>_die_pivot)
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode SetSideMotions(MPI_Comm comm, const Options &opt, int pass, size_t first_side, std::vector<Tool> &tools)
{
  const std::string option = PassOptionName(pass, "side_motion");
  const DieMotion side = DiesOfPass(opt, pass).side_motion;
  PetscFunctionBeginUser;
  for (size_t k = first_side; !DieMoves(side, kStrokeMotion) && k < tools.size(); ++k) {
    MotionSpec spec = side.spec;
    spec.direction = tools[k].Direction(); // (towards the tube's centre, turned with the pass)
    PetscCall(SetMotion(comm, option.c_str(), side.kind, spec, tools[k]));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

} // namespace tf
