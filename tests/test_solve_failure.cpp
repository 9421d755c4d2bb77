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
// KLU (-factorization klu, every rank factoring the whole matrix): the same
// singular matrix stops its solve with an error that DescribeSolveError names
// as a singular stiffness, and on the 1D Laplacian it is made from (the last
// diagonal 2, its couplings kept) its solution of A x = 1 is the closed form
// x_i = i (n + 1 - i) / 2 (i from 1) to round-off (1e-12 relative: n is tens).
#include <petscksp.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "check.hpp"
#include "tubeform/assembly/linear_solver.hpp"
#include "tubeform/assembly/solve_failure.hpp"
#include "tubeform/core/core.hpp"

using namespace tf;

static const PetscInt kRowsPerRank = 6;

// The matrix above (`singular`), or the 1D Laplacian it is made from.
static PetscErrorCode Laplacian(MPI_Comm comm, bool singular, Mat &a)
{
  PetscInt lo, hi, n;
  PetscFunctionBeginUser;
  PetscCall(
    MatCreateAIJ(comm, kRowsPerRank, kRowsPerRank, PETSC_DETERMINE, PETSC_DETERMINE, 3, nullptr, 2, nullptr, &a));
  PetscCall(MatGetOwnershipRange(a, &lo, &hi));
  PetscCall(MatGetSize(a, &n, nullptr));
  for (PetscInt i = lo; i < hi; ++i) {
    if (singular && i == n - 1) {
      PetscCall(MatSetValue(a, i, i, 0.0, INSERT_VALUES)); // the null pivot
      continue;
    }
    PetscCall(MatSetValue(a, i, i, 2.0, INSERT_VALUES));
    if (i > 0) PetscCall(MatSetValue(a, i, i - 1, -1.0, INSERT_VALUES));
    if (i + 1 < (singular ? n - 1 : n)) PetscCall(MatSetValue(a, i, i + 1, -1.0, INSERT_VALUES));
  }
  PetscCall(MatAssemblyBegin(a, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(a, MAT_FINAL_ASSEMBLY));
  PetscFunctionReturn(PETSC_SUCCESS);
}

// One solve on the path SetupLinearSolver takes for `ndofs`; `why` is empty when it succeeded.
static PetscErrorCode Solve(Mat a, PetscInt ndofs, std::string &why, bool &redundant,
                            Factorization factorization = Factorization::Mumps)
{
  KSP ksp;
  Vec x, b;
  KSPConvergedReason reason;
  std::string what;
  PetscFunctionBeginUser;
  PetscCall(KSPCreate(PetscObjectComm((PetscObject)a), &ksp));
  PetscCall(SetupLinearSolver(ksp, ndofs, factorization, what, redundant));
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

// KLU on the singular matrix (an error DescribeSolveError names) and on the regular one (the closed form).
static PetscErrorCode CheckKlu(Mat a, Mat regular)
{
  KSP ksp;
  Vec x, b;
  std::string what, why;
  bool redundant;
  PetscInt lo, hi, n;
  PetscMPIInt rank;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(PetscObjectComm((PetscObject)a), &rank));
  PetscCall(MatGetSize(a, &n, nullptr));
  PetscCall(KSPCreate(PetscObjectComm((PetscObject)a), &ksp));
  PetscCall(SetupLinearSolver(ksp, kDistributedDofs, Factorization::Klu, what, redundant));
  if (!rank) std::printf("klu: %s\n", what.c_str());
  CHECK(what.find("KLU") != std::string::npos);
  PetscCall(KSPSetOperators(ksp, a, a));
  PetscCall(MatCreateVecs(a, &x, &b));
  PetscCall(VecSet(b, 1.0));
  PetscCall(PetscPushErrorHandler(PetscReturnErrorHandler, nullptr));
  const PetscErrorCode failed = KSPSolve(ksp, b, x);
  PetscCall(PetscPopErrorHandler());
  PetscCall(DescribeSolveError(ksp, failed, why));
  if (!rank) std::printf("  singular: error %d: %s\n", (int)failed, why.c_str());
  CHECK(failed != 0 && why.find("the stiffness is singular") != std::string::npos);
  PetscCall(MatGetOwnershipRange(regular, &lo, &hi));
  PetscCall(KSPSetOperators(ksp, regular, regular));
  PetscCall(KSPSolve(ksp, b, x));
  const PetscScalar *xa;
  double worst = 0;
  PetscCall(VecGetArrayRead(x, &xa));
  for (PetscInt i = lo; i < hi; ++i) {
    const double exact = 0.5 * (double)(i + 1) * (double)(n - i);
    worst = std::max(worst, std::abs(xa[i - lo] - exact) / exact);
  }
  PetscCall(VecRestoreArrayRead(x, &xa));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &worst, 1, MPI_DOUBLE, MPI_MAX, PetscObjectComm((PetscObject)a)));
  if (!rank) std::printf("  regular: largest relative difference from the closed form %.2e\n", worst);
  CHECK(worst < 1e-12);
  PetscCall(VecDestroy(&x));
  PetscCall(VecDestroy(&b));
  PetscCall(KSPDestroy(&ksp));
  PetscFunctionReturn(PETSC_SUCCESS);
}

int main(int argc, char **argv)
{
  Mat a, regular;
  PetscCall(PetscInitialize(&argc, &argv, nullptr, nullptr));
  PetscCall(Laplacian(PETSC_COMM_WORLD, true, a));
  PetscCall(Laplacian(PETSC_COMM_WORLD, false, regular));
  PetscCall(CheckPath(a, kDistributedDofs));     // every rank factors the whole matrix
  PetscCall(CheckPath(a, kDistributedDofs + 1)); // distributed on several ranks (on one: redundant again)
  PetscCall(CheckKlu(a, regular));
  PetscCall(MatDestroy(&a));
  PetscCall(MatDestroy(&regular));
  const int status = ReportChecks("solve_failure");
  PetscCall(PetscFinalize());
  return status;
}
