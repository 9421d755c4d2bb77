// tubeform: elasto-plastic FE analysis of squaring a circular tube between
// V-shaped dies (Huang 2008), on PETSc.
//
// Sample runs:
//   mpirun -n 2 build/tubeform -options_file options/pressure.opts -monitor
//   build/tubeform -help
#include <petscsys.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <string>
#include <vector>

#include "tubeform/core/core.hpp"
#include "tubeform/core/signals.hpp"
#include "tubeform/driver/problem.hpp"
#include "tubeform/io/options.hpp"
#include "tubeform/io/options_files.hpp"
#include "tubeform/io/options_left.hpp"
#include "tubeform/scenes/registry.hpp"

static const char help[] =
  "tubeform: updated-Lagrangian elasto-plastic FE analysis of tube squaring (plane strain).\n"
  "Usage: mpirun -n 2 build/tubeform -options_file options/<scene>.opts [-option value ...]\n\n";

// The error estimate's companion (driver/answer.hpp): the same case at half
// the resolution (half the cells through the wall and around, half the trial
// increments; a mesh file is kept, so the estimate then covers the steps
// only), run quietly once the main run has reached its end; its history is what the answer
// compares with. Its result file is removed.
// The companion keeps at least 2 cells through the wall: with one, a bending
// wall's answer is off by an order more than the run's (the fast preset's 2 x 64
// case: a load estimate of 11 % for a 4 % error, 0.27 in C/t for 0.01).
constexpr PetscInt kCompanionMinNt = 2;

static PetscErrorCode Companion(const tf::Options &opt, std::vector<tf::HistoryRow> &rows)
{
  tf::Options c = opt;
  PetscFunctionBeginUser;
  c.mesh_nt = std::max<PetscInt>(kCompanionMinNt, opt.mesh_nt / 2);
  tf::ChooseElement(c); // -element auto: the companion's element follows its own wall
  c.mesh_ntheta = std::max<PetscInt>(4, 2 * (opt.mesh_ntheta / 4));
  c.increments = std::max<PetscInt>(1, opt.increments / 2);
  if (opt.unload_increments > 0) c.unload_increments = std::max<PetscInt>(1, opt.unload_increments / 2);
  c.output = opt.output + ".companion.h5";
  c.history_csv.clear();
  c.checkpoint.clear(), c.restart.clear();
  c.checkpoint_every = 0;
  c.progress = 0, c.monitor = PETSC_FALSE;
  c.output_every = std::numeric_limits<int>::max(), c.output_stroke = 0;
  c.error_estimate = PETSC_FALSE;
  const double t0 = MPI_Wtime();
  PetscErrorCode failed;
  {
    tf::Problem problem;
    problem.SetQuiet();
    PetscCall(problem.Setup(PETSC_COMM_WORLD, c));
    failed = problem.Run();
    rows = problem.history().rows();
  }
  PetscMPIInt rank;
  PetscCallMPI(MPI_Comm_rank(PETSC_COMM_WORLD, &rank));
  if (rank == 0) {
    std::remove(c.output.c_str());
    std::remove((c.output.substr(0, c.output.size() - 3) + ".xmf").c_str()); // its ParaView index
  }
  // A stop signal stops the job (Run's caller reports it); a companion that
  // could not finish leaves the run without an estimate, not without a result.
  if (failed == PETSC_ERR_NOT_CONVERGED) {
    const char *why = nullptr;
    (void)PetscErrorMessage(failed, nullptr, (char **)&why);
    std::string text = why ? why : "?";
    text = text.substr(0, text.find("; results up to there")); // its file is not kept
    PetscCall(
      PetscPrintf(PETSC_COMM_WORLD, "tubeform: no error estimate: its companion run stopped (%s)\n", text.c_str()));
    rows.clear();
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  PetscCall(failed);
  const std::string mesh = opt.mesh_file.empty() ? tf::Formatted("%d x %d cells", (int)c.mesh_nt, (int)c.mesh_ntheta)
                                                 : "the mesh file's cells";
  PetscCall(PetscPrintf(PETSC_COMM_WORLD,
                        "tubeform: companion run for the error estimate: %s, %d trial increments (%.1f s)\n",
                        mesh.c_str(), (int)c.increments, MPI_Wtime() - t0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

// `collective` tells main whether an error seen so far was found by every
// rank at once (option parsing is: each rank reads the same options).
static PetscErrorCode Run(bool &collective)
{
  tf::Options opt;
  PetscFunctionBeginUser;
  collective = true;
  PetscCall(tf::ReadOptions(PETSC_COMM_WORLD, tf::SceneNames(), opt));
  collective = false;
  if (opt.help) PetscFunctionReturn(PETSC_SUCCESS);
  tf::Problem problem;
  PetscCall(problem.Setup(PETSC_COMM_WORLD, opt));
  // Before anything is written:
  PetscCall(tf::CheckOptionsLeft(PETSC_COMM_WORLD, opt, problem.system().ndofs(), problem.system().redundant()));
  if (opt.error_estimate && (opt.scene == "squaring" || opt.scene == "flattening"))
    problem.SetCompanion([&opt](std::vector<tf::HistoryRow> &rows) { return Companion(opt, rows); });
  PetscCall(problem.Run());
  PetscFunctionReturn(PETSC_SUCCESS);
}

int main(int argc, char **argv)
{
  PetscMPIInt rank;
  // A missing options file, before PETSc reads them (it would stop with a
  // 30-line error): every process finds the same, the first one says it.
  const std::string bad_file = tf::CheckOptionsFiles(argc, argv);
  if (!bad_file.empty()) {
    const char *launcher_rank = std::getenv("OMPI_COMM_WORLD_RANK"); // set by mpirun before MPI starts
    if (!launcher_rank) launcher_rank = std::getenv("PMI_RANK");
    if (!launcher_rank || std::atoi(launcher_rank) == 0) fprintf(stderr, "tubeform: error: %s\n", bad_file.c_str());
    return 1;
  }
  PetscErrorCode ierr = PetscInitialize(&argc, &argv, nullptr, help);
  if (ierr) return 1;
  // Errors come back as codes; main prints one line and every rank exits.
  (void)PetscPushErrorHandler(PetscReturnErrorHandler, nullptr);
  tf::InstallStopSignals();
  (void)MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
  bool collective = false;
  ierr = Run(collective);
  (void)PetscPopErrorHandler();
  if (ierr) {
    const char *text = nullptr;
    char *specific = nullptr;
    (void)PetscErrorMessage(ierr, &text, &specific);
    const char *msg = specific && specific[0] ? specific : (text ? text : "unknown error");
    if (collective || ierr == PETSC_ERR_USER_INPUT || ierr == PETSC_ERR_FILE_WRITE || ierr == PETSC_ERR_NOT_CONVERGED ||
        ierr == PETSC_ERR_SIG) {
      // Collective errors: every rank found the same problem; rank 0 reports it.
      if (rank == 0) fprintf(stderr, "tubeform: error: %s\n", msg);
      (void)PetscFinalize();
      return 1;
    }
    // Anything else may have struck one rank only: report it and abort the job
    // so that no rank waits forever in a collective call.
    fprintf(stderr, "tubeform: error on rank %d: %s\n", rank, msg);
    MPI_Abort(MPI_COMM_WORLD, 2);
  }
  ierr = PetscFinalize();
  return ierr ? 1 : 0;
}
