// Shared definitions for tubeform: error-code conventions and small helpers.
#pragma once

#include <petscsys.h>

#ifndef PETSC_SUCCESS
#define PETSC_SUCCESS 0 // PETSc 3.18 predates the named constant.
#endif

namespace tf {

// Voigt order used everywhere: {xx, yy, zz, xy}; strains carry gamma_xy = 2 eps_xy.
constexpr int kNumStress = 4;

// Number of displacement components per node (plane strain).
constexpr int kDim = 2;

} // namespace tf
