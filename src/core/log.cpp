#include "tubeform/core/log.hpp"

#include "tubeform/core/core.hpp"

namespace tf {

PetscLogEvent Log::mesh = 0, Log::assemble = 0, Log::apply_bc = 0, Log::solve = 0, Log::scan = 0, Log::contact = 0,
              Log::commit = 0, Log::trial = 0, Log::measure = 0, Log::output = 0, Log::yield = 0, Log::friction = 0;
PetscLogStage Log::setup_stage = 0, Log::load_stage = 0, Log::output_stage = 0, Log::unlogged_stage = 0;

PetscErrorCode Log::Register()
{
  static bool done = false;
  PetscClassId id;

  PetscFunctionBeginUser;
  if (done) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PetscClassIdRegister("tubeform", &id));
  PetscCall(PetscLogEventRegister("TfMesh", id, &mesh));
  PetscCall(PetscLogEventRegister("TfAssemble", id, &assemble));
  PetscCall(PetscLogEventRegister("TfApplyBC", id, &apply_bc));
  PetscCall(PetscLogEventRegister("TfSolve", id, &solve));
  PetscCall(PetscLogEventRegister("TfScan", id, &scan));
  PetscCall(PetscLogEventRegister("TfContact", id, &contact));
  PetscCall(PetscLogEventRegister("TfCommit", id, &commit));
  PetscCall(PetscLogEventRegister("TfTrial", id, &trial));
  PetscCall(PetscLogEventRegister("TfMeasure", id, &measure));
  PetscCall(PetscLogEventRegister("TfOutput", id, &output));
  PetscCall(PetscLogEventRegister("TfYield", id, &yield));
  PetscCall(PetscLogEventRegister("TfFriction", id, &friction));
  PetscCall(PetscLogStageRegister("TfSetup", &setup_stage));
  PetscCall(PetscLogStageRegister("TfLoading", &load_stage));
  PetscCall(PetscLogStageRegister("TfOutput", &output_stage));
  PetscCall(PetscLogStageRegister("TfUnlogged", &unlogged_stage));
  PetscCall(PetscLogStageSetActive(unlogged_stage, PETSC_FALSE));
  PetscCall(PetscLogStageSetVisible(unlogged_stage, PETSC_FALSE));
  done = true;
  PetscFunctionReturn(PETSC_SUCCESS);
}

} // namespace tf
