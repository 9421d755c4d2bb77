// Each pass's press as its upper die's motion kind reads it, and the kind's refusal (scenes/motion_checks.hpp); the
// dies' options of another motion word's kind, refused in a press. A new motion that refuses some presses says so in
// its own file (src/tool/motion_*.cpp); nothing here names a kind.
#include "tubeform/scenes/motion_checks.hpp"

namespace tf {

MotionPress PressOfPass(const Options &opt, int pass)
{
  MotionPress press;
  press.prefix = pass == 0 ? "-die_" : PassOptionName(pass, "die_");
  press.scene = opt.scene;
  press.dies = PressesWithDie(opt), press.tools = PressesWithTools(opt);
  press.pass = pass;
  const ModelChoice model = ModelOf(opt); // (once: the model and the pass's hold)
  press.quarter = model.part == TubeModel::Quarter, press.lower_stays = LowerDieMoves(opt, pass, LowerDieMove::Fixed);
  if (ReleaseOfPass(opt, pass) == Unload::Withdraw) press.withdrawn_by = ReleaseOption(opt, pass);
  press.stroke_given = pass > 0 && LaterPass(opt, pass).stroke != 0;
  press.stroke_path = !StrokePathOf(opt, 0).empty(), press.corner_radius = FirstPass(opt).corner_radius > 0;
  press.side_dies = !DiesOfPass(opt, pass).side.Is(DieFrom::None);
  press.die_offset = ToolsOf(opt).passes[pass].dies.offset != 0;
  press.off_axis = PassOffAxis(opt, pass), press.held = model.HeldByRotation(pass);
  return press;
}

PetscErrorCode CheckUpperMotion(MPI_Comm comm, const Options &opt, int pass)
{
  const DieMotion &motion = ToolsOf(opt).passes[pass].dies.motion;
  const std::string why = CheckMotionInPress(motion.kind, motion.spec, PressOfPass(opt, pass));
  PetscFunctionBeginUser;
  PetscCheck(why.empty(), comm, PETSC_ERR_USER_INPUT, "%s", why.c_str());
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode CheckMotionStrays(MPI_Comm comm, const Options &opt)
{
  const std::vector<PassSpec> &passes = ToolsOf(opt).passes;
  std::vector<const std::string *> strays; // (in the order the blocks are read: ReadToolSceneOptions)
  PetscFunctionBeginUser;
  if (!PressesWithTools(opt)) PetscFunctionReturn(PETSC_SUCCESS); // (their names refused, or let go: -allow_unused)
  for (const PassSpec &p : passes)
    if (p.lower_motion) strays.push_back(&p.lower_motion->stray);
  strays.push_back(&passes.front().dies.motion.stray);
  for (const PassSpec &p : passes) strays.push_back(&p.dies.side_motion.stray);
  for (size_t pass = 1; pass < passes.size(); ++pass) strays.push_back(&passes[pass].dies.motion.stray);
  for (const std::string *stray : strays) PetscCheck(stray->empty(), comm, PETSC_ERR_USER_INPUT, "%s", stray->c_str());
  PetscFunctionReturn(PETSC_SUCCESS);
}

} // namespace tf
