// PETSc log events and stages: -log_view is tubeform's profiler (one event per
// hot routine, one stage per phase of a run).
#pragma once

#include <petscsys.h>

namespace tf {

struct Log {
  // yield: the plasticity part of the scans (only with a plastic law);
  // friction: friction iterates and forces (only with mu > 0).
  static PetscLogEvent mesh, assemble, apply_bc, solve, scan, contact, commit, trial, measure, output, yield, friction;
  static PetscLogStage setup_stage, load_stage, output_stage;
  // Work that is not the run's (the solver options' stand-in factorization):
  // neither logged nor shown by -log_view.
  static PetscLogStage unlogged_stage;
  // Registers the events once; later calls do nothing.
  static PetscErrorCode Register();
};

} // namespace tf
