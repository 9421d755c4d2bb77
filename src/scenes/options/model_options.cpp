// The model's options: read into ToolSceneParams::model, the first pass's die off the axis into its dies (in the block
// "tube model and passes" of -help) and checked, one line naming the option: the part of the tube modelled, a die
// off the axis (which only the full model takes), and how the full model is held (the model they and the passes' tools
// choose: ModelOf, scenes/options/model_choice.cpp).
#include <cmath>
#include <cstdio>
#include <string>

#include "tubeform/scenes/tool_options.hpp"

namespace tf {

PetscErrorCode ReadModelOptions(PetscOptionItems *PetscOptionsObject, OptionReader &read, ToolSceneParams &tools)
{
  ModelParams &m = tools.model;
  PetscFunctionBeginUser;
  PetscCall(ChooseWord(PetscOptionsObject, read, "-model",
                       "tool scenes: the part of the tube modelled: quarter, half (x >= 0), full (held as "
                       "-full_hold says), auto (the quarter where exact, else the half or the full)",
                       kModelWords, m.part));
  PetscCall(read.Real(PetscOptionsObject, "-die_offset",
                      "squaring: the first pass's upper die moved off the y axis by this along x (mm; the full model, "
                      "held by the rotation hold, a second pass after it too; docs/dies.md)",
                      tools.passes[0].dies.offset));
  PetscCall(
    ChooseWord(PetscOptionsObject, read, "-full_hold",
               "the full model's support: pins (the x of its outer nodes on the y axis), rotation (a couple "
               "on its inner nodes there holds its rotation alone, the dies its slide; docs/dies.md), auto "
               "(rotation where the pins would hold the tube's slide against the dies: with -die_offset or a sideways "
               "-die_path and a second pass after it, in a pass with -pass<N>_die_offset and after it, and in a "
               "quarter-turned second pass after a first pass not mirrored top to bottom, and in one turned by "
               "another angle; else pins)",
               kFullHoldWords, m.full_hold));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode CheckDieOffset(MPI_Comm comm, const Options &opt, const std::string &name, double offset)
{
  PetscFunctionBeginUser;
  PetscCheck(std::isfinite(offset), comm, PETSC_ERR_USER_INPUT, "%s %g: give a number of mm", name.c_str(), offset);
  PetscCheck(offset == 0 || PressesWithDie(opt), comm, PETSC_ERR_USER_INPUT,
             "%s %g: the squaring scene's die (a plate off the axis is the same plate)", name.c_str(), offset);
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode CheckModelOptions(MPI_Comm comm, const Options &opt)
{
  const ModelParams &m = ToolsOf(opt).model;
  const double offset = FirstDies(opt).offset; // (-die_offset)
  const ModelChoice model = ModelOf(opt);
  PetscFunctionBeginUser;
  PetscCheck(m.part != TubeModel::Quarter || model.Mirrored(), comm, PETSC_ERR_USER_INPUT,
             "-model quarter: the quarter model needs the lower die to mirror the upper one in shape and motion "
             "in every pass (-lower_die mirror -lower_die_motion mirror, and each pass's); use -model half or auto");
  // The rotation hold: the full model; one extra unknown in a solve (scenes/hold.hpp).
  PetscCall(CheckDieOffset(comm, opt, "-die_offset", offset));
  char off_axis[64] = "-die_path"; // (what puts the die off the axis, named in the errors)
  if (offset != 0) std::snprintf(off_axis, sizeof off_axis, "-die_offset %g", offset);
  if (offset == 0 && !DiePathSideways(opt)) std::snprintf(off_axis, sizeof off_axis, "-die_path_turn");
  PetscCheck(!DieOffAxis(opt) || model.part == TubeModel::Full, comm, PETSC_ERR_USER_INPUT,
             "%s: a die off the axis breaks the tube's mirror symmetry; use -model full (or auto)", off_axis);
  PetscCheck(m.full_hold != FullHold::Rotation || PressesWithDie(opt), comm, PETSC_ERR_USER_INPUT,
             "-full_hold rotation: the %s scene's plates do not hold the tube's slide; use pins", opt.scene.c_str());
  PetscCheck(!DieOffAxis(opt) || m.full_hold != FullHold::Pins, comm, PETSC_ERR_USER_INPUT,
             "%s with -full_hold pins: the pins would hold the tube's slide against the die; use -full_hold rotation "
             "(or auto)",
             off_axis);
  PetscCheck(m.full_hold == FullHold::Auto || model.part == TubeModel::Full, comm, PETSC_ERR_USER_INPUT,
             "-full_hold %s: only the full model is held so (-model full)", WordOf(kFullHoldWords, m.full_hold));
  for (int pass = 0; pass < kMaxPasses; ++pass) { // (a pass's press: one force-controlled unknown in an increment)
    const PassExtent e = Extent(opt, pass);
    const double side = ToolsOf(opt).passes[pass].dies.SideForce();
    PetscCheck(!model.HeldByRotation(pass) || (!e.Forced() && side == 0), comm, PETSC_ERR_USER_INPUT,
               "%s %g: the %s pass is held by the rotation hold (-full_hold; a die off the axis in it or before it: "
               "-die_offset, -pass<N>_die_offset, -die_path; a turn off the quarters), an unknown of each increment "
               "as a force-controlled die's travel is; one of them in a pass",
               e.Forced() ? e.Option().c_str() : PassOptionName(pass, "side_force").c_str(),
               e.Forced() ? e.Target() : side, PassOrdinal(pass).c_str());
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

} // namespace tf
