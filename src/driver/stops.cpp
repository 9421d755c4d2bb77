// Why a run ends before the end of its load path, in one place: the checks
// Problem::Run makes before an increment (a stall, the increment budget, the
// clock, a stop signal), after a failed one, and after a committed one (a
// number that overflowed, an energy balance that diverged, friction that does
// not settle), and the checkpoint a stop or a schedule writes. Each stop is a
// one-line reason and an exit code, reported once the results so far are
// written (Problem::Finish).
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <cstring>

#include "tubeform/core/signals.hpp"
#include "tubeform/driver/problem.hpp"
#include "tubeform/metrics/crossing.hpp"

namespace tf {

namespace {
// printf into a string (the run's one-line messages).
std::string Format(const char *fmt, ...)
{
  char buf[512];
  va_list args;
  va_start(args, fmt);
  std::vsnprintf(buf, sizeof(buf), fmt, args);
  va_end(args);
  return buf;
}
} // namespace

std::string Problem::Where() const
{
  return Format("stroke %g, lambda %.6g, after %d increments", history_.rows().back().stroke, at_.lambda, (int)at_.inc);
}

PetscErrorCode Problem::Checkpoint(ResultWriter &writer, const OutputSchedule &output, Stop &stop)
{
  PetscFunctionBeginUser;
  // A checkpoint that cannot be written (its scratch file, too little room, a
  // failed HDF5 write: found on every rank) ends the run like a failed
  // increment: results written, the earlier checkpoint kept.
  const PetscErrorCode failed = WriteCheckpoint(writer, output);
  if (failed == PETSC_ERR_FILE_WRITE) {
    const char *specific = nullptr;
    PetscCall(PetscErrorMessage(failed, nullptr, (char **)&specific));
    stop.code = failed;
    stop.why = Format("%s (%s)", specific ? specific : "the checkpoint could not be written", Where().c_str());
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  PetscCall(failed);
  stop.checkpointed = true;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Problem::StopBefore(ResultWriter &writer, const OutputSchedule &output, double t_start, Stop &stop)
{
  PetscFunctionBeginUser;
  // The stall watch ends a load path that no longer advances.
  if (at_.inc - at_.inc_mark >= opt_.driver.rmin_stall_increments) {
    if (at_.lambda - at_.lambda_mark < kStallAdvance) {
      stop.stalled = true, stop.code = PETSC_ERR_NOT_CONVERGED;
      stop.why = Format("the load path stalled (%s): %d increments (-rmin_stall_increments) advanced lambda by less "
                        "than %g; the history column limiter names what cut them (docs/theory.md, \"Stalls\")",
                        Where().c_str(), (int)opt_.driver.rmin_stall_increments, kStallAdvance);
      PetscFunctionReturn(PETSC_SUCCESS);
    }
    at_.lambda_mark = at_.lambda, at_.inc_mark = at_.inc;
  }
  // ... and so does the increment budget (results up to here are written).
  if (at_.inc == opt_.driver.rmin_max_increments) {
    stop.code = PETSC_ERR_NOT_CONVERGED;
    stop.why = Format("the load path needs more than -rmin_max_increments %d increments (%s); raise "
                      "-rmin_max_increments or relax -rmin_deps / -rmin_domega",
                      (int)opt_.driver.rmin_max_increments, Where().c_str());
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  // ... and the clock (-time_limit) and stop signals (rank 0 may be the only
  // one to see either: clocks differ, a signal may reach one process); both
  // leave a checkpoint to continue from.
  // A write of the history CSV that failed (rank 0's) ends the run at once:
  // nothing is renamed into place (a full disk: the HDF5 file cannot be
  // finished either), the earlier results stay whole.
  int mine[3] = {opt_.time_limit > 0 && MPI_Wtime() - t_start > opt_.time_limit, StopSignal(), history_.CsvError()},
      any[3];
  PetscCallMPI(MPI_Allreduce(mine, any, 3, MPI_INT, MPI_MAX, comm_));
  if (any[2] && rank_ == 0) history_.DropCsv();
  PetscCheck(!any[2], comm_, PETSC_ERR_FILE_WRITE,
             "-history_csv %s: writing %s.partial failed (%s; %s); it is removed, nothing is renamed into place "
             "(the results so far stay in %s.partial)",
             opt_.history_csv.c_str(), opt_.history_csv.c_str(), std::strerror(any[2]), Where().c_str(),
             opt_.output.c_str());
  if (any[1]) {
    stop.signal = any[1], stop.code = PETSC_ERR_SIG;
    stop.why = Format("interrupted by %s (%s)", SignalName(any[1]), Where().c_str());
  } else if (any[0]) {
    stop.code = PETSC_ERR_NOT_CONVERGED;
    stop.why = Format("-time_limit %g s reached (%s)", opt_.time_limit, Where().c_str());
  }
  if (!stop.why.empty() && !opt_.checkpoint.empty()) {
    PetscCall(Checkpoint(writer, output, stop)); // a failure replaces the stop's message with its own
    if (stop.checkpointed)
      PetscCall(PetscPrintf(comm_, "tubeform: checkpoint after increment %d in %s; continue with -restart %s\n",
                            (int)at_.inc, opt_.checkpoint.c_str(), opt_.checkpoint.c_str()));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Problem::StopOnFailure(PetscErrorCode failed, Stop &stop)
{
  PetscFunctionBeginUser;
  if (failed == PETSC_ERR_SIG) {
    // A stop signal the ranks agreed on inside the increment (Controller::Solve): it is dropped.
    int mine = StopSignal(), any;
    PetscCallMPI(MPI_Allreduce(&mine, &any, 1, MPI_INT, MPI_MAX, comm_));
    --at_.inc;
    stop.signal = any, stop.code = failed;
    stop.why = Format("interrupted by %s (%s; the increment in progress dropped)", SignalName(any), Where().c_str());
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  if (failed == PETSC_ERR_USER_INPUT || failed == PETSC_ERR_NOT_CONVERGED) {
    const char *specific = nullptr;
    PetscCall(PetscErrorMessage(failed, nullptr, (char **)&specific));
    --at_.inc;
    stop.code = failed;
    stop.why = Format("%s (%s)", specific ? specific : "the increment failed", Where().c_str());
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  PetscCall(failed);
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Problem::StopAfter(Stop &stop, bool &wrote_last)
{
  PetscFunctionBeginUser;
  if (!nonfinite_.empty()) {
    PetscInt cell = -1;
    PetscCall(body_.NonFiniteCell(cell));
    const std::string at = cell >= 0 ? Format(", first in element %d", (int)cell) : "";
    stop.code = PETSC_ERR_NOT_CONVERGED, wrote_last = true; // the last fields written are the last finite ones
    stop.why = Format("increment %d gave %s = NaN or Inf%s: the numbers overflowed (units? -material_E is in MPa); "
                      "it is not written (%s)",
                      (int)at_.inc, nonfinite_.c_str(), at.c_str(), Where().c_str());
  } else if (diverged_) {
    stop.code = PETSC_ERR_NOT_CONVERGED, wrote_last = false;
    stop.why =
      Format("the energy balance error %.1f %% passed -max_energy_error %g: the solution has left "
             "equilibrium (shorter steps: more -increments, a smaller -rmin_deps; docs/accuracy.md, \"Extremes\") "
             "(%s)",
             100 * history_.rows().back().energy_error, opt_.driver.max_energy_error, Where().c_str());
  } else if (unsettled_run_ >= opt_.driver.friction_max_unsettled * kDeepPerUnsettled) {
    stop.code = PETSC_ERR_NOT_CONVERGED, wrote_last = false;
    const bool balance = opt_.driver.equilibrium_tol > 0; // the equilibrium iterations carry the friction's
    const bool inertia = inertia_ && inertia_->active();
    const std::string shorter =
      inertia ? Format(" (and with inertia up to %d times, %d steps settled only so counting as one)", kMaxCutsInertia,
                       kDeepPerUnsettled)
              : "";
    stop.why =
      Format("the %s iterations did not settle in %d increments in a row (-friction_max_unsettled), "
             "even on steps halved %d times%s: raise -friction_max_iters or %s%s (%s)",
             balance ? "equilibrium" : "friction", (int)(unsettled_run_ / kDeepPerUnsettled), kMaxCuts, shorter.c_str(),
             balance ? "-equilibrium_tol" : "-friction_tol", inertia ? "" : ", or try -dynamics auto", Where().c_str());
  }
  if (stop.why.empty() && contact_) {
    PetscCall(StopOnCrossing(stop));
    if (!stop.why.empty()) wrote_last = false; // (the state that crossed is written)
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Problem::StopOnCrossing(Stop &stop)
{
  PetscFunctionBeginUser;
  PlaneCrossing p;
  PetscCall(contact_->Crossing(p));
  if (p.depth > p.tol) {
    // A symmetry wall by its plane, a tool by its name.
    const auto name = [&](int k) {
      if (k < contact_->num_tools()) return "the " + contact_->tool(k).name;
      const Vec2 n = contact_->tool(k).segments[0].n_line;
      return std::string(std::abs(n[0]) > std::abs(n[1]) ? "its symmetry plane x = 0" : "its symmetry plane y = 0");
    };
    stop.code = PETSC_ERR_NOT_CONVERGED;
    const std::string at =
      Format("the tube's wall lies %.3g mm beyond %s at (%.4g, %.4g)", p.depth, name(p.tool).c_str(), p.x[0], p.x[1]);
    if (p.held >= 0)
      stop.why = Format("%s, where it touches %s: a node touches one tool or symmetry plane at a time, and the wall is "
                        "pinched between them there (%s)",
                        at.c_str(), name(p.held).c_str(), Where().c_str());
    else
      stop.why = Format("%s, which it does not touch (%s)", at.c_str(), Where().c_str());
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  SelfCrossing c;
  PetscCall(SurfaceSelfCrossing(mesh_, body_.position(), contact_->surfaces(), c));
  if (!c.found) PetscFunctionReturn(PETSC_SUCCESS);
  stop.code = PETSC_ERR_NOT_CONVERGED;
  stop.why = Format("the tube's wall meets itself at (%.4g, %.4g) (its surface between nodes %ld and %ld crosses "
                    "that between %ld and %ld), which the solver does not model as contact (%s)",
                    c.at[0], c.at[1], c.nodes[0], c.nodes[1], c.nodes[2], c.nodes[3], Where().c_str());
  PetscFunctionReturn(PETSC_SUCCESS);
}

} // namespace tf
