#include "tubeform/driver/companions.hpp"

#include <algorithm>
#include <limits>
#include <string>

#include "tubeform/core/core.hpp"
#include "tubeform/core/job_end.hpp"
#include "tubeform/io/options_left.hpp"

namespace tf {

namespace {

// One companion run on comm: its history in `rows`, its wall time in `seconds`.
PetscErrorCode RunCompanion(MPI_Comm comm, const Options &c, std::vector<HistoryRow> &rows, double &seconds)
{
  PetscFunctionBeginUser;
  const double t0 = MPI_Wtime();
  PetscCall(RunOnce(comm, c, true, nullptr, &rows));
  seconds = MPI_Wtime() - t0;
  PetscFunctionReturn(PETSC_SUCCESS);
}

// Collective on comm: `rows` and `seconds` of rank `root` on every rank.
PetscErrorCode Share(MPI_Comm comm, int root, std::vector<HistoryRow> &rows, double &seconds)
{
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Bcast(&seconds, 1, MPI_DOUBLE, root, comm));
  PetscCall(BroadcastRows(comm, root, rows));
  PetscFunctionReturn(PETSC_SUCCESS);
}

// Collective on comm (2 ranks or more): the two companions side by side, `mesh` on the first half of the ranks,
// `steps` on the second; each half's error comes back on its own ranks, the others' histories then being empty.
PetscErrorCode SideBySide(MPI_Comm comm, const Options &mesh, const Options &steps, Companions &out, double *seconds)
{
  PetscMPIInt rank, size;
  MPI_Comm half;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCallMPI(MPI_Comm_size(comm, &size));
  const int color = rank < size / 2 ? 0 : 1, second_root = size / 2;
  PetscCallMPI(MPI_Comm_split(comm, color, rank, &half));
  const PetscErrorCode failed =
    color == 0 ? RunCompanion(half, mesh, out.mesh, seconds[0]) : RunCompanion(half, steps, out.steps, seconds[1]);
  const std::string why = failed ? ErrorText(failed) : "";
  PetscCallMPI(MPI_Comm_free(&half));
  int ok = !failed, all = 0;
  PetscCallMPI(MPI_Allreduce(&ok, &all, 1, MPI_INT, MPI_MIN, comm));
  PetscCheck(!failed, PETSC_COMM_SELF, failed, "%s", why.c_str());
  if (!all) { // (the other half's error: it says it; these ranks' histories go unused)
    out = Companions{};
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  PetscCall(Share(comm, 0, out.mesh, seconds[0]));
  PetscCall(Share(comm, second_root, out.steps, seconds[1]));
  PetscFunctionReturn(PETSC_SUCCESS);
}

// `c` at twice the increment limits of `ran` and half its trial increments.
Options AtTwiceTheLimits(const Options &c, const Options &ran)
{
  Options steps = c;
  steps.driver.increments = std::max<PetscInt>(1, ran.driver.increments / 2);
  steps.driver.rmin_deps = 2 * ran.driver.rmin_deps, steps.driver.rmin_deps_yield = 2 * ran.driver.rmin_deps_yield;
  steps.driver.rmin_domega = 2 * ran.driver.rmin_domega;
  return steps;
}

// Collective on comm: the increments' part alone (AccuracyParams::steps_only), on the cells of `ran` (a level that the
// next takes as its mesh companion), factored as that level is (the companions' own factorization is chosen for a
// quarter of a run's cells).
PetscErrorCode RunStepsAlone(MPI_Comm comm, const Options &ran, Companions &out, std::string *line)
{
  double seconds = 0;
  PetscFunctionBeginUser;
  out = Companions{};
  PetscCall(RunCompanion(comm, AtTwiceTheLimits(CompanionQuiet(ran), ran), out.steps, seconds));
  const std::string said =
    Formatted("companion run for the error estimate's increments part: level %d's %d x %d cells at twice its "
              "increment limits (%.1f s)",
              (int)ran.level, (int)ran.mesh_nt, (int)ran.mesh_ntheta, seconds);
  if (line)
    *line = said;
  else
    PetscCall(PetscPrintf(comm, "tubeform: %s\n", said.c_str()));
  PetscFunctionReturn(PETSC_SUCCESS);
}

} // namespace

Options CompanionQuiet(const Options &ran)
{
  Options c = ran;
  c.output.clear(), c.history_csv.clear(); // no files: nothing of it is left behind, whatever ends it
  c.checkpoint.clear(), c.restart.clear();
  c.checkpoint_every = 0;
  c.progress = 0, c.monitor = PETSC_FALSE;
  c.output_every = std::numeric_limits<int>::max(), c.output_stroke = 0;
  c.accuracy.error_estimate = PETSC_FALSE;
  c.accuracy.target_load = c.accuracy.target_c_over_t = 0;
  c.accuracy.steps_only = false;
  return c;
}

PetscErrorCode BroadcastRows(MPI_Comm comm, int root, std::vector<HistoryRow> &rows)
{
  double n = (double)rows.size();
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Bcast(&n, 1, MPI_DOUBLE, root, comm));
  rows.resize((size_t)n);
  if (!rows.empty()) PetscCallMPI(MPI_Bcast(rows.data(), RowDoubles(rows), MPI_DOUBLE, root, comm));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode RunOnce(MPI_Comm comm, const Options &opt, bool quiet, const Problem::CompanionRun &companion,
                       std::vector<HistoryRow> *rows, Refinement *refinement)
{
  std::string why;
  PetscErrorCode failed;
  PetscFunctionBeginUser;
  {
    Problem problem;
    if (quiet) problem.SetQuiet();
    failed = problem.Setup(comm, opt);
    // (the run's options nothing reads: an error before anything is written)
    if (!failed && !quiet) failed = CheckOptionsLeft(comm, opt, problem.system().ndofs(), problem.system().redundant());
    if (!failed && companion) problem.SetCompanion(companion);
    if (!failed) failed = problem.Run();
    if (failed) why = ErrorText(failed);
    if (!failed && rows) *rows = problem.history().rows();
    if (!failed && refinement) *refinement = problem.refinement();
  }
  PetscCheck(!failed, PETSC_COMM_SELF, failed, "%s", why.c_str());
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode RunCompanions(MPI_Comm comm, const Options &ran, Companions &out, std::string *line)
{
  if (ran.accuracy.steps_only) return RunStepsAlone(comm, ran, out, line);
  Options mesh = CompanionQuiet(ran);
  // (a quarter of the run's cells: MUMPS's per-call cost dominates)
  mesh.driver.factorization = ran.accuracy.estimate_factorization;
  double seconds[2] = {0, 0};
  PetscMPIInt size;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_size(comm, &size));
  const bool coarsen = ran.mesh_file.empty();
  if (coarsen) {
    mesh.mesh_nt = CompanionNt(ran.mesh_nt);
    mesh.mesh_ntheta = std::max<PetscInt>(4, 2 * (ran.mesh_ntheta / 4));
  }
  const Options steps = AtTwiceTheLimits(mesh, ran);
  if (coarsen && size >= 2) {
    PetscCall(SideBySide(comm, mesh, steps, out, seconds));
    if (!out.Ran()) PetscFunctionReturn(PETSC_SUCCESS);
  } else {
    if (coarsen) PetscCall(RunCompanion(comm, mesh, out.mesh, seconds[0]));
    PetscCall(RunCompanion(comm, steps, out.steps, seconds[1]));
  }
  const std::string cells =
    coarsen ? Formatted("%d x %d cells at the run's increments (%.1f s), and there at twice their limits",
                        (int)mesh.mesh_nt, (int)mesh.mesh_ntheta, seconds[0])
            : std::string("the mesh file's cells at twice the run's increment limits");
  const std::string said = Formatted("companion runs for the error estimate: %s (%.1f s)%s", cells.c_str(), seconds[1],
                                     coarsen && size >= 2 ? ", side by side" : "");
  if (line)
    *line = said;
  else
    PetscCall(PetscPrintf(comm, "tubeform: %s\n", said.c_str()));
  PetscFunctionReturn(PETSC_SUCCESS);
}

} // namespace tf
