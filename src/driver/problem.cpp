#include "tubeform/driver/problem.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "tubeform/core/log.hpp"
#include "tubeform/core/signals.hpp"
#include "tubeform/driver/output_schedule.hpp"
#include "tubeform/driver/progress.hpp"
#include "tubeform/material/factory.hpp"
#include "tubeform/scenes/registry.hpp"
#include "tubeform/scenes/tool_columns.hpp"
#include "tubeform/scenes/tool_scene.hpp"

namespace tf {

namespace {
// A step ending this close to a breakpoint (in trial steps) ends on it.
constexpr double kSnapToBreak = 1e-9;

BodyParams MakeBodyParams(const Options &opt)
{
  BodyParams b;
  b.element = opt.element;
  b.material = opt.material;
  b.rmin_deps = opt.driver.rmin_deps;
  b.rmin_deps_yield = opt.driver.rmin_deps_yield;
  b.rmin_domega = opt.driver.rmin_domega;
  b.group_tol = opt.driver.rmin_group_tol;
  // With equilibrium iterations a point yields inside the step on its own path
  // (the update finds the onset); r1 limits the paper's forward increments only.
  b.yield_inside = opt.driver.rmin_yield == RminYield::Inside || opt.driver.equilibrium_tol > 0;
  b.yield_tol = opt.driver.rmin_yield_tol;
  b.drift_correction = opt.driver.drift_correction;
  b.plastic_update = UpdateFor(opt.driver.plastic_update, LawOf(opt.material), opt.driver.equilibrium_tol > 0);
  b.state_from_strain = opt.driver.equilibrium_tol > 0;
  b.kinematics = opt.driver.kinematics;
  return b;
}

// A stop signal during the set-up (the mesh, its partition, the system) ends
// the run before it writes anything: at once, as a batch system's kill a
// second or two later asks.
PetscErrorCode CheckNotInterrupted(MPI_Comm comm, const std::string &output)
{
  PetscFunctionBeginUser;
  int mine = StopSignal(), any;
  PetscCallMPI(MPI_Allreduce(&mine, &any, 1, MPI_INT, MPI_MAX, comm));
  PetscCheck(!any, comm, PETSC_ERR_SIG, "interrupted by %s before the first increment: no results written%s%s",
             SignalName(any), output.empty() ? "" : ", the earlier ones unchanged in ", output.c_str());
  PetscFunctionReturn(PETSC_SUCCESS);
}

// Where the load path's increments end: its stages' ends (`breaks`: the breakpoints and the path's end), those
// and the kinks inside the stages (`ends`, sorted), and the stages the progress line counts (`bounds`: 0, the
// breakpoints before the end, the end).
struct Stages {
  std::vector<double> breaks, ends, bounds;
};

Stages StagesOf(const LoadPath &path)
{
  Stages s;
  s.breaks = path.breakpoints;
  s.breaks.push_back(path.end);
  s.ends = s.breaks;
  s.ends.insert(s.ends.end(), path.kinks.begin(), path.kinks.end());
  std::sort(s.ends.begin(), s.ends.end());
  s.bounds = {0.0};
  for (double b : path.breakpoints)
    if (b < path.end - kLambdaTol) s.bounds.push_back(b);
  s.bounds.push_back(path.end);
  return s;
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
  started_ = MPI_Wtime();
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

  const BodyParams body = MakeBodyParams(opt_);
  if (!quiet_) {
    // (the radial return named: a demanded accuracy chooses it where -plastic_update does not)
    const char *update = body.plastic_update == PlasticUpdate::Radial ? ", radial return" : "";
    if (opt.mesh_file.empty())
      PetscCall(PetscPrintf(comm, "tubeform: mesh %d cells (%s), %s elements%s\n", ncells,
                            scene_->MeshLayout(opt).c_str(), opt.element_name.c_str(), update));
    else
      PetscCall(PetscPrintf(comm, "tubeform: mesh %d cells from %s, %s elements%s\n", ncells, opt.mesh_file.c_str(),
                            opt.element_name.c_str(), update));
  }

  // 2. Partition and distribute; the global system, the body, inertia.
  PetscCall(mesh_.Create(comm, serial, scene_->BoundarySets()));
  PetscCall(PetscLogEventEnd(Log::mesh, 0, 0, 0, 0));
  PetscCall(system_.Setup(mesh_, opt_.driver.factorization));
  if ((size_ > 1 || opt_.monitor) && !quiet_)
    PetscCall(PetscPrintf(comm_, "tubeform: linear solver: %s\n", system_.solver().c_str()));
  PetscCall(body_.Setup(mesh_, body));
  if (opt_.driver.dynamics != Dynamics::Quasistatic) {
    inertia_ = std::make_unique<Inertia>();
    PetscCall(inertia_->Setup(body_, opt_.material.density, opt_.driver.dynamics == Dynamics::Implicit));
  }
  model_ = std::make_unique<Model>(Model{comm_, mesh_, system_, body_, nullptr, quiet_});
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

PetscErrorCode Problem::Open(ResultWriter &writer)
{
  PetscFunctionBeginUser;
  // Outputs are checked before any work, so a bad path fails at once; the
  // tools the scene asks for are set up (and refused if they start inside the
  // body) before the result file is opened, so such a start leaves no file.
  if (!opt_.history_csv.empty()) PetscCall(CheckWritable(comm_, opt_.history_csv, "-history_csv"));
  if (!opt_.output.empty()) PetscCall(CheckWritable(comm_, opt_.output, "-output")); // (none: a companion run)
  if (!opt_.checkpoint.empty()) PetscCall(CheckWritable(comm_, opt_.checkpoint, "-checkpoint"));
  ContactSpec tools;
  PetscCall(scene_->Initialize(*model_, tools));
  if (!tools.candidates.empty()) {
    contact_ = std::make_unique<ContactSet>();
    PetscCall(contact_->Setup(mesh_, system_, body_.position(), std::move(tools)));
    contact_->SetBalanced(opt_.driver.equilibrium_tol > 0);
    PetscCall(contact_->Initialize());
    model_->contact = contact_.get();
  }
  if (opt_.restart.empty() && !opt_.output.empty()) PetscCall(writer.Open(mesh_, opt_.output));
  writer.SetTimeScale(path_.duration); // the .xmf's time: seconds of the load path (a tool's stroke at 1 mm/s)
  PetscCall(history_.Declare(DeclaredToolColumns(), comm_)); // (the tools' columns: scenes/tool_columns.hpp)
  int ok = history_.OpenCsv(opt_.history_csv, rank_);
  PetscCallMPI(MPI_Bcast(&ok, 1, MPI_INT, 0, comm_));
  PetscCheck(ok, comm_, PETSC_ERR_USER_INPUT,
             "-history_csv %s: cannot create the file (does the directory exist and is it writable?)",
             opt_.history_csv.c_str());
  Vec like = system_.CreateLocalVector();
  PetscCall(CreateForces(like));
  PetscCall(VecDestroy(&like));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Problem::Start(ResultWriter &writer)
{
  HistoryRow row;
  PetscFunctionBeginUser;
  PetscCall(EndForces(0.0));
  PetscCall(ContactColumns(nullptr, row));
  PetscCall(scene_->Measure(*model_, 0.0, forces_.f_int, row));
  history_.Append(row);
  PetscCall(WriteFields(writer, at_.step++, 0.0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Problem::Run()
{
  ResultWriter writer;
  Stop stop;

  PetscFunctionBeginUser;
  PetscCall(CheckNotInterrupted(comm_, opt_.output));
  PetscCall(Open(writer));
  at_.started.assign(path_.breakpoints.size() + 1, 0); // one per stage; a checkpoint's must have as many stages
  OutputSchedule output(opt_.output_every, opt_.output_stroke > 0 ? opt_.output_stroke / Travel(opt_) : 0);
  if (!opt_.restart.empty())
    PetscCall(ReadCheckpoint(writer, output)); // the state and the results so far
  else
    PetscCall(Start(writer)); // increment 0: the initial state
  PetscCall(Increments(writer, output, stop));
  PetscCall(DestroyForces());

  // 7. The answer, the result files (renamed into place only now), the estimate added to them, the self-checks.
  PetscCall(Finish(writer, stop));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Problem::Increments(ResultWriter &writer, OutputSchedule &output, Stop &stop)
{
  PetscFunctionBeginUser;
  const double end = path_.end;
  Stages stages = StagesOf(path_ = scene_->Path(opt_)); // (again: a restart inside a later pass, its kinks)
  double &lambda = at_.lambda;
  PetscInt &inc = at_.inc;
  const double dl_load = 1.0 / opt_.driver.increments;
  const double dl_unload = opt_.driver.unload_increments > 0 ? 1.0 / opt_.driver.unload_increments : dl_load;
  Controller controller(*model_, *scene_, inertia_.get(), opt_, path_.duration, at_.iterate_tangent);
  controller.SetStartForces(forces_.f_start);
  Vec du = system_.CreateLocalVector();
  // A restart has written no field step yet: its last state is written whatever ends the run.
  bool wrote_last = opt_.restart.empty();
  Progress progress(
    comm_, opt_.progress, stages.bounds, [this](double lambda) { return scene_->Unloading(lambda); }, at_.lambda);
  const double t_start = MPI_Wtime();
  PetscCall(PetscLogStagePush(Log::load_stage));
  while (lambda < end - kLambdaTol) {
    // 1. Whatever ends the load path before its end: a stall, the increment
    //    budget, the clock, a stop signal (src/driver/stops.cpp).
    PetscCall(StopBefore(writer, output, t_start, stop));
    if (!stop.why.empty()) break;
    ++inc;

    // 2. A stage of the load path (the paper's unloading) begins at its breakpoint.
    bool began;
    PetscCall(BeginStages(stages.breaks, stop, began));
    if (!stop.why.empty()) break;
    if (began) stages = StagesOf(path_ = scene_->Path(opt_)); // (a later pass's kinks, known once it starts)
    const double next_break =
      *std::find_if(stages.ends.begin(), stages.ends.end(), [&](double b) { return b > lambda + kLambdaTol; });
    const double dl_stage = scene_->Unloading(lambda) ? dl_unload : dl_load;
    const double dl = std::min(dl_stage, next_break - lambda);

    // 3. Frames of the supports and contact nodes on the current geometry.
    PetscCall(BeginIncrement(lambda));

    // 4. The trial step cut by r_min (paper eq. 16) and brought into balance.
    //    An increment that fails on every rank alike (an element inverted,
    //    r_min vanishing, a singular system) ends the run after the results so
    //    far are written; errors of other kinds end it at once.
    Increment taken;
    controller.SetForceScale(q_sum_, q_count_);
    PetscCall(StopOnFailure(controller.Advance(lambda, dl, end, du, taken), stop));
    if (!stop.why.empty()) break;

    // 5. Commit: stresses, plastic states and geometry; inertia; contact; lambda at the step's end.
    Committed done;
    const double lambda0 = lambda;
    bool on_break;
    PetscCall(Commit(du, taken, next_break, dl_stage, done, on_break));

    // 6. Forces, energies, self-checks and the scene's measurements on the
    //    new configuration; what they say may end the run.
    PetscCall(Record(inc, lambda0, lambda, taken, done, du));
    PetscCall(StopAfter(stop, wrote_last));
    if (!stop.why.empty()) break;
    PetscCall(progress.Update(lambda, inc, history_.rows().back().stroke));
    wrote_last = output.Due(inc, lambda, on_break, lambda >= end - kLambdaTol);
    if (wrote_last) PetscCall(WriteFields(writer, at_.step++, lambda));
    if (opt_.checkpoint_every > 0 && inc % opt_.checkpoint_every == 0) {
      PetscCall(Checkpoint(writer, output, stop));
      if (!stop.why.empty()) break;
    }
  }
  if (!wrote_last) PetscCall(WriteFields(writer, at_.step++, lambda)); // (a loop that ends normally wrote it)
  PetscCall(PetscLogStagePop());
  PetscCall(VecDestroy(&du));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Problem::BeginStages(const std::vector<double> &breaks, Stop &stop, bool &began)
{
  PetscFunctionBeginUser;
  began = false;
  // The loads at a stage's start are the new stage's. A stage the scene refuses to start (a second pass's die
  // inside the tube) ends the run as a failed increment does, with the results so far written.
  for (size_t b = 0; b + 1 < breaks.size() && stop.why.empty(); ++b)
    if (!at_.started[b] && at_.lambda >= breaks[b] - kLambdaTol) {
      at_.started[b] = 1, began = true;
      PetscCall(StopOnFailure(scene_->BeginStage(*model_, at_.lambda), stop));
      if (stop.why.empty()) PetscCall(EndForces(at_.lambda));
    }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Problem::BeginIncrement(double lambda)
{
  PetscFunctionBeginUser;
  PetscCall(scene_->BeginIncrement(*model_, lambda));
  if (contact_) {
    contact_->SetStroke(scene_->ToolStroke(lambda));
    if (q_count_ > 0) contact_->SetForceResolution(opt_.driver.equilibrium_tol * q_sum_ / q_count_);
    if (contact_->active()) PetscCall(contact_->BeginIncrement());
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Problem::Commit(Vec du, const Increment &taken, double next_break, double dl_stage, Committed &done,
                               bool &on_break)
{
  double &lambda = at_.lambda;

  PetscFunctionBeginUser;
  for (auto [now, start] : {std::pair{forces_.f_app, forces_.f_app0}, std::pair{forces_.f_ext, forces_.f_ext0},
                            std::pair{forces_.f_int, forces_.f_int0}})
    PetscCall(VecCopy(now, start));
  PetscCall(body_.Commit(du, taken.scale, done.body));
  if (inertia_) PetscCall(inertia_->Advance(du, taken.dl * path_.duration, done.dw_inertia));
  if (contact_ && contact_->active()) PetscCall(contact_->Commit(du, taken.dU, taken.scale, done.contact));
  on_break = std::abs(lambda + taken.dl - next_break) < kSnapToBreak * dl_stage;
  lambda = on_break ? next_break : lambda + taken.dl;
  unsettled_ += taken.unsettled;
  // (in kDeepPerUnsettled-ths of an unsettled step: a step that settled only on inertia's shorter steps counts
  // as such a part, a run of them creeping on at 1e-6 of a step)
  unsettled_run_ = taken.unsettled > 0 ? unsettled_run_ + kDeepPerUnsettled : taken.deep ? unsettled_run_ + 1 : 0;
  events_inside_ += taken.event_inside;
  inconsistent_ += taken.inconsistent > 0;
  PetscFunctionReturn(PETSC_SUCCESS);
}

} // namespace tf
