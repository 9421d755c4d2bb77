// A singular matrix on each factorization path (SetupLinearSolver: redundant
// up to kDistributedDofs or on one rank, distributed above it on several):
//  - the solve fails and DescribeSolveFailure says so with MUMPS's code
//    (INFOG(1) -10, numerically singular, or -6, structurally);
//  - it names the null-pivot option of the path in use (-mat_mumps_icntl_24
//    when distributed, -redundant_mat_mumps_icntl_24 when every rank factors
//    the whole matrix), never the other prefix's;
//  - the option it names acts: given as it says, the same solve succeeds,
//    while the other prefix's option leaves it failing (no one reads it).
// The matrix: a 1D Laplacian, 6 rows a rank, its last row and column zero but
// for a stored 0 on the diagonal, so that a pivot is exactly zero whatever the
// scaling and ordering. (A stiffness with a rigid-body motion left free is
// singular only to round-off: MUMPS finds no null pivot without ICNTL(24).)
// The path is chosen by the `ndofs` SetupLinearSolver is given, not by the
// matrix's size, so a small matrix takes the path of a large system.
#include <petscksp.h>

#include <string>

#include "check.hpp"
#include "tubeform/assembly/linear_solver.hpp"
#include "tubeform/assembly/solve_failure.hpp"
#include "tubeform/core/core.hpp"

using namespace tf;

static const PetscInt kRowsPerRank = 6;

static PetscErrorCode SingularMatrix(MPI_Comm comm, Mat &a)
{
  PetscInt lo, hi, n;
  PetscFunctionBeginUser;
  PetscCall(
    MatCreateAIJ(comm, kRowsPerRank, kRowsPerRank, PETSC_DETERMINE, PETSC_DETERMINE, 3, nullptr, 2, nullptr, &a));
  PetscCall(MatGetOwnershipRange(a, &lo, &hi));
  PetscCall(MatGetSize(a, &n, nullptr));
  for (PetscInt i = lo; i < hi; ++i) {
    if (i == n - 1) {
      PetscCall(MatSetValue(a, i, i, 0.0, INSERT_VALUES)); // the null pivot
      continue;
    }
    PetscCall(MatSetValue(a, i, i, 2.0, INSERT_VALUES));
    if (i > 0) PetscCall(MatSetValue(a, i, i - 1, -1.0, INSERT_VALUES));
    if (i + 1 < n - 1) PetscCall(MatSetValue(a, i, i + 1, -1.0, INSERT_VALUES));
  }
  PetscCall(MatAssemblyBegin(a, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(a, MAT_FINAL_ASSEMBLY));
  PetscFunctionReturn(PETSC_SUCCESS);
}

// One solve on the path SetupLinearSolver takes for `ndofs`; `why` is empty when it succeeded.
static PetscErrorCode Solve(Mat a, PetscInt ndofs, std::string &why, bool &redundant)
{
  KSP ksp;
  Vec x, b;
  KSPConvergedReason reason;
  std::string what;
  PetscFunctionBeginUser;
  PetscCall(KSPCreate(PetscObjectComm((PetscObject)a), &ksp));
  PetscCall(SetupLinearSolver(ksp, ndofs, what, redundant));
  PetscCall(KSPSetOperators(ksp, a, a));
  PetscCall(MatCreateVecs(a, &x, &b));
  PetscCall(VecSet(b, 1.0));
  PetscCall(KSPSolve(ksp, b, x));
  PetscCall(KSPGetConvergedReason(ksp, &reason));
  why.clear();
  if (reason < 0) PetscCall(DescribeSolveFailure(ksp, why));
  PetscCall(VecDestroy(&x));
  PetscCall(VecDestroy(&b));
  PetscCall(KSPDestroy(&ksp));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode CheckPath(Mat a, PetscInt ndofs)
{
  PetscMPIInt rank, size;
  std::string why;
  bool redundant;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(PetscObjectComm((PetscObject)a), &rank));
  PetscCallMPI(MPI_Comm_size(PetscObjectComm((PetscObject)a), &size));
  const bool distributed = size > 1 && ndofs > kDistributedDofs;
  const std::string named = distributed ? "-mat_mumps_icntl_24" : "-redundant_mat_mumps_icntl_24";
  const std::string other = distributed ? "-redundant_mat_mumps_icntl_24" : "-mat_mumps_icntl_24";

  PetscCall(Solve(a, ndofs, why, redundant));
  if (!rank) std::printf("%d ranks, %d dofs: %s\n", size, (int)ndofs, why.c_str());
  CHECK(redundant == !distributed);
  CHECK(why.find("the stiffness is singular") != std::string::npos);
  CHECK(why.find("INFOG(1) = -10") != std::string::npos || why.find("INFOG(1) = -6") != std::string::npos);
  CHECK(why.find(" " + named + " 1 ") != std::string::npos); // (" -mat_..." is not inside "-redundant_mat_...")
  CHECK(why.find(" " + other + " ") == std::string::npos);

  // The other prefix's option is read by no one: the solve still fails.
  PetscCall(PetscOptionsSetValue(nullptr, other.c_str(), "1"));
  PetscCall(Solve(a, ndofs, why, redundant));
  CHECK(why.find("the stiffness is singular") != std::string::npos);
  PetscCall(PetscOptionsClearValue(nullptr, other.c_str()));
  // The named one acts: MUMPS sets the null pivot aside and the solve succeeds.
  PetscCall(PetscOptionsSetValue(nullptr, named.c_str(), "1"));
  PetscCall(Solve(a, ndofs, why, redundant));
  if (!rank) std::printf("  with %s 1: %s\n", named.c_str(), why.empty() ? "solved" : why.c_str());
  CHECK(why.empty());
  PetscCall(PetscOptionsClearValue(nullptr, named.c_str()));
  PetscFunctionReturn(PETSC_SUCCESS);
}

int main(int argc, char **argv)
{
  Mat a;
  PetscCall(PetscInitialize(&argc, &argv, nullptr, nullptr));
  PetscCall(SingularMatrix(PETSC_COMM_WORLD, a));
  PetscCall(CheckPath(a, kDistributedDofs));     // every rank factors the whole matrix
  PetscCall(CheckPath(a, kDistributedDofs + 1)); // distributed on several ranks (on one: redundant again)
  PetscCall(MatDestroy(&a));
  const int status = ReportChecks("solve_failure");
  PetscCall(PetscFinalize());
  return status;
}
