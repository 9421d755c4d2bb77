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

// Collective on the KSP. Its solve returned the error `code`: `why` says in words a user can act on where the
// factorization raised it (KLU, which stops on a singular matrix with a library error where MUMPS and PETSc's LU
// report through the KSP's reason); empty where it is another error.
PetscErrorCode DescribeSolveError(KSP ksp, PetscErrorCode code, std::string &why);

} // namespace tf
