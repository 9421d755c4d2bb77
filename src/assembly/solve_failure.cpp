#include "tubeform/assembly/solve_failure.hpp"

#include <string>

#include "tubeform/assembly/linear_solver.hpp"
#include "tubeform/core/core.hpp"

namespace tf {

namespace {

// MUMPS's INFOG(1) < 0 (MUMPS 5 users' guide, "Error diagnostics"), the ones a run can meet. `option` is the
// prefix of the options that reach this factorization: "-redundant_mat_mumps_" where every rank factors the
// whole matrix, "-mat_mumps_" where the factorization is distributed (each other prefix is read by no one);
// `distributed`: MUMPS factors on several ranks, whose way back is the factorization on every rank.
std::string MumpsError(PetscInt info1, PetscInt info2, const std::string &option, bool distributed)
{
  const std::string code =
    " (MUMPS INFOG(1) = " + std::to_string(info1) + ", INFOG(2) = " + std::to_string(info2) + ")";
  switch (info1) {
  case -6:
  case -10:
    // (ICNTL(24) 1: pivots below a threshold are null pivots, set aside, and the factorization goes on)
    return "the stiffness is singular" + code +
           ": a rigid-body motion left free (check the scene's supports) or an element without stiffness; " + option +
           "icntl_24 1 makes MUMPS set its null pivots aside and go on";
  case -8:
  case -9:
  case -14:
  case -15:
    return "MUMPS's workspace is too small" + code + ": raise " + option + "icntl_14 (percent extra, e.g. 50)";
  case -13:
    return "out of memory" + code +
           (distributed
              ? ": more ranks (each holds its share of the factors), a smaller mesh, or more memory"
              : ": a smaller mesh, more memory, or the distributed factorization (each rank holds a share: "
                "several ranks above " +
                  std::to_string((int)kDistributedDofs) + " dofs, or -pc_type lu -pc_factor_mat_solver_type mumps)");
  case -19:
    return "the memory " + option + "icntl_23 allows (MB per rank) is too small" + code + ": raise it, or leave it out";
  default:
    return "MUMPS failed" + code + ": see its users' guide, \"Error diagnostics\"" +
           (distributed ? "; or factor the whole matrix on every rank: -pc_type redundant "
                          "-redundant_pc_factor_mat_solver_type mumps"
                        : "");
  }
}

} // namespace

PetscErrorCode DescribeSolveFailure(KSP ksp, std::string &why)
{
  Mat factor;
  bool mumps;
  PetscFunctionBeginUser;
  why = "the linear solve failed";
  PetscCall(FactoredMatrix(ksp, factor, mumps));
  if (!factor) PetscFunctionReturn(PETSC_SUCCESS); // an iterative solver of the user's: KSP's reason says it
  if (mumps) {
    PetscInt info1, info2;
    PetscCall(MatMumpsGetInfog(factor, 1, &info1));
    PetscCall(MatMumpsGetInfog(factor, 2, &info2));
    // The factor's options prefix is the one MUMPS read its options with (the redundant PC's inner solver's
    // "redundant_", or none).
    const char *prefix = nullptr;
    PetscMPIInt size;
    PetscCall(MatGetOptionsPrefix(factor, &prefix));
    PetscCallMPI(MPI_Comm_size(PetscObjectComm((PetscObject)factor), &size));
    if (info1 < 0) why = MumpsError(info1, info2, std::string("-") + (prefix ? prefix : "") + "mat_mumps_", size > 1);
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  MatFactorError error;
  PetscCall(MatFactorGetError(factor, &error));
  if (error == MAT_FACTOR_NUMERIC_ZEROPIVOT || error == MAT_FACTOR_STRUCT_ZEROPIVOT)
    why = "the stiffness is singular (a zero pivot in PETSc's LU): a rigid-body motion left free (check the scene's "
          "supports) or an element without stiffness";
  else if (error == MAT_FACTOR_OUTMEMORY)
    why = "out of memory in PETSc's LU factorization";
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode DescribeSolveError(KSP ksp, PetscErrorCode code, std::string &why)
{
  Mat factor;
  bool mumps;
  MatSolverType type = nullptr;
  PetscFunctionBeginUser;
  why.clear();
  if (code != PETSC_ERR_LIB) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(FactoredMatrix(ksp, factor, mumps));
  if (factor) PetscCall(MatFactorGetSolverType(factor, &type));
  if (type && std::string(type) == MATSOLVERKLU)
    why = "the stiffness is singular (KLU found no usable pivot): a rigid-body motion left free (check the scene's "
          "supports) or an element without stiffness";
  PetscFunctionReturn(PETSC_SUCCESS);
}

} // namespace tf
