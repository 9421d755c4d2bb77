#include "tubeform/driver/beside.hpp"

#include <ctime>
#include <string>
#include <vector>

#include "tubeform/assembly/linear_solver.hpp"
#include "tubeform/core/core.hpp"
#include "tubeform/core/job_end.hpp"
#include "tubeform/driver/companions.hpp"

namespace tf {

namespace {

// Messages between the run's first rank and the companions' (on a communicator of their own).
constexpr int kTagCompanions = 1, kTagLevel = 2;

// What follows a level, as the companions need it (plain data); or the run's error, which the companions' ranks
// then end with too (the job's error is one, said once).
struct LevelStep {
  int follows = 0, reuse = 0; // (reuse: the level's estimate is the run's own, Refinement::reuse)
  LevelChange change;
  PetscErrorCode run_failed = 0;
  char why[PETSC_MAX_PATH_LEN] = "";
};

// How a level's companions ended (an error code, 0: they ran), its text (their line, or why they failed), their
// histories: sent by the companions' first rank, received by the run's.
struct Outcome {
  PetscErrorCode failed = 0;
  std::string text;
  Companions companions;
};

// Waits for the n requests, looking every millisecond: the companions' first rank, whose runs end long before the
// run's level, waits so for the run to take them and say what follows, its core left to other jobs (a blocking MPI
// call would spin in MPI's progress loop for the rest of the level).
PetscErrorCode WaitIdle(int n, MPI_Request *requests)
{
  const timespec pause = {0, 1000000};
  PetscFunctionBeginUser;
  for (int done = 0;;) {
    PetscCallMPI(MPI_Testall(n, requests, &done, MPI_STATUSES_IGNORE));
    if (done) break;
    nanosleep(&pause, nullptr);
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Send(MPI_Comm link, int to, const Outcome &o)
{
  MPI_Request requests[4];
  int n = 0;
  PetscFunctionBeginUser;
  const double head[4] = {(double)o.failed, (double)o.companions.mesh.size(), (double)o.companions.steps.size(),
                          (double)o.text.size()};
  PetscCallMPI(MPI_Isend(head, 4, MPI_DOUBLE, to, kTagCompanions, link, &requests[n++]));
  if (!o.text.empty())
    PetscCallMPI(MPI_Isend(o.text.data(), (int)o.text.size(), MPI_CHAR, to, kTagCompanions, link, &requests[n++]));
  for (const auto *rows : {&o.companions.mesh, &o.companions.steps})
    if (!rows->empty())
      PetscCallMPI(MPI_Isend(rows->data(), RowDoubles(*rows), MPI_DOUBLE, to, kTagCompanions, link, &requests[n++]));
  PetscCall(WaitIdle(n, requests));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Receive(MPI_Comm link, int from, Outcome &o)
{
  double head[4];
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Recv(head, 4, MPI_DOUBLE, from, kTagCompanions, link, MPI_STATUS_IGNORE));
  o.failed = (PetscErrorCode)head[0];
  o.companions.mesh.resize((size_t)head[1]), o.companions.steps.resize((size_t)head[2]);
  o.text.assign((size_t)head[3], ' ');
  if (!o.text.empty())
    PetscCallMPI(MPI_Recv(o.text.data(), (int)o.text.size(), MPI_CHAR, from, kTagCompanions, link, MPI_STATUS_IGNORE));
  for (auto *rows : {&o.companions.mesh, &o.companions.steps})
    if (!rows->empty())
      PetscCallMPI(
        MPI_Recv(rows->data(), RowDoubles(*rows), MPI_DOUBLE, from, kTagCompanions, link, MPI_STATUS_IGNORE));
  PetscFunctionReturn(PETSC_SUCCESS);
}

// Collective on half: a level's companions, as the run would hand them over: the options of a set-up of the case
// of its own (the element and the friction regularization the run takes, into `own` as the run's
// Problem::OwnChoices: what a finer level starts from), then the two runs.
PetscErrorCode LevelCompanions(MPI_Comm half, const Options &level, Outcome &o, Options &own)
{
  Options ran;
  const Options quiet = CompanionQuiet(level);
  std::string why;
  PetscFunctionBeginUser;
  {
    Problem p;
    p.SetQuiet();
    o.failed = p.Setup(half, quiet);
    if (!o.failed) o.failed = p.CompanionOptions(ran);
    if (o.failed) why = ErrorText(o.failed);
  }
  if (!o.failed) own = ran;
  if (!o.failed) o.failed = RunCompanions(half, ran, o.companions, &o.text);
  if (o.failed && why.empty()) why = ErrorText(o.failed);
  if (o.failed) o.text = why, o.companions = Companions{};
  PetscFunctionReturn(PETSC_SUCCESS);
}

// Collective on half: a reused level's increments' part (AccuracyParams::steps_only), on the cells of the last
// level (`last`, its own choices), as the run would ask for it (main.cpp).
PetscErrorCode StepsOfLast(MPI_Comm half, const Options &last, Outcome &o)
{
  Options steps_only = last;
  PetscFunctionBeginUser;
  steps_only.accuracy.steps_only = true;
  o.failed = RunCompanions(half, steps_only, o.companions, &o.text);
  if (o.failed) o.text = ErrorText(o.failed), o.companions = Companions{};
  PetscFunctionReturn(PETSC_SUCCESS);
}

// Collective on half (the companions' ranks): level after level, the companions, sent to the run's first rank;
// then what follows, from it.
PetscErrorCode Serve(MPI_Comm half, MPI_Comm link, int run_root, Options level)
{
  PetscMPIInt rank;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(half, &rank));
  Options last; // the last level's own choices: a reused level's increments' part runs on its cells
  for (bool reuse = false;;) {
    Outcome o;
    Options own = level; // (a reused level's choices are the last one's)
    if (!reuse)
      PetscCall(LevelCompanions(half, level, o, own));
    else
      PetscCall(StepsOfLast(half, last, o));
    if (rank == 0) PetscCall(Send(link, run_root, o));
    LevelStep step;
    if (rank == 0) {
      MPI_Request request;
      PetscCallMPI(MPI_Irecv(&step, sizeof(step), MPI_BYTE, run_root, kTagLevel, link, &request));
      PetscCall(WaitIdle(1, &request));
    }
    PetscCallMPI(MPI_Bcast(&step, sizeof(step), MPI_BYTE, 0, half));
    PetscCheck(!step.run_failed, half, step.run_failed, "%s", step.why);
    if (!step.follows) break;
    last = own;
    level = step.change.Applied(own), reuse = step.reuse;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

// The run's side: its companion callback takes the level's outcome (on every rank of the run); what follows a
// level goes to the companions' first rank. A level that ends before it takes its outcome (an error, a stop) still
// receives it, so that the companions' send completes.
struct RunSide {
  MPI_Comm half = MPI_COMM_NULL, link = MPI_COMM_NULL;
  int companions_root = 0;
  PetscMPIInt rank = 0;
  bool taken = false; // this level's outcome received

  PetscErrorCode Take(Outcome &o)
  {
    double head[2];
    PetscFunctionBeginUser;
    taken = true;
    if (rank == 0) PetscCall(Receive(link, companions_root, o));
    head[0] = (double)o.failed, head[1] = (double)o.text.size();
    PetscCallMPI(MPI_Bcast(head, 2, MPI_DOUBLE, 0, half));
    o.failed = (PetscErrorCode)head[0];
    o.text.resize((size_t)head[1]);
    if (!o.text.empty()) PetscCallMPI(MPI_Bcast(o.text.data(), (int)o.text.size(), MPI_CHAR, 0, half));
    PetscCall(BroadcastRows(half, 0, o.companions.mesh));
    PetscCall(BroadcastRows(half, 0, o.companions.steps));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  PetscErrorCode Next(const Refinement &r, PetscErrorCode run_failed = 0)
  {
    PetscFunctionBeginUser;
    LevelStep step;
    step.follows = r.follows, step.reuse = r.reuse, step.change = r.change;
    if (run_failed) {
      step.run_failed = run_failed;
      PetscCall(PetscStrncpy(step.why, ErrorText(run_failed).c_str(), sizeof(step.why)));
    }
    if (!taken) {
      Outcome unused;
      PetscCall(Take(unused));
    }
    if (rank == 0) PetscCallMPI(MPI_Send(&step, sizeof(step), MPI_BYTE, companions_root, kTagLevel, link));
    taken = false;
    PetscFunctionReturn(PETSC_SUCCESS);
  }
};

} // namespace

bool CompanionsBeside(const Options &opt, PetscMPIInt size)
{
  const double dofs = 2.0 * (opt.mesh_nt + 1) * (opt.mesh_ntheta + 1); // (a generated mesh's; a file's is not known)
  return size >= 2 && opt.restart.empty() && opt.checkpoint.empty() && opt.mesh_file.empty() &&
         dofs <= kDistributedDofs;
}

PetscErrorCode RunBeside(MPI_Comm world, const Options &opt, const LevelRunner &levels)
{
  PetscMPIInt rank, size;
  MPI_Comm half, link;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(world, &rank));
  PetscCallMPI(MPI_Comm_size(world, &size));
  const int companions_root = size / 2, color = rank < companions_root ? 0 : 1;
  PetscCallMPI(MPI_Comm_split(world, color, rank, &half));
  PetscCallMPI(MPI_Comm_dup(world, &link));
  PetscErrorCode failed = 0;
  if (color == 1) {
    failed = Serve(half, link, 0, opt);
  } else {
    RunSide side{half, link, companions_root};
    PetscCallMPI(MPI_Comm_rank(half, &side.rank));
    const Problem::CompanionRun companion = [&side](const Options &, Companions &out) {
      Outcome o;
      PetscFunctionBeginUser;
      PetscCall(side.Take(o));
      PetscCheck(!o.failed, side.half, o.failed, "%s", o.text.c_str());
      out = std::move(o.companions);
      PetscCall(PetscPrintf(side.half, "tubeform: %s, beside the run\n", o.text.c_str()));
      PetscFunctionReturn(PETSC_SUCCESS);
    };
    const LevelHook after = [&side](const Refinement &next) { return side.Next(next); };
    failed = levels(half, opt, companion, after);
    // (a level that failed or stopped: the companions are told, and end with its error)
    if (failed) (void)side.Next(Refinement(), failed);
  }
  PetscCallMPI(MPI_Comm_free(&link));
  PetscCallMPI(MPI_Comm_free(&half));
  PetscFunctionReturn(failed);
}

} // namespace tf
