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
#include <string>
#include <vector>

#include "tubeform/core/core.hpp"
#include "tubeform/core/job_end.hpp"
#include "tubeform/core/signals.hpp"
#include "tubeform/driver/beside.hpp"
#include "tubeform/driver/companions.hpp"
#include "tubeform/driver/driver_options.hpp"
#include "tubeform/driver/problem.hpp"
#include "tubeform/io/options.hpp"
#include "tubeform/io/options_files.hpp"
#include "tubeform/io/output.hpp"
#include "tubeform/scenes/registry.hpp"

static const char help[] =
  "tubeform: updated-Lagrangian elasto-plastic FE analysis of tube squaring (plane strain).\n"
  "Usage: mpirun -n 2 build/tubeform -options_file options/<scene>.opts [-option value ...]\n\n";

// The estimate of a level that takes the last one as its mesh companion (tf::Refinement::reuse): the last level's run
// as its mesh companion, and the increments' part from `companions` asked for it alone, on the last level's cells at
// twice its increment limits (tf::AccuracyParams::steps_only: run here, or beside the run by the companions' ranks).
static tf::Problem::CompanionRun Reused(MPI_Comm comm, const tf::Refinement &last,
                                        const tf::Problem::CompanionRun &companions)
{
  return [comm, c = last.companions, level = last.last, companions](const tf::Options &, tf::Companions &out) {
    tf::Options steps_only = level;
    tf::Companions steps;
    PetscFunctionBeginUser;
    steps_only.accuracy.steps_only = true;
    PetscCall(companions(steps_only, steps));
    out = c;
    out.steps = std::move(steps.steps), out.steps_base = c.mesh;
    PetscCall(PetscPrintf(comm, "tubeform: the error estimate's mesh part from level %d's run\n", c.level));
    PetscFunctionReturn(PETSC_SUCCESS);
  };
}

// A finer level of accuracy on demand (driver/refine.hpp), `next.next` its options, on comm: the last level's
// complete results kept as <output stem>.level<k-1>.h5 while it runs into -output (removed once it ends; a stop or
// failure leaves them); `next` then what follows it.
static PetscErrorCode RunFinerLevel(MPI_Comm comm, const tf::Problem::CompanionRun &companions, tf::Refinement &next)
{
  std::string kept, why;
  const tf::Options level = next.next;
  const tf::Problem::CompanionRun companion = next.reuse && companions ? Reused(comm, next, companions) : companions;
  PetscFunctionBeginUser;
  if (!level.output.empty()) {
    kept = tf::Formatted("%s.level%d.h5", tf::ResultStem(level.output).c_str(), (int)level.level - 1);
    PetscCall(tf::KeepResultCopy(comm, level.output, kept, why));
    if (!why.empty()) {
      PetscCall(PetscPrintf(comm,
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
  PetscCall(PetscPrintf(comm, "tubeform: accuracy on demand, level %d (%.0f s so far)%s\n", (int)level.level,
                        MPI_Wtime() - level.job_started, note.c_str()));
  PetscCall(tf::RunOnce(comm, level, false, companion, nullptr, &next));
  PetscMPIInt rank;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (rank == 0 && !kept.empty()) std::remove(kept.c_str());
  PetscFunctionReturn(PETSC_SUCCESS);
}

// The run of the options on comm, level after level while its estimate passes its targets (accuracy on demand,
// driver/refine.hpp): each level writes the results (the last level's are the run's); `after` told what follows
// each.
static PetscErrorCode RunLevels(MPI_Comm comm, const tf::Options &opt, const tf::Problem::CompanionRun &companion,
                                const tf::LevelHook &after)
{
  tf::Refinement next;
  PetscFunctionBeginUser;
  PetscCall(tf::RunOnce(comm, opt, false, companion, nullptr, &next));
  if (after) PetscCall(after(next));
  while (next.follows) {
    PetscCall(RunFinerLevel(comm, companion, next));
    if (after) PetscCall(after(next));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

// The run of the options: its error estimate's companions beside it where that costs no wall time
// (driver/beside.hpp), else after it.
static PetscErrorCode Run()
{
  tf::Options opt;
  PetscMPIInt size;
  PetscFunctionBeginUser;
  PetscCall(tf::ReadOptions(PETSC_COMM_WORLD, tf::DriverOptions(), tf::SceneReaders(), opt));
  if (opt.help) PetscFunctionReturn(tf::PrintSceneHelp(PETSC_COMM_WORLD, opt.known));
  opt.job_started = MPI_Wtime();
  PetscCallMPI(MPI_Comm_size(PETSC_COMM_WORLD, &size));
  tf::Problem::CompanionRun companion;
  if (opt.accuracy.error_estimate && tf::PressesWithTools(opt)) {
    if (tf::CompanionsBeside(opt, size)) PetscFunctionReturn(tf::RunBeside(PETSC_COMM_WORLD, opt, RunLevels));
    companion = [](const tf::Options &ran, tf::Companions &out) {
      return tf::RunCompanions(PETSC_COMM_WORLD, ran, out);
    };
  }
  PetscCall(RunLevels(PETSC_COMM_WORLD, opt, companion, nullptr));
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
