// The tool scenes' options as one (include/tubeform/scenes/tool_options.hpp): read in their blocks of -help (the
// model and the later passes, then each die's shape and motion under its own prefix) and checked in turn: a die's
// option of another motion word's kind, which dies, forces and side dies go together, a -die_path's stroke, the lower
// die's own motion, the passes' turns, the model and the release, the V-die's numbers. Read and checked for every
// scene, so that a tool scene's option given to a scene without tools is refused by name.
#include "tubeform/io/loading_options.hpp"
#include "tubeform/scenes/motion_checks.hpp"
#include "tubeform/scenes/tool_options.hpp"

namespace tf {

namespace {

// The dies: which dies, forces and side dies go together.
PetscErrorCode CheckDies(MPI_Comm comm, Options &opt)
{
  PetscFunctionBeginUser;
  const bool press = PressesWithTools(opt);
  const DieSet &first = FirstDies(opt);
  bool asked = !first.lower.Is(DieFrom::Mirror) || !LowerDieMoves(opt, 0, LowerDieMove::Mirror) ||
               ToolsOf(opt).model.part != TubeModel::Auto || !DieMoves(first, kStrokeMotion) ||
               !first.side.Is(DieFrom::None) || !DieMoves(first.side_motion, kStrokeMotion) || first.offset != 0 ||
               ToolsOf(opt).model.full_hold != FullHold::Auto;
  for (int pass = 1; pass < kMaxPasses; ++pass) {
    const PassSpec &p = LaterPass(opt, pass);
    asked = asked || p.stroke != 0 || p.turn != 0 || !p.dies.upper.kind.empty() || p.dies.lower.Given() ||
            p.dies.side.Given() || p.dies.offset != 0 || !DieMoves(p.dies.side_motion, kStrokeMotion) || p.release ||
            p.lower_motion;
  }
  PetscCheck(
    press || !asked, comm, PETSC_ERR_USER_INPUT,
    "-lower_die, -lower_die_motion, -model, -pass<N>_*, -die_motion, -die_force, -die_offset, -die_path, -side_die, "
    "-side_force, -full_hold: "
    "the %s scene presses with no dies (these are the squaring and flattening scenes' options)",
    opt.scene.c_str());
  PetscCall(CheckUpperMotion(comm, opt, 0));     // (its kind's press check; a later pass's with its stroke)
  PetscCall(CheckPassStrokesAndDies(comm, opt)); // (passes_check.cpp)
  PetscCall(CheckSideDieOptions(comm, opt));     // (die_shape_options.cpp)
  PetscFunctionReturn(PETSC_SUCCESS);
}

// -die_motion path (checked by the path kind in its press, tool/motion_path.cpp): the stroke U where the path ends.
void SetDiePathStroke(Options &opt) { opt.stroke.u = -0.5 * DiePath(opt).Last()[1]; }

// A lower die on a motion of its own (neither mirror nor fixed: a path, or another kind; its options are its
// kind's own reader's, tool/motion.hpp): the first pass's follows it as the stroke rises; a later pass's moves as its
// own -pass<N>_lower_die_motion says, its strokes from where the pass's dies start (the first pass's motion is not
// taken for it: its strokes would be another pass's).
PetscErrorCode CheckLowerDieMotion(MPI_Comm comm, const Options &opt)
{
  const char *word = FirstPass(opt).lower_motion->word.c_str();
  PetscFunctionBeginUser;
  if (LowerDieMoves(opt, 0, LowerDieMove::Own)) // (nor a path of strokes: CheckPassStrokePath, every pass's)
    PetscCheck(ReleaseOfPass(opt, 0) != Unload::Withdraw && FirstPass(opt).corner_radius <= 0, comm,
               PETSC_ERR_USER_INPUT,
               "-lower_die_motion %s: the lower die follows its motion as the stroke rises: not with -unload withdraw "
               "or -stroke_corner_radius",
               word);
  // (a later pass's withdrawn: CheckRelease refuses it, its model not the quarter)
  for (int pass = 1; pass < PassCount(opt); ++pass)
    PetscCheck(LaterPass(opt, pass).lower_motion || !LowerDieMoves(opt, 0, LowerDieMove::Own), comm,
               PETSC_ERR_USER_INPUT,
               "-lower_die_motion %s: the first pass's lower die on a motion of its own; give the %s pass's, %s "
               "(mirror, fixed or a motion of its own, its strokes from where that pass's dies start)",
               word, PassOrdinal(pass).c_str(), PassOptionName(pass, "lower_die_motion").c_str());
  PetscFunctionReturn(PETSC_SUCCESS);
}

// The release the model cannot take: the dies withdrawn from the half model would let the tube come free of both.
PetscErrorCode CheckRelease(MPI_Comm comm, const Options &opt)
{
  PetscFunctionBeginUser;
  for (int k = 0; k < PassCount(opt); ++k)
    PetscCheck(QuarterModel(opt) || ReleaseOfPass(opt, k) != Unload::Withdraw, comm, PETSC_ERR_USER_INPUT,
               "%s withdraw: not with the half model (the tube would come free of both dies); use %s reverse",
               ReleaseOption(opt, k).c_str(), ReleaseOption(opt, k).c_str());
  PetscFunctionReturn(PETSC_SUCCESS);
}

// The first pass's stroke rules the dies cannot take: the corner-radius rule is two equal V-dies'; a path of strokes
// is not a force's.
PetscErrorCode CheckStrokeWithDies(MPI_Comm comm, const Options &opt)
{
  const double radius = FirstPass(opt).corner_radius;
  PetscFunctionBeginUser;
  PetscCheck(radius >= 0, comm, PETSC_ERR_USER_INPUT, "-stroke_corner_radius %g: must be non-negative", radius);
  PetscCheck(VDie(opt) || radius <= 0, comm, PETSC_ERR_USER_INPUT,
             "-stroke_corner_radius %g: the corner-radius rule is the V-die's; with -die_profile give -stroke", radius);
  PetscCheck(
    FirstDies(opt).lower.Is(DieFrom::Mirror) || radius <= 0, comm, PETSC_ERR_USER_INPUT,
    "-stroke_corner_radius %g: the corner-radius rule is for two equal V-dies; with -lower_die %s give -stroke", radius,
    ShapeWord(FirstDies(opt).lower).c_str());
  PetscCall(CheckPassStrokePath(comm, opt, 0)); // (passes_check.cpp)
  PetscFunctionReturn(PETSC_SUCCESS);
}

// The later passes' turns, the model (a die off the axis, the rotation hold) and the release.
PetscErrorCode CheckPassesAndHolds(MPI_Comm comm, Options &opt)
{
  PetscFunctionBeginUser;
  PetscCall(CheckPassTurns(comm, opt));    // (passes_check.cpp)
  PetscCall(CheckModelOptions(comm, opt)); // (model_options.cpp)
  PetscCall(CheckRelease(comm, opt));
  PetscFunctionReturn(PETSC_SUCCESS);
}

} // namespace

PetscErrorCode ReadToolSceneOptions(MPI_Comm comm, OptionReader &read, Options &opt)
{
  PetscFunctionBeginUser;
  {
    TF_OPTIONS_BEGIN(comm, "tubeform: tube model and passes");
    PetscCall(ReadModelOptions(PetscOptionsObject, read, ToolsOf(opt))); // (model_options.cpp)
    PetscCall(ReadToolOptions(PetscOptionsObject, read, opt));           // (pass_options.cpp)
    TF_OPTIONS_END();
  }
  PetscCall(ReadLowerDieShape(comm, read, opt));  // (die_shape_options.cpp)
  PetscCall(ReadLowerDieMotion(comm, read, opt)); // (die_motion_options.cpp)
  PetscCall(ReadPassLowerMotions(comm, read, opt));
  PetscCall(ReadUpperDieShape(comm, read, opt)); // (die_shape_options.cpp)
  PetscCall(ReadUpperDieMotion(comm, read, opt));
  PetscCall(ReadPassShapes(comm, read, opt)); // (die_shape_options.cpp; after the first pass's, their defaults)
  PetscCall(ReadSideDieShape(comm, read, opt));
  PetscCall(ReadSideMotions(comm, read, opt));   // (die_motion_options.cpp)
  PetscCall(ReadPassOwnShapes(comm, read, opt)); // (die_shape_options.cpp; after the first pass's, their defaults)
  PetscCall(ReadPassMotions(comm, read, opt));   // (die_motion_options.cpp)
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode CheckToolSceneOptions(MPI_Comm comm, Options &opt)
{
  PetscFunctionBeginUser;
  PetscCall(CheckMotionStrays(comm, opt)); // (first, as when read: an option of another motion word's kind)
  PetscCall(CheckDies(comm, opt));
  if (FirstDies(opt).motion.OwnPath()) SetDiePathStroke(opt);
  PetscCall(CheckLowerDieMotion(comm, opt));
  PetscCall(CheckPassesAndHolds(comm, opt));
  PetscCall(CheckStrokeWithDies(comm, opt));
  if (!StrokePathOf(opt, 0).empty()) opt.stroke.u = StrokePathOf(opt, 0).back(); // (its last stroke: the press's)
  PetscCall(CheckShape(comm, kVShape, "die_", UpperDieShape(opt).spec)); // (the V-die's options: read with a file too)
  PetscCall(CheckDieShapes(comm, opt));         // (the lower and side dies' of their own: die_shape_options.cpp)
  for (int pass = 1; pass < kMaxPasses; ++pass) // (a later pass's own V numbers)
    if (LaterPass(opt, pass).dies.upper.kind == kVShape)
      PetscCall(
        CheckShape(comm, kVShape, Formatted("pass%d_die_", pass + 1).c_str(), DiesOfPass(opt, pass).upper.spec));
  PetscFunctionReturn(PETSC_SUCCESS);
}

} // namespace tf
