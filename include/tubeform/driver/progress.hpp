#pragma once

#include <cmath>
#include <cstdio>
#include <functional>
#include <utility>
#include <vector>

#include <petscsys.h>

namespace tf {

// The -progress line: every `interval` seconds of wall time, rank 0 prints
// where the load path is (stage, percent of it, the scene's stroke), the
// increments so far and the time left in the stage at the stage's mean rate
// so far (the springback costs far less per unit of the path than the loading).
// A path of more than two stages (two passes) names the stage's number too.
// Quiet on runs shorter than one interval; -monitor prints every increment.
class Progress {
public:
  // `bounds`: lambda at the stages' ends, from 0 to the path's end (0, the
  // breakpoints, end); `unloading`: whether the stage starting at a lambda
  // unloads (the scene's); `from`: where this run starts (a restart's
  // lambda), the origin of its rate.
  Progress(MPI_Comm comm, double interval, std::vector<double> bounds, std::function<bool(double)> unloading,
           double from = 0)
      : comm_(comm), interval_(interval), bounds_(std::move(bounds)), unloading_(std::move(unloading)), from_(from),
        start_(MPI_Wtime()), next_(start_ + interval)
  {}

  // After an increment: prints if an interval has passed (rank 0 only; no communication).
  PetscErrorCode Update(double lambda, PetscInt inc, double stroke)
  {
    PetscMPIInt rank;
    PetscFunctionBeginUser;
    if (interval_ <= 0) PetscFunctionReturn(PETSC_SUCCESS);
    PetscCallMPI(MPI_Comm_rank(comm_, &rank));
    const double now = MPI_Wtime();
    int k = 0; // the stage: lambda in [bounds k, bounds k+1) (the last one closed)
    while (k + 2 < (int)bounds_.size() && lambda >= bounds_[k + 1]) ++k;
    if (stage_ < 0) stage_ = k; // the stage this run starts in: its rate from the run's start
    if (k != stage_) stage_ = k, stage_start_ = now, stage_lambda_ = lambda;
    if (rank != 0 || now < next_) PetscFunctionReturn(PETSC_SUCCESS);
    next_ = now + interval_;
    const double stage0 = bounds_[k], stage1 = bounds_[k + 1];
    const double t0 = stage_start_ < 0 ? start_ : stage_start_, l0 = stage_start_ < 0 ? from_ : stage_lambda_;
    const double pct = 100.0 * (lambda - stage0) / (stage1 - stage0);
    const double left = lambda > l0 ? (now - t0) * (stage1 - lambda) / (lambda - l0) : NAN;
    const char *what = unloading_(stage0) ? "unloading" : "loading";
    char stage[64] = "";
    if (bounds_.size() > 3) std::snprintf(stage, sizeof(stage), " (stage %d of %d)", k + 1, (int)bounds_.size() - 1);
    PetscCall(PetscPrintf(
      PETSC_COMM_SELF, "tubeform: %s%s %3.0f %% (stroke %.4g), %d increments, %.0f s so far, ~%.0f s left in the %s\n",
      what, stage, pct, stroke, (int)inc, now - start_, left, what));
    PetscFunctionReturn(PETSC_SUCCESS);
  }

private:
  MPI_Comm comm_;
  double interval_;
  std::vector<double> bounds_;
  std::function<bool(double)> unloading_;
  double from_, start_, next_;
  int stage_ = -1;
  double stage_start_ = -1, stage_lambda_ = 0; // when and where the stage under way began (-1: with the run)
};

} // namespace tf
