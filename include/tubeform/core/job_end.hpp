// How an error ends the job: decided by the ranks agreeing on it, not by its
// error code. Every rank that leaves the run (with an error or without) says
// so in a non-blocking gather on a communicator of its own; when every rank
// answers, an error they all met is reported once, by rank 0, and every rank
// exits with 1. A rank whose error the others did not meet (they wait in a
// collective call it will never join, or compute on) finds them silent for
// kAgreeSeconds: it reports its error in one line and aborts the job.
#pragma once

#include <petscsys.h>

#include <functional>
#include <string>

namespace tf {

// How long a rank that left the run waits for the others. The ranks that meet
// one error leave the same collective call (the broadcast or reduction that
// made it every rank's) within milliseconds of each other, and only their
// clean-up lies between it and the end; ten seconds leave that a thousand
// times over on a loaded machine, and bound how long a job whose ranks
// disagree waits before it is aborted.
constexpr double kAgreeSeconds = 10;

// What the ranks said when they left the run (AgreeOnError).
struct ErrorVerdict {
  bool all_answered = true; // every rank answered within the time limit
  int failed = 0;           // ranks that left with an error
  int first = -1;           // the lowest of them (-1: none)
  PetscErrorCode code = 0;  // its error code
};

// Collective on `agree`, a communicator no other call uses (so that the gather
// cannot meet a collective call a rank left behind on the run's): every rank
// gives its error code (0: none) and waits at most `seconds` for the others'.
ErrorVerdict AgreeOnError(MPI_Comm agree, PetscErrorCode mine, double seconds);

// The one-line text of error `code` on this rank (PETSc's message for it).
std::string ErrorText(PetscErrorCode code);

// Runs `cleanup` (a destroy in a destructor, reached while an error unwinds)
// so that the run's error keeps its text: PETSc keeps the text of the last
// error raised, and a clean-up that fails too (a result file closed on a full
// disk) would otherwise replace the error the run stopped with by its own.
void KeepErrorText(const std::function<void()> &cleanup);

// The end of a job whose run returned `ierr` on this rank: agreed with the
// others (AgreeOnError), reported in one line on standard error, and the exit
// code returned (0 or 1); an error the other ranks did not answer aborts the
// job here (MPI_Abort, exit code 2). PetscFinalize is the caller's.
int EndJob(MPI_Comm agree, PetscErrorCode ierr, double seconds = kAgreeSeconds);

} // namespace tf
