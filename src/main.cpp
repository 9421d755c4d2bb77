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
#include "tubeform/io/output.hpp"
#include "tubeform/scenes/registry.hpp"

static const char help[] =
  "tubeform: updated-Lagrangian elasto-plastic FE analysis of tube squaring (plane strain).\n"
  "Usage: mpirun -n 2 build/tubeform -options_file options/<scene>.opts [-option value ...]\n\n";

// The error estimate's companions (driver/answer.hpp, kStepShare) keep at
// least 2 cells through the wall: with one, a bending wall's answer is off by
// an order more than the run's (the fast preset's 2 x 64 case: a load
// difference of 4 % for a 4 % error, 0.09 in C/t for 0.01).
constexpr PetscInt kCompanionMinNt = 2;

// One run of `opt` (quiet: a companion's; rows: its history, when it ends). Its
// error comes back with the message it raised, taken before the run's clean-up
// (a result file closed on a full disk) can raise errors of its own whose
// messages would replace it.
static PetscErrorCode RunProblem(const tf::Options &opt, bool quiet, const tf::Problem::CompanionRun &companion,
                                 std::vector<tf::HistoryRow> *rows, tf::Refinement *refinement = nullptr)
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
    if (!failed && refinement) *refinement = problem.refinement();
  }
  PetscCheck(!failed, PETSC_COMM_SELF, failed, "%s", why.c_str());
  PetscFunctionReturn(PETSC_SUCCESS);
}

// A companion's options: `ran`'s (the run's as it ran them: its element and friction regularization fixed),
// writing no file, quiet.
static tf::Options Companion(const tf::Options &ran)
{
  tf::Options c = ran;
  c.output.clear(), c.history_csv.clear(); // no files: nothing of it is left behind, whatever ends it
  c.checkpoint.clear(), c.restart.clear();
  c.checkpoint_every = 0;
  c.progress = 0, c.monitor = PETSC_FALSE;
  c.output_every = std::numeric_limits<int>::max(), c.output_stroke = 0;
  c.error_estimate = PETSC_FALSE;
  c.target_load = c.target_c_over_t = 0;
  return c;
}

// One companion run: its history in `rows`, its wall time in `seconds`.
static PetscErrorCode RunCompanion(const tf::Options &c, std::vector<tf::HistoryRow> &rows, double &seconds)
{
  PetscFunctionBeginUser;
  const double t0 = MPI_Wtime();
  PetscCall(RunProblem(c, true, nullptr, &rows));
  seconds = MPI_Wtime() - t0;
  PetscFunctionReturn(PETSC_SUCCESS);
}

// The estimate's two companions, run once the main run's results are final: `mesh` on half the cells through the
// wall and around at the run's increment limits (a mesh file is kept: it would be the run itself, and is not run),
// `steps` on the cells of `mesh` at twice those limits.
static PetscErrorCode Companions(const tf::Options &ran, tf::Companions &out)
{
  tf::Options c = Companion(ran);
  double t_mesh = 0, t_steps = 0;
  PetscFunctionBeginUser;
  const bool coarsen = ran.mesh_file.empty();
  out.mesh_share = ran.element == tf::fe::Formulation::QM6Bar ? tf::kMeshShareQM6Bar : tf::kMeshShareQM6;
  if (coarsen) {
    c.mesh_nt = std::max<PetscInt>(kCompanionMinNt, ran.mesh_nt / 2);
    c.mesh_ntheta = std::max<PetscInt>(4, 2 * (ran.mesh_ntheta / 4));
    PetscCall(RunCompanion(c, out.mesh, t_mesh));
  }
  c.increments = std::max<PetscInt>(1, ran.increments / 2);
  c.rmin_deps = 2 * ran.rmin_deps, c.rmin_deps_yield = 2 * ran.rmin_deps_yield, c.rmin_domega = 2 * ran.rmin_domega;
  PetscCall(RunCompanion(c, out.steps, t_steps));
  const std::string cells =
    coarsen ? tf::Formatted("%d x %d cells at the run's increments (%.1f s), and there at twice their limits",
                            (int)c.mesh_nt, (int)c.mesh_ntheta, t_mesh)
            : std::string("the mesh file's cells at twice the run's increment limits");
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "tubeform: companion runs for the error estimate: %s (%.1f s)\n",
                        cells.c_str(), t_steps));
  PetscFunctionReturn(PETSC_SUCCESS);
}

// A finer level of accuracy on demand (driver/refine.hpp), its options `level`: the last level's complete
// results kept as <output stem>.level<k-1>.h5 while it runs into -output (removed once it ends; a stop or failure
// leaves them), `next` what follows it.
static PetscErrorCode RunFinerLevel(const tf::Options &level, const tf::Problem::CompanionRun &companion,
                                    tf::Refinement &next)
{
  std::string kept, why;
  PetscFunctionBeginUser;
  if (!level.output.empty()) {
    const std::string stem = level.output.size() > 3 && level.output.substr(level.output.size() - 3) == ".h5"
                               ? level.output.substr(0, level.output.size() - 3)
                               : level.output;
    kept = tf::Formatted("%s.level%d.h5", stem.c_str(), (int)level.level - 1);
    PetscCall(tf::KeepResultCopy(PETSC_COMM_WORLD, level.output, kept, why));
    if (!why.empty()) {
      PetscCall(PetscPrintf(PETSC_COMM_WORLD,
                            "tubeform: warning: no finer level: level %d's results in %s cannot be kept while it runs "
                            "(%s); they are the run's, with their estimate over the target\n",
                            (int)level.level - 1, level.output.c_str(), why.c_str()));
      next = tf::Refinement{};
      PetscFunctionReturn(PETSC_SUCCESS);
    }
  }
  const std::string note = kept.empty() ? ""
                                        : tf::Formatted(": level %d's results are kept in %s until it ends",
                                                        (int)level.level - 1, kept.c_str());
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "tubeform: accuracy on demand, level %d (%.0f s so far)%s\n",
                        (int)level.level, MPI_Wtime() - level.job_started, note.c_str()));
  PetscCall(RunProblem(level, false, companion, nullptr, &next));
  PetscMPIInt rank;
  PetscCallMPI(MPI_Comm_rank(PETSC_COMM_WORLD, &rank));
  if (rank == 0 && !kept.empty()) std::remove(kept.c_str());
  PetscFunctionReturn(PETSC_SUCCESS);
}

// The run of the options, level after level while its estimate passes its targets (accuracy on demand,
// driver/refine.hpp): each level writes the results (the last level's are the run's).
static PetscErrorCode Run()
{
  tf::Options opt;
  PetscFunctionBeginUser;
  PetscCall(tf::ReadOptions(PETSC_COMM_WORLD, tf::SceneNames(), opt));
  if (opt.help) PetscFunctionReturn(PETSC_SUCCESS);
  opt.job_started = MPI_Wtime();
  tf::Problem::CompanionRun companion;
  if (opt.error_estimate && (opt.scene == "squaring" || opt.scene == "flattening"))
    companion = [](const tf::Options &ran, tf::Companions &out) { return Companions(ran, out); };
  tf::Refinement next;
  PetscCall(RunProblem(opt, false, companion, nullptr, &next));
  while (next.follows) PetscCall(RunFinerLevel(next.next, companion, next));
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
