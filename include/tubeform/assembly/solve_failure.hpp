// Why a direct solve failed, in words a user can act on: the factorization's
// own report (MUMPS's INFOG(1), PETSc LU's zero pivot) instead of KSP's
// DIVERGED_PC_FAILED.
#pragma once

#include <petscksp.h>

#include <string>

namespace tf {

// Collective on the KSP. The KSP's solve failed; its PC is LU, or redundant
// with LU inside.
PetscErrorCode DescribeSolveFailure(KSP ksp, std::string &why);

} // namespace tf
