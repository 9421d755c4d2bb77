#include "tubeform/assembly/linear_solver.hpp"

#include <cctype>

#include "tubeform/core/core.hpp"
#include "tubeform/core/log.hpp"

namespace tf {

namespace {

// MUMPS settings for the redundant (small-system) factorization, each taken
// only where the user gave no value (docs/performance.md, "The presets: MUMPS,
// and 1 or 2 ranks"; instruction counts of a whole run with callgrind):
//   ICNTL(8) = 0: no scaling. The stiffness of one material on one mesh is
//     well scaled, and MUMPS computed its scaling anew at every factorization
//     (8 % of a run's instructions).
//   ICNTL(7) = 0: AMD ordering in place of MUMPS's automatic choice, which
//     gave more fill on these meshes (5 % of a run's instructions).
struct MumpsDefault {
  const char *option, *value;
};
constexpr MumpsDefault kMumpsDefaults[] = {{"-redundant_mat_mumps_icntl_8", "0"},
                                           {"-redundant_mat_mumps_icntl_7", "0"}};

// The factorization the options finally chose, in words.
PetscErrorCode Describe(KSP ksp, std::string &solver, bool &redundant)
{
  PC pc;
  PetscBool is_redundant;
  PetscFunctionBeginUser;
  PetscCall(KSPGetPC(ksp, &pc));
  PetscCall(PetscObjectTypeCompare((PetscObject)pc, PCREDUNDANT, &is_redundant));
  redundant = is_redundant;
  if (is_redundant) {
    KSP inner;
    PetscCall(PCRedundantGetKSP(pc, &inner));
    PetscCall(KSPGetPC(inner, &pc));
  }
  PCType type;
  MatSolverType package = nullptr;
  PetscCall(PCGetType(pc, &type));
  PetscBool factor;
  PetscCall(PetscObjectTypeCompareAny((PetscObject)pc, &factor, PCLU, PCCHOLESKY, ""));
  if (factor) PetscCall(PCFactorGetMatSolverType(pc, &package));
  // "MUMPS LU", "PETSC LU", or the PC type of a user's choice.
  std::string name = package ? package : "";
  for (char &ch : name) ch = (char)std::toupper((unsigned char)ch);
  std::string kind = type ? type : "?";
  if (factor)
    for (char &ch : kind) ch = (char)std::toupper((unsigned char)ch);
  solver = name.empty() ? kind : name + " " + kind;
  PetscFunctionReturn(PETSC_SUCCESS);
}

// The redundant factorization (every rank factors the whole matrix, with `factorization`) or the distributed one
// (MUMPS), then the options; `defaults`: kMumpsDefaults where the user gave no value and MUMPS factors.
PetscErrorCode Configure(KSP ksp, bool distributed, Factorization factorization, bool defaults)
{
  PC pc;
  PetscBool user_pc;

  PetscFunctionBeginUser;
  PetscCall(KSPSetType(ksp, KSPPREONLY));
  PetscCall(KSPGetPC(ksp, &pc));
  PetscCall(PetscOptionsHasName(nullptr, nullptr, "-pc_type", &user_pc));
  if (distributed) {
    PetscCall(PCSetType(pc, PCLU));
    PetscCall(PCFactorSetMatSolverType(pc, MATSOLVERMUMPS));
  } else {
    KSP inner;
    PC inner_pc;
    PetscCall(PCSetType(pc, PCREDUNDANT));
    PetscCall(PCRedundantGetKSP(pc, &inner));
    PetscCall(KSPSetType(inner, KSPPREONLY));
    PetscCall(KSPGetPC(inner, &inner_pc));
    PetscCall(PCSetType(inner_pc, PCLU));
    const bool mumps = factorization == Factorization::Mumps;
    PetscCall(PCFactorSetMatSolverType(inner_pc, mumps ? MATSOLVERMUMPS : MATSOLVERKLU));
    if (!user_pc && defaults && mumps)
      for (const auto &d : kMumpsDefaults) {
        PetscBool set;
        PetscCall(PetscOptionsHasName(nullptr, nullptr, d.option, &set));
        if (!set) PetscCall(PetscOptionsSetValue(nullptr, d.option, d.value));
      }
  }
  PetscCall(KSPSetFromOptions(ksp));
  {
    // The inner solver of a redundant PC reads its options (-redundant_*) only
    // at set-up; read them now so that the run can say what will run.
    PetscBool still_redundant;
    PetscCall(PetscObjectTypeCompare((PetscObject)pc, PCREDUNDANT, &still_redundant));
    if (still_redundant) {
      KSP inner;
      PetscCall(PCRedundantGetKSP(pc, &inner));
      PetscCall(KSPSetFromOptions(inner));
    }
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

bool Distributed(PetscMPIInt size, PetscInt ndofs) { return size > 1 && ndofs > kDistributedDofs; }

} // namespace

PetscErrorCode SetupLinearSolver(KSP ksp, PetscInt ndofs, Factorization factorization, std::string &what,
                                 bool &redundant)
{
  MPI_Comm comm;
  PetscMPIInt size;

  PetscFunctionBeginUser;
  PetscCall(PetscObjectGetComm((PetscObject)ksp, &comm));
  PetscCallMPI(MPI_Comm_size(comm, &size));
  PetscCall(Configure(ksp, Distributed(size, ndofs), factorization, true));

  std::string solver;
  PetscCall(Describe(ksp, solver, redundant));
  char line[256];
  if (size == 1)
    PetscCall(PetscSNPrintf(line, sizeof(line), "%s on 1 rank (%d dofs)", solver.c_str(), (int)ndofs));
  else if (redundant)
    PetscCall(
      PetscSNPrintf(line, sizeof(line),
                    "%s on each of %d ranks, each factoring the whole matrix (%d dofs; bit-for-bit reproducible "
                    "runs; distributed above %d dofs)",
                    solver.c_str(), size, (int)ndofs, (int)kDistributedDofs));
  else
    PetscCall(PetscSNPrintf(line, sizeof(line),
                            "%s distributed over %d ranks (%d dofs; its last digits may differ from run to run)",
                            solver.c_str(), size, (int)ndofs));
  what = line;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode ReadFactorizationOptions(MPI_Comm comm, PetscInt ndofs, Factorization factorization, bool other_path)
{
  PetscMPIInt size, rank;
  Mat a = nullptr;
  KSP ksp = nullptr;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_size(comm, &size));
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCall(Log::Register());
  PetscCall(PetscLogStagePush(Log::unlogged_stage));
  // The identity, one row per rank: every factorization takes it, and it costs nothing.
  PetscCall(MatCreateAIJ(comm, 1, 1, PETSC_DETERMINE, PETSC_DETERMINE, 1, nullptr, 0, nullptr, &a));
  PetscCall(MatSetValue(a, rank, rank, 1.0, INSERT_VALUES));
  PetscCall(MatAssemblyBegin(a, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(a, MAT_FINAL_ASSEMBLY));
  PetscCall(KSPCreate(comm, &ksp));
  PetscErrorCode ierr = Configure(ksp, Distributed(size, ndofs) != other_path, factorization, !other_path);
  if (!ierr) ierr = KSPSetOperators(ksp, a, a);
  if (!ierr) ierr = KSPSetUp(ksp);
  if (!ierr) ierr = KSPSetUpOnBlocks(ksp); // a redundant PC's inner solver factors here
  PetscCall(KSPDestroy(&ksp));
  PetscCall(MatDestroy(&a));
  PetscCall(PetscLogStagePop());
  PetscCall(ierr);
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode FactoredMatrix(KSP ksp, Mat &factor, bool &mumps)
{
  PC pc;
  PetscBool redundant, factored;
  PetscFunctionBeginUser;
  factor = nullptr, mumps = false;
  PetscCall(KSPGetPC(ksp, &pc));
  PetscCall(PetscObjectTypeCompare((PetscObject)pc, PCREDUNDANT, &redundant));
  if (redundant) {
    KSP inner;
    PetscCall(PCRedundantGetKSP(pc, &inner));
    PetscCall(KSPGetPC(inner, &pc));
  }
  PetscCall(PetscObjectTypeCompareAny((PetscObject)pc, &factored, PCLU, PCCHOLESKY, PCILU, PCICC, ""));
  if (!factored) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PCFactorGetMatrix(pc, &factor));
  if (!factor) PetscFunctionReturn(PETSC_SUCCESS);
  MatSolverType type;
  PetscCall(MatFactorGetSolverType(factor, &type));
  mumps = type && std::string(type) == MATSOLVERMUMPS;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode DeterminantSign(KSP ksp, int &sign)
{
  Mat factor;
  bool mumps;
  PetscFunctionBeginUser;
  sign = 0;
  PetscCall(FactoredMatrix(ksp, factor, mumps));
  if (!mumps) PetscFunctionReturn(PETSC_SUCCESS);
  PetscInt on;
  PetscCall(MatMumpsGetIcntl(factor, 33, &on));
  if (on != 1) PetscFunctionReturn(PETSC_SUCCESS);
  PetscReal mantissa;
  PetscCall(MatMumpsGetRinfog(factor, 12, &mantissa)); // the determinant is RINFOG(12) x 2^INFOG(34)
  sign = mantissa > 0 ? 1 : mantissa < 0 ? -1 : 0;
  PetscFunctionReturn(PETSC_SUCCESS);
}

} // namespace tf
