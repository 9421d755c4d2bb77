// The error estimate's companion runs, once the run's results are final: its
// ranks agree on how it ended (a rank-local error the others did not meet
// aborts the job, the results being in place already); an error means no
// estimate and one line why; a stop signal ends the job as asked.
#include <cstdio>
#include <string>

#include "tubeform/core/job_end.hpp"
#include "tubeform/core/signals.hpp"
#include "tubeform/driver/problem.hpp"

namespace tf {

namespace {

// The options a run's companions take: the run's, with what it chose for itself kept, its element and its
// friction regularization (`vcri`; 0: no tools).
Options Kept(const Options &opt, double vcri)
{
  Options ran = opt;
  ran.element_auto = false;
  if (vcri > 0) ran.friction.vcri = vcri;
  return ran;
}

} // namespace

PetscErrorCode Problem::CompanionOptions(Options &ran)
{
  ContactSpec tools;
  PetscFunctionBeginUser;
  // (after Run the contact set holds the tools; Estimate reads it)
  PetscCheck(!contact_, comm_, PETSC_ERR_ORDER, "Problem::CompanionOptions: before Run only");
  PetscCall(scene_->Initialize(*model_, tools));
  ran = Kept(opt_, tools.candidates.empty() ? 0 : tools.params.vcri);
  PetscFunctionReturn(PETSC_SUCCESS);
}

Options Problem::OwnChoices() const { return Kept(opt_, contact_ ? contact_->params().vcri : 0); }

PetscErrorCode Problem::Estimate(Companions &companions, Stop &stop)
{
  MPI_Comm agree; // (a communicator of its own: a rank that failed alone cannot meet the others' calls)
  char text[PETSC_MAX_PATH_LEN] = "";
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_dup(comm_, &agree));
  const Options ran = OwnChoices();
  const PetscErrorCode failed = companion_run_(ran, companions);
  const ErrorVerdict v = AgreeOnError(agree, failed, kAgreeSeconds);
  if (!v.all_answered) {
    std::fprintf(stderr,
                 "tubeform: error on rank %d: %s (in the companion run of the error estimate; the other ranks did not "
                 "stop with it within %g s: the job is aborted; the results in %s are complete, without the "
                 "estimate)\n",
                 (int)rank_, ErrorText(failed).c_str(), kAgreeSeconds, opt_.output.c_str());
    std::fflush(stderr);
    MPI_Abort(MPI_COMM_WORLD, 2);
  }
  if (v.failed && rank_ == v.first) PetscCall(PetscStrncpy(text, ErrorText(failed).c_str(), sizeof(text)));
  if (v.failed) PetscCallMPI(MPI_Bcast(text, sizeof(text), MPI_CHAR, v.first, agree));
  PetscCallMPI(MPI_Comm_free(&agree));
  if (!v.failed) PetscFunctionReturn(PETSC_SUCCESS);
  companions = Companions{};
  if (v.code == PETSC_ERR_SIG) {
    int mine = StopSignal(), any;
    PetscCallMPI(MPI_Allreduce(&mine, &any, 1, MPI_INT, MPI_MAX, comm_));
    stop.signal = any, stop.code = PETSC_ERR_SIG, stop.after_end = true;
    stop.why = std::string("interrupted by ") + SignalName(any) +
               " during the companion run of the error estimate: the run had reached its end, its results in " +
               opt_.output + " are complete, without an estimate";
  } else {
    PetscCall(PetscPrintf(comm_, "tubeform: no error estimate: its companion run failed (%s)\n", text));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

} // namespace tf
