#pragma once

#include <cmath>

#include <petscsys.h>

namespace tf {

// The -progress line: every `interval` seconds of wall time, rank 0 prints
// where the load path is (stage, percent of it, the scene's stroke), the
// increments so far and the time left in the stage at the stage's mean rate
// so far (the springback costs far less per unit of the path than the loading).
// Quiet on runs shorter than one interval; -monitor prints every increment.
class Progress {
public:
  // `end`: lambda at the end of the load path; `loading_end`: where the
  // loading ends (1; the path may go on with the springback); `from`: where
  // this run starts (a restart's lambda), the origin of its rate.
  Progress(MPI_Comm comm, double interval, double end, double loading_end, double from = 0)
      : comm_(comm), interval_(interval), end_(end), loading_end_(loading_end), from_(from), start_(MPI_Wtime()),
        next_(start_ + interval)
  {}

  // After an increment: prints if an interval has passed (rank 0 only; no communication).
  PetscErrorCode Update(double lambda, PetscInt inc, double stroke)
  {
    PetscMPIInt rank;
    PetscFunctionBeginUser;
    if (interval_ <= 0) PetscFunctionReturn(PETSC_SUCCESS);
    PetscCallMPI(MPI_Comm_rank(comm_, &rank));
    const double now = MPI_Wtime();
    const bool loading = lambda < loading_end_;
    if (!loading && stage_start_ < 0) stage_start_ = now, stage_lambda_ = lambda;
    if (rank != 0 || now < next_) PetscFunctionReturn(PETSC_SUCCESS);
    next_ = now + interval_;
    const double stage0 = loading ? 0.0 : loading_end_, stage1 = loading ? loading_end_ : end_;
    const double t0 = loading ? start_ : stage_start_, l0 = loading ? from_ : stage_lambda_;
    const double pct = 100.0 * (lambda - stage0) / (stage1 - stage0);
    const double left = lambda > l0 ? (now - t0) * (stage1 - lambda) / (lambda - l0) : NAN;
    PetscCall(PetscPrintf(
      PETSC_COMM_SELF, "tubeform: %s %3.0f %% (stroke %.4g), %d increments, %.0f s so far, ~%.0f s left in the %s\n",
      loading ? "loading" : "unloading", pct, stroke, (int)inc, now - start_, left, loading ? "loading" : "unloading"));
    PetscFunctionReturn(PETSC_SUCCESS);
  }

private:
  MPI_Comm comm_;
  double interval_, end_, loading_end_, from_, start_, next_;
  double stage_start_ = -1, stage_lambda_ = 0; // when and where the unloading began
};

} // namespace tf
