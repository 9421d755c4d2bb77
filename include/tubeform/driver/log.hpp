// PETSc log events and stages: -log_view is tubeform's profiler.
#pragma once

#include <petscsys.h>

namespace tf {

struct Log {
  static PetscLogEvent assemble, apply_bc, solve, update, output, mesh;
  static PetscLogStage setup_stage, load_stage, output_stage;
  // Registers the events once; later calls do nothing.
  static PetscErrorCode Register();
};

} // namespace tf
