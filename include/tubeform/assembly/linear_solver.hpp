// The direct solver of every increment: MUMPS LU, as the design says, set up
// for the size of the system (docs/performance.md, "Solver"):
//   - up to kDistributedDofs, or on one rank: every rank factors the whole
//     matrix with sequential MUMPS (PCREDUNDANT). Runs are reproducible bit
//     for bit at a given rank count, and on the paper's meshes (a few thousand
//     dofs) a factorization spread over ranks is slower than one on a rank.
//   - above it on several ranks: MUMPS's distributed factorization, which
//     spreads the work and the memory; its dynamic scheduling changes the
//     order of floating-point operations from run to run, so results then
//     differ in their last digits between runs.
// MUMPS's own defaults are tuned for large systems; on these small ones its
// per-call overhead dominates, and two settings cut it (kMumpsDefaults). Any
// solver option given by the user (-pc_type, -redundant_*, -mat_mumps_*)
// overrides what is chosen here.
#pragma once

#include <petscksp.h>

#include <string>

namespace tf {

// The factorization of a system every rank factors whole (PCREDUNDANT): MUMPS, as the design says, or KLU
// (SuiteSparse, through PETSc), which pivots as MUMPS does and, at the few hundred to few thousand dofs of a tube
// quarter, costs less per call (docs/performance.md, "Factorization"). The distributed one is always MUMPS.
enum class Factorization { Mumps, Klu };

// Above this many dofs, on more than one rank, the factorization is
// distributed (measured crossover on 2 ranks: docs/performance.md, "Solver").
constexpr PetscInt kDistributedDofs = 20000;

// Collective: KSP preonly with an LU factorization (`factorization` where every
// rank factors the whole matrix, else MUMPS) for a system of `ndofs` global dofs on
// the KSP's communicator, then KSPSetFromOptions. `what` receives one line
// saying which factorization was chosen and why; `redundant` whether every
// rank factors the whole matrix (PCREDUNDANT, the options prefix redundant_).
PetscErrorCode SetupLinearSolver(KSP ksp, PetscInt ndofs, Factorization factorization, std::string &what,
                                 bool &redundant);

// Collective: sets up and factors a solver as SetupLinearSolver does for a
// system of `ndofs` dofs (`other_path`: the factorization it does not choose
// there, redundant or distributed, without kMumpsDefaults), on a stand-in (the
// identity, one row per rank), and destroys it. PETSc's objects read some
// options only at their first factorization (MUMPS's -[redundant_]mat_mumps_*):
// after this they are marked read, before the run's own solver factors.
PetscErrorCode ReadFactorizationOptions(MPI_Comm comm, PetscInt ndofs, Factorization factorization, bool other_path);

// The factored matrix of a direct solve (through PCREDUNDANT to its inner
// KSP), or nullptr when the preconditioner factors nothing (an iterative
// solver of the user's) or has not factored yet; `mumps` says whether MUMPS
// made it.
PetscErrorCode FactoredMatrix(KSP ksp, Mat &factor, bool &mumps);

// Collective: the sign of the determinant of the last matrix MUMPS factored
// (+1, -1), or 0 when MUMPS does not compute it (it does with
// -redundant_mat_mumps_icntl_33 1, or -mat_mumps_icntl_33 1 when distributed).
// A change of sign along a load path is an eigenvalue of the tangent passing
// zero: a bifurcation or a limit point.
PetscErrorCode DeterminantSign(KSP ksp, int &sign);

} // namespace tf
