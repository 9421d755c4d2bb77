// The options of the scenes without tools (include/tubeform/io/scene_options.hpp); checked in options_check.cpp.
#include "tubeform/io/scene_options.hpp"

namespace tf {

namespace {
// Reversals -tension_cycle and -bending_cycle take at most.
constexpr PetscInt kMaxTensionCycle = 16;
} // namespace

PetscErrorCode ReadSceneSizes(PetscOptionItems *PetscOptionsObject, OptionReader &read, Options &opt)
{
  PetscFunctionBeginUser;
  PetscCall(read.Real(PetscOptionsObject, "-shear_gamma", "shear scene: final shear strain gamma", opt.shear_gamma));
  PetscCall(
    read.Real(PetscOptionsObject, "-slide_n", "slide scene: normal force pressing the block (N/mm)", opt.slide_n));
  PetscCall(ChooseWord(PetscOptionsObject, read, "-slide_tool",
                       "slide scene: a block on a flat floor, or a quarter ring turned inside a cylinder (arc)",
                       {"flat", "arc"}, opt.slide_tool));
  PetscCall(read.Real(PetscOptionsObject, "-slide_push", "slide scene: sideways displacement of the block's top (mm)",
                      opt.slide_push));
  PetscCall(read.Real(PetscOptionsObject, "-slide_back",
                      "slide scene (flat): then push the top back by this much (mm; 0: no third stage), "
                      "reversing the slip",
                      opt.slide_back));
  PetscCall(read.Real(PetscOptionsObject, "-tension_strain",
                      "tension scene: final nominal strain in x (negative: compression)", opt.tension_strain));
  PetscCall(RealList(PetscOptionsObject, read, "-tension_cycle",
                     "tension scene: nominal strains the block is then taken to in turn, each over "
                     "-unload_increments trial increments (a tension-compression cycle: -tension_strain 0.02 "
                     "-tension_cycle -0.02,0.02)",
                     kMaxTensionCycle, opt.tension_cycle));
  PetscCall(read.Real(PetscOptionsObject, "-bending_strain",
                      "bending scene: the outer fibre's nominal strain at the end of the first stage (y > 0; "
                      "negative: bent the other way)",
                      opt.bending_strain));
  PetscCall(RealList(PetscOptionsObject, read, "-bending_cycle",
                     "bending scene: outer-fibre strains the strip is then taken to in turn, each over "
                     "-unload_increments trial increments (bend and unbend: -bending_strain 0.01 -bending_cycle 0)",
                     kMaxTensionCycle, opt.bending_cycle));
  PetscCall(read.Real(PetscOptionsObject, "-rotation_angle",
                      "rotation scene: rigid rotation after the prestretch (degrees)", opt.rotation_angle));
  PetscCall(read.Real(PetscOptionsObject, "-rotation_strain",
                      "rotation scene: uniaxial prestretch strain in x before the rotation", opt.rotation_strain));
  PetscCall(read.Real(PetscOptionsObject, "-column_l", "column scene: length between the pins (mm)", opt.column_l));
  PetscCall(read.Real(PetscOptionsObject, "-column_t", "column scene: thickness (mm)", opt.column_t));
  PetscCall(read.Real(PetscOptionsObject, "-column_imperfection",
                      "column scene: amplitude of the initial sine-shaped bow (mm)", opt.column_imperfection));
  PetscFunctionReturn(PETSC_SUCCESS);
}

} // namespace tf
