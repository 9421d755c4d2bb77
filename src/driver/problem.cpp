#include "tubeform/driver/problem.hpp"

#include <algorithm>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <string>

#include "tubeform/core/log.hpp"
#include "tubeform/core/signals.hpp"
#include "tubeform/driver/output_schedule.hpp"
#include "tubeform/driver/progress.hpp"
#include "tubeform/scenes/registry.hpp"

namespace tf {

namespace {
// A step ending this close to a breakpoint (in trial steps) ends on it.
constexpr double kSnapToBreak = 1e-9;

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

BodyParams MakeBodyParams(const Options &opt)
{
  BodyParams b;
  b.element = opt.element;
  b.material = opt.material;
  b.rmin_deps = opt.rmin_deps;
  b.rmin_deps_yield = opt.rmin_deps_yield;
  b.rmin_domega = opt.rmin_domega;
  b.group_tol = opt.rmin_group_tol;
  b.yield_inside = opt.rmin_yield == "inside";
  b.yield_tol = opt.rmin_yield_tol;
  b.drift_correction = opt.drift_correction;
  b.state_from_strain = opt.equilibrium_tol > 0;
  b.kinematics = opt.kinematics;
  return b;
}
} // namespace

Problem::~Problem() { (void)DestroyForces(); }

PetscErrorCode Problem::Setup(MPI_Comm comm, const Options &opt)
{
  PetscFunctionBeginUser;
  auto scene = CreateScene(opt);
  if (!scene) {
    std::string names;
    for (const auto &n : SceneNames()) names += (names.empty() ? "" : ", ") + n;
    SETERRQ(comm, PETSC_ERR_USER_INPUT, "-scene %s: unknown scene (available: %s)", opt.scene.c_str(), names.c_str());
  }
  PetscCall(Setup(comm, opt, std::move(scene)));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Problem::Setup(MPI_Comm comm, const Options &opt, std::unique_ptr<Scene> scene)
{
  SerialMesh serial;
  char why[PETSC_MAX_PATH_LEN] = "";

  PetscFunctionBeginUser;
  comm_ = comm;
  opt_ = opt;
  scene_ = std::move(scene);
  PetscCallMPI(MPI_Comm_rank(comm, &rank_));
  PetscCallMPI(MPI_Comm_size(comm, &size_));
  PetscCall(Log::Register());
  PetscCall(PetscLogStagePush(Log::setup_stage));

  // 1. The serial mesh on rank 0; its verdict is shared so all ranks stop together.
  PetscCall(PetscLogEventBegin(Log::mesh, 0, 0, 0, 0));
  if (rank_ == 0) {
    std::string err = scene_->BuildMesh(opt, serial);
    if (err.empty()) err = serial.validate(scene_->BoundarySets());
    if (!err.empty() && !opt.mesh_file.empty() && err.find(opt.mesh_file) == std::string::npos)
      err = "-mesh_file " + opt.mesh_file + ": " + err;
    PetscCall(PetscStrncpy(why, err.c_str(), sizeof(why)));
  }
  PetscCallMPI(MPI_Bcast(why, sizeof(why), MPI_CHAR, 0, comm));
  PetscCheck(why[0] == 0, comm, PETSC_ERR_USER_INPUT, "%s", why);
  int ncells = serial.num_cells();
  PetscCallMPI(MPI_Bcast(&ncells, 1, MPI_INT, 0, comm));
  PetscCheck(ncells >= size_, comm, PETSC_ERR_USER_INPUT,
             "the mesh has %d cells, fewer than the %d MPI ranks: refine it or run on fewer ranks", ncells, (int)size_);

  // 2. Partition and distribute; the global system, the body, inertia.
  PetscCall(mesh_.Create(comm, serial, scene_->BoundarySets()));
  PetscCall(PetscLogEventEnd(Log::mesh, 0, 0, 0, 0));
  PetscCall(system_.Setup(mesh_));
  if (size_ > 1 || opt_.monitor)
    PetscCall(PetscPrintf(comm_, "tubeform: linear solver: %s\n", system_.solver().c_str()));
  PetscCall(body_.Setup(mesh_, MakeBodyParams(opt_)));
  if (opt_.dynamics != Dynamics::Quasistatic) {
    inertia_ = std::make_unique<Inertia>();
    PetscCall(inertia_->Setup(body_, opt_.material.density, opt_.dynamics == Dynamics::Implicit));
  }
  model_ = std::make_unique<Model>(Model{comm_, mesh_, system_, body_, nullptr});
  path_ = scene_->Path(opt_);
  PetscCall(PetscLogStagePop());
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Problem::CreateForces(Vec like)
{
  PetscFunctionBeginUser;
  for (Vec *v : {&forces_.f_app, &forces_.f_app0, &forces_.f_ext, &forces_.f_ext0, &forces_.f_int, &forces_.f_int0,
                 &forces_.f_res, &forces_.f_net, &forces_.f_start})
    PetscCall(VecDuplicate(like, v));
  PetscCall(VecZeroEntries(forces_.f_res));
  PetscCall(VecZeroEntries(forces_.f_start));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Problem::DestroyForces()
{
  PetscFunctionBeginUser;
  for (Vec *v : {&forces_.f_app, &forces_.f_app0, &forces_.f_ext, &forces_.f_ext0, &forces_.f_int, &forces_.f_int0,
                 &forces_.f_res, &forces_.f_net, &forces_.f_start})
    PetscCall(VecDestroy(v));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Problem::Run()
{
  ResultWriter writer;
  Vec du;
  HistoryRow row;

  PetscFunctionBeginUser;
  // 0. Outputs are checked before any work, so a bad path fails at once; the
  // tools the scene asks for are set up (and refused if they start inside the
  // body) before the result file is opened, so such a start leaves no file.
  if (!opt_.history_csv.empty()) PetscCall(CheckWritable(comm_, opt_.history_csv, "-history_csv"));
  PetscCall(CheckWritable(comm_, opt_.output, "-output"));
  if (!opt_.checkpoint.empty()) PetscCall(CheckWritable(comm_, opt_.checkpoint, "-checkpoint"));
  ContactSpec tools;
  PetscCall(scene_->Initialize(*model_, tools));
  if (!tools.candidates.empty()) {
    contact_ = std::make_unique<ContactSet>();
    contact_->Setup(mesh_, system_, body_.position(), std::move(tools));
    contact_->SetCarryResidual(opt_.equilibrium_tol > 0);
    PetscCall(contact_->Initialize());
    model_->contact = contact_.get();
  }
  if (opt_.restart.empty()) PetscCall(writer.Open(mesh_, opt_.output));
  {
    int ok = history_.OpenCsv(opt_.history_csv, rank_);
    PetscCallMPI(MPI_Bcast(&ok, 1, MPI_INT, 0, comm_));
    PetscCheck(ok, comm_, PETSC_ERR_USER_INPUT,
               "-history_csv %s: cannot create the file (does the directory exist and is it writable?)",
               opt_.history_csv.c_str());
  }
  du = system_.CreateLocalVector();
  PetscCall(CreateForces(du));

  const double end = path_.end;
  std::vector<double> breaks = path_.breakpoints;
  breaks.push_back(end);
  at_.started.assign(breaks.size(), 0);
  OutputSchedule output(opt_.output_every, opt_.output_stroke > 0 ? opt_.output_stroke / opt_.stroke : 0);
  if (!opt_.restart.empty()) {
    // A restart: the state, the history and the results so far from the checkpoint.
    PetscCall(ReadCheckpoint(writer, output));
  } else {
    // Increment 0: the initial state.
    PetscCall(EndForces(0.0));
    PetscCall(ContactColumns(nullptr, row));
    PetscCall(scene_->Measure(*model_, 0.0, forces_.f_int, row));
    history_.Append(row);
    PetscCall(WriteFields(writer, at_.step++, 0.0));
  }
  double &lambda = at_.lambda;
  PetscInt &inc = at_.inc;
  const double dlambda_trial = 1.0 / opt_.increments;
  const double dlambda_unload = opt_.unload_increments > 0 ? 1.0 / opt_.unload_increments : dlambda_trial;
  Controller controller(*model_, *scene_, inertia_.get(), opt_, path_.duration);
  controller.SetStartForces(forces_.f_start);
  controller.SetForceScale(q_sum_, q_count_);
  // Why the run ends before the end of its path (empty: it does not), reported
  // with code stop_code after the results so far are written.
  std::string stop;
  PetscErrorCode stop_code = 0;
  // A restart has written no field step yet: its last state is written whatever ends the run.
  bool stalled = false, wrote_last = opt_.restart.empty();
  int interrupted = 0; // the stop signal that ended the run
  const auto where = [&] {
    return Format("stroke %g, lambda %.6g, after %d increments", history_.rows().back().stroke, lambda, (int)inc);
  };
  // A checkpoint that cannot be written (its scratch file, too little room, a
  // failed HDF5 write: found on every rank) ends the run like a failed
  // increment: results written, the earlier checkpoint kept. `written` says
  // whether it was.
  const auto checkpoint = [&](bool &written) -> PetscErrorCode {
    PetscFunctionBeginUser;
    const PetscErrorCode failed = WriteCheckpoint(writer, output);
    written = failed == 0;
    if (failed == PETSC_ERR_FILE_WRITE) {
      const char *specific = nullptr;
      PetscCall(PetscErrorMessage(failed, nullptr, (char **)&specific));
      stop_code = failed;
      stop = Format("%s (%s)", specific ? specific : "the checkpoint could not be written", where().c_str());
      PetscFunctionReturn(PETSC_SUCCESS);
    }
    PetscCall(failed);
    PetscFunctionReturn(PETSC_SUCCESS);
  };
  const double t_start = MPI_Wtime();
  Progress progress(comm_, opt_.progress, end, path_.breakpoints.empty() ? end : path_.breakpoints.front(), at_.lambda);
  PetscCall(PetscLogStagePush(Log::load_stage));
  while (lambda < end - kLambdaTol) {
    // 1. The stall watch ends a load path that no longer advances.
    if (inc - at_.inc_mark >= opt_.rmin_stall_increments) {
      if (lambda - at_.lambda_mark < kStallAdvance) {
        stalled = true, stop_code = PETSC_ERR_NOT_CONVERGED;
        stop = Format("the load path stalled (%s): %d increments (-rmin_stall_increments) advanced lambda by less than "
                      "%g; the history column limiter names what cut them (docs/theory.md, \"Stalls\")",
                      where().c_str(), (int)opt_.rmin_stall_increments, kStallAdvance);
        break;
      }
      at_.lambda_mark = lambda, at_.inc_mark = inc;
    }
    // ... and so does the increment budget (results up to here are written).
    if (inc == opt_.rmin_max_increments) {
      stop_code = PETSC_ERR_NOT_CONVERGED;
      stop = Format("the load path needs more than -rmin_max_increments %d increments (%s); raise "
                    "-rmin_max_increments or relax -rmin_deps / -rmin_domega",
                    (int)opt_.rmin_max_increments, where().c_str());
      break;
    }
    // ... and the clock (-time_limit) and stop signals (rank 0 may be the only
    // one to see either: clocks differ, a signal may reach one process); both
    // leave a checkpoint to continue from.
    {
      int mine[2] = {opt_.time_limit > 0 && MPI_Wtime() - t_start > opt_.time_limit, StopSignal()}, any[2];
      PetscCallMPI(MPI_Allreduce(mine, any, 2, MPI_INT, MPI_MAX, comm_));
      if (any[1]) {
        interrupted = any[1], stop_code = PETSC_ERR_SIG;
        stop = Format("interrupted by %s (%s)", SignalName(any[1]), where().c_str());
      } else if (any[0]) {
        stop_code = PETSC_ERR_NOT_CONVERGED;
        stop = Format("-time_limit %g s reached (%s)", opt_.time_limit, where().c_str());
      }
      if (!stop.empty() && !opt_.checkpoint.empty()) {
        bool written;
        PetscCall(checkpoint(written)); // a failure replaces the stop's message with its own
        if (written)
          PetscCall(PetscPrintf(comm_, "tubeform: checkpoint after increment %d in %s; continue with -restart %s\n",
                                (int)inc, opt_.checkpoint.c_str(), opt_.checkpoint.c_str()));
      }
      if (!stop.empty()) break;
    }
    ++inc;

    // 2. A stage of the load path (the paper's unloading) begins at its
    //    breakpoint; the loads at its start are the new stage's.
    for (size_t b = 0; b + 1 < breaks.size(); ++b)
      if (!at_.started[b] && lambda >= breaks[b] - kLambdaTol) {
        at_.started[b] = 1;
        PetscCall(scene_->BeginStage(*model_, lambda));
        PetscCall(EndForces(lambda)); // the loads of the new stage (and the start of its first increment)
      }
    const double next_break =
      *std::find_if(breaks.begin(), breaks.end(), [&](double b) { return b > lambda + kLambdaTol; });
    const double dl_stage = lambda >= 1 - kLambdaTol ? dlambda_unload : dlambda_trial;
    const double dl = std::min(dl_stage, next_break - lambda);

    // 3. Frames of the supports and contact nodes on the current geometry.
    PetscCall(scene_->BeginIncrement(*model_, lambda));
    if (contact_) {
      contact_->SetStroke(scene_->ToolStroke(lambda));
      if (q_count_ > 0) contact_->SetForceResolution(opt_.equilibrium_tol * q_sum_ / q_count_);
      if (contact_->active()) PetscCall(contact_->BeginIncrement());
    }

    // 4. The trial solution cut by r_min (paper eq. 16).
    // An increment that fails on every rank alike (an element inverted, r_min
    // vanishing, a singular system) ends the run after the results so far are
    // written; errors (main's handler returns them) of other kinds end it at once.
    Increment taken;
    controller.SetForceScale(q_sum_, q_count_);
    const PetscErrorCode failed = controller.Advance(lambda, dl, end, du, taken);
    if (failed == PETSC_ERR_USER_INPUT || failed == PETSC_ERR_NOT_CONVERGED) {
      const char *specific = nullptr;
      PetscCall(PetscErrorMessage(failed, nullptr, (char **)&specific));
      --inc;
      stop_code = failed;
      stop = Format("%s (%s)", specific ? specific : "the increment failed", where().c_str());
      break;
    }
    PetscCall(failed);

    // 5. Commit: stresses, plastic states and geometry; inertia; contact.
    Committed done;
    for (auto [now, start] : {std::pair{forces_.f_app, forces_.f_app0}, std::pair{forces_.f_ext, forces_.f_ext0},
                              std::pair{forces_.f_int, forces_.f_int0}})
      PetscCall(VecCopy(now, start));
    PetscCall(body_.Commit(du, taken.scale, done.body));
    if (inertia_) PetscCall(inertia_->Advance(du, taken.dl * path_.duration, done.dw_inertia));
    if (contact_ && contact_->active()) PetscCall(contact_->Commit(du, taken.dU, taken.scale, done.contact));
    const double lambda0 = lambda;
    const bool on_break = std::abs(lambda + taken.dl - next_break) < kSnapToBreak * dl_stage;
    lambda = on_break ? next_break : lambda + taken.dl;
    unsettled_ += taken.unsettled;
    unsettled_run_ = taken.unsettled > 0 ? unsettled_run_ + 1 : 0;
    events_inside_ += taken.event_inside;
    inconsistent_ += taken.inconsistent > 0;

    // 6. Forces, energies and the scene's measurements on the new configuration.
    PetscCall(Record(inc, lambda0, lambda, taken, done, du));
    if (!nonfinite_.empty()) {
      PetscInt cell;
      PetscCall(body_.NonFiniteCell(cell));
      const std::string at = cell >= 0 ? Format(", first in element %d", (int)cell) : "";
      stop_code = PETSC_ERR_NOT_CONVERGED, wrote_last = true; // the last fields written are the last finite ones
      stop = Format("increment %d gave %s = NaN or Inf%s: the numbers overflowed (units? -material_E is in MPa); "
                    "it is not written",
                    (int)inc, nonfinite_.c_str(), at.c_str());
      stop += Format(" (%s)", where().c_str());
      break;
    }
    if (diverged_) {
      stop_code = PETSC_ERR_NOT_CONVERGED, wrote_last = false;
      stop = Format("the energy balance error %.1f %% passed -max_energy_error %g: the solution has left equilibrium "
                    "(smaller -increments / -rmin_deps; docs/accuracy.md, \"Extremes\") (%s)",
                    100 * history_.rows().back().energy_error, opt_.max_energy_error, where().c_str());
      break;
    }
    if (unsettled_run_ >= opt_.friction_max_unsettled) {
      stop_code = PETSC_ERR_NOT_CONVERGED, wrote_last = false;
      stop = Format("the friction iterations did not settle in %d increments in a row (-friction_max_unsettled), even "
                    "on steps halved %d times: raise -friction_max_iters or -friction_tol, or try -dynamics auto (%s)",
                    (int)unsettled_run_, kMaxCuts, where().c_str());
      break;
    }
    PetscCall(progress.Update(lambda, inc, history_.rows().back().stroke));
    wrote_last = output.Due(inc, lambda, on_break, lambda >= end - kLambdaTol);
    if (wrote_last) PetscCall(WriteFields(writer, at_.step++, lambda));
    if (opt_.checkpoint_every > 0 && inc % opt_.checkpoint_every == 0) {
      bool written;
      PetscCall(checkpoint(written));
      if (!written) break;
    }
  }
  if (!wrote_last) PetscCall(WriteFields(writer, at_.step++, lambda)); // (a loop that ends normally wrote it)
  PetscCall(PetscLogStagePop());

  // 7. Final metrics and the result file (renamed into place only now).
  PetscCall(PetscLogStagePush(Log::output_stage));
  const HistoryRow &last = history_.rows().back();
  std::vector<std::pair<std::string, double>> metrics = {{"final_stroke", last.stroke},
                                                         {"final_load", last.load},
                                                         {"x_max", last.x_max},
                                                         {"y_max", last.y_max},
                                                         {"stalled", stalled ? 1.0 : 0.0},
                                                         {"stopped", stop.empty() ? 0.0 : 1.0},
                                                         {"interrupted", double(interrupted)}};
  for (const auto &m : scene_->FinalMetrics(history_)) metrics.push_back(m);
  PetscCall(writer.Close(history_, metrics));
  {
    int ok = history_.FinishCsv(); // rank 0 holds the file; every rank learns the outcome
    PetscCallMPI(MPI_Bcast(&ok, 1, MPI_INT, 0, comm_));
    PetscCheck(ok, comm_, PETSC_ERR_FILE_WRITE, "-history_csv %s: cannot rename the finished file into place",
               opt_.history_csv.c_str());
  }
  PetscCall(PetscLogStagePop());
  if (stop.empty()) {
    PetscCall(PetscPrintf(comm_, "tubeform: %s done, %d increments, %d factorizations; results in %s\n",
                          opt_.scene.c_str(), (int)inc, (int)system_.factorizations(), opt_.output.c_str()));
    PetscCall(PetscPrintf(comm_,
                          "tubeform: self-checks: energy balance within %.2g %%, internal work within %.2g %%; "
                          "compromises: %d steps past an event, %d unsettled, %d with inconsistent loading states\n",
                          100 * worst_error_, 100 * worst_internal_, (int)events_inside_, (int)unsettled_,
                          (int)inconsistent_));
  }
  PetscCall(VecDestroy(&du));
  PetscCall(DestroyForces());
  // An early stop is a failure of the run, reported after its results are written.
  PetscCheck(stop.empty(), comm_, stop_code, "%s; results up to there are in %s", stop.c_str(), opt_.output.c_str());
  PetscFunctionReturn(PETSC_SUCCESS);
}

} // namespace tf
