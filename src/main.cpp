// tubeform: elasto-plastic FE analysis of squaring a circular tube between
// V-shaped dies (Huang 2008), on PETSc.
//
// Sample runs:
//   mpirun -n 2 build/tubeform -options_file options/pressure.opts -monitor
//   build/tubeform -help
#include <hdf5.h>
#include <petscsys.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <string>
#include <vector>

#include "tubeform/core/core.hpp"
#include "tubeform/core/job_end.hpp"
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
// only), run quietly once the main run's results are final, writing no file;
// its history is what the answer compares with. How it ended is the driver's
// to judge (Problem::Estimate): an error means no estimate.
// The companion keeps at least 2 cells through the wall: with one, a bending
// wall's answer is off by an order more than the run's (the fast preset's 2 x 64
// case: a load estimate of 11 % for a 4 % error, 0.27 in C/t for 0.01).
constexpr PetscInt kCompanionMinNt = 2;

// One run of `opt` (quiet: a companion's; rows: its history, when it ends). Its
// error comes back with the message it raised, taken before the run's clean-up
// (a result file closed on a full disk) can raise errors of its own whose
// messages would replace it.
static PetscErrorCode RunProblem(const tf::Options &opt, bool quiet, const tf::Problem::CompanionRun &companion,
                                 std::vector<tf::HistoryRow> *rows)
{
  std::string why;
  PetscErrorCode failed;
  PetscFunctionBeginUser;
  {
    tf::Problem problem;
    if (quiet) problem.SetQuiet();
    failed = problem.Setup(PETSC_COMM_WORLD, opt);
    // (the run's options nothing reads: an error before anything is written)
    if (!failed && !quiet)
      failed = tf::CheckOptionsLeft(PETSC_COMM_WORLD, opt, problem.system().ndofs(), problem.system().redundant());
    if (!failed && companion) problem.SetCompanion(companion);
    if (!failed) failed = problem.Run();
    if (failed) why = tf::ErrorText(failed);
    if (!failed && rows) *rows = problem.history().rows();
  }
  PetscCheck(!failed, PETSC_COMM_SELF, failed, "%s", why.c_str());
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode Companion(const tf::Options &opt, std::vector<tf::HistoryRow> &rows)
{
  tf::Options c = opt;
  PetscFunctionBeginUser;
  c.mesh_nt = std::max<PetscInt>(kCompanionMinNt, opt.mesh_nt / 2);
  tf::ChooseElement(c); // -element auto: the companion's element follows its own wall
  c.mesh_ntheta = std::max<PetscInt>(4, 2 * (opt.mesh_ntheta / 4));
  c.increments = std::max<PetscInt>(1, opt.increments / 2);
  if (opt.unload_increments > 0) c.unload_increments = std::max<PetscInt>(1, opt.unload_increments / 2);
  c.output.clear(), c.history_csv.clear(); // no files: nothing of it is left behind, whatever ends it
  c.checkpoint.clear(), c.restart.clear();
  c.checkpoint_every = 0;
  c.progress = 0, c.monitor = PETSC_FALSE;
  c.output_every = std::numeric_limits<int>::max(), c.output_stroke = 0;
  c.error_estimate = PETSC_FALSE;
  const double t0 = MPI_Wtime();
  PetscCall(RunProblem(c, true, nullptr, &rows));
  const std::string mesh = opt.mesh_file.empty() ? tf::Formatted("%d x %d cells", (int)c.mesh_nt, (int)c.mesh_ntheta)
                                                 : "the mesh file's cells";
  PetscCall(PetscPrintf(PETSC_COMM_WORLD,
                        "tubeform: companion run for the error estimate: %s, %d trial increments (%.1f s)\n",
                        mesh.c_str(), (int)c.increments, MPI_Wtime() - t0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode Run()
{
  tf::Options opt;
  PetscFunctionBeginUser;
  PetscCall(tf::ReadOptions(PETSC_COMM_WORLD, tf::SceneNames(), opt));
  if (opt.help) PetscFunctionReturn(PETSC_SUCCESS);
  tf::Problem::CompanionRun companion;
  if (opt.error_estimate && (opt.scene == "squaring" || opt.scene == "flattening"))
    companion = [&opt](std::vector<tf::HistoryRow> &rows) { return Companion(opt, rows); };
  PetscCall(RunProblem(opt, false, companion, nullptr));
  PetscFunctionReturn(PETSC_SUCCESS);
}

int main(int argc, char **argv)
{
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
  // Errors come back as codes; the ranks agree on how the job ends (core/job_end.hpp),
  // on a communicator of their own.
  (void)PetscPushErrorHandler(PetscReturnErrorHandler, nullptr);
  (void)H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr); // HDF5's error stacks: a failed call is one line of ours
  tf::InstallStopSignals();
  MPI_Comm agree;
  (void)MPI_Comm_dup(PETSC_COMM_WORLD, &agree);
  ierr = Run();
  (void)PetscPopErrorHandler();
  const int code = tf::EndJob(agree, ierr);
  (void)MPI_Comm_free(&agree);
  ierr = PetscFinalize();
  return code ? code : (ierr ? 1 : 0);
}
