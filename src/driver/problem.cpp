#include "tubeform/driver/problem.hpp"

#include <algorithm>
#include <cmath>

#include "tubeform/core/log.hpp"
#include "tubeform/scenes/registry.hpp"

namespace tf {

namespace {
// Stall watch: -rmin_stall_increments increments that together advance lambda
// by less than this end the loading (results so far kept).
constexpr double kStall = 1e-6;
// A step ending this close to a breakpoint (in trial steps) ends on it.
constexpr double kSnapToBreak = 1e-9;
// The energy balance error above which the run warns once (after the first increments).
constexpr double kEnergyWarning = 0.05;
constexpr PetscInt kEnergyWarningAfter = 10;

BodyParams MakeBodyParams(const Options &opt)
{
  BodyParams b;
  b.element = opt.element;
  b.material = opt.material;
  b.rmin_deps = opt.rmin_deps;
  b.rmin_domega = opt.rmin_domega;
  b.group_tol = opt.rmin_group_tol;
  b.drift_correction = opt.drift_correction;
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
  PetscCall(body_.Setup(mesh_, MakeBodyParams(opt_)));
  if (opt_.dynamics != Dynamics::Quasistatic) {
    inertia_ = std::make_unique<Inertia>();
    inertia_->Setup(body_, opt_.material.density, opt_.dynamics == Dynamics::Implicit);
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
                 &forces_.f_res, &forces_.f_net})
    PetscCall(VecDuplicate(like, v));
  PetscCall(VecZeroEntries(forces_.f_res));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Problem::DestroyForces()
{
  PetscFunctionBeginUser;
  for (Vec *v : {&forces_.f_app, &forces_.f_app0, &forces_.f_ext, &forces_.f_ext0, &forces_.f_int, &forces_.f_int0,
                 &forces_.f_res, &forces_.f_net})
    PetscCall(VecDestroy(v));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Problem::Run()
{
  ResultWriter writer;
  Vec du;
  HistoryRow row;
  double lambda = 0;
  PetscInt step = 0, inc = 0;

  PetscFunctionBeginUser;
  // 0. Outputs are checked before any work, so a bad path fails at once.
  if (!opt_.history_csv.empty()) PetscCall(CheckWritable(comm_, opt_.history_csv, "-history_csv"));
  PetscCall(writer.Open(mesh_, opt_.output));
  {
    const std::string err = history_.OpenCsv(opt_.history_csv, rank_);
    int ok = err.empty();
    PetscCallMPI(MPI_Bcast(&ok, 1, MPI_INT, 0, comm_));
    PetscCheck(ok, comm_, PETSC_ERR_USER_INPUT,
               "-history_csv %s: cannot create the file (does the directory exist and is it writable?)",
               opt_.history_csv.c_str());
  }
  du = system_.CreateLocalVector();
  PetscCall(CreateForces(du));

  // The tools the scene asks for, and increment 0: the initial state.
  ContactSpec tools;
  PetscCall(scene_->Initialize(*model_, tools));
  if (!tools.candidates.empty()) {
    contact_ = std::make_unique<ContactSet>();
    contact_->Setup(mesh_, system_, body_.position(), std::move(tools));
    PetscCall(contact_->Initialize());
    model_->contact = contact_.get();
  }
  PetscCall(body_.InternalForce(forces_.f_int));
  PetscCall(ExternalForces(0.0));
  PetscCall(ContactColumns(ContactCommit{}, row));
  PetscCall(scene_->Measure(*model_, 0.0, forces_.f_int, row));
  history_.Append(row);
  PetscCall(WriteFields(writer, step++, 0.0));

  const double end = path_.end;
  std::vector<double> breaks = path_.breakpoints;
  breaks.push_back(end);
  std::vector<char> started(breaks.size(), 0);
  const double dlambda_trial = 1.0 / opt_.increments;
  Controller controller(*model_, *scene_, inertia_.get(), opt_, path_.duration);
  controller.SetResidual(forces_.f_res);
  double lambda_mark = 0;
  PetscInt inc_mark = 0;
  bool stalled = false;
  PetscCall(PetscLogStagePush(Log::load_stage));
  while (lambda < end - kLambdaTol) {
    // 1. The stall watch ends a load path that no longer advances.
    if (inc - inc_mark >= opt_.rmin_stall_increments) {
      if (lambda - lambda_mark < kStall) {
        stalled = true;
        break;
      }
      lambda_mark = lambda, inc_mark = inc;
    }
    PetscCheck(++inc <= opt_.rmin_max_increments, comm_, PETSC_ERR_NOT_CONVERGED,
               "no convergence of the load path: %d increments reached lambda = %g; raise -rmin_max_increments or "
               "relax -rmin_deps / -rmin_domega",
               (int)opt_.rmin_max_increments, lambda);

    // 2. A stage of the load path (the paper's unloading) begins at its breakpoint.
    for (size_t b = 0; b + 1 < breaks.size(); ++b)
      if (!started[b] && lambda >= breaks[b] - kLambdaTol) {
        started[b] = 1;
        PetscCall(scene_->BeginStage(*model_, lambda));
      }
    const double next_break =
      *std::find_if(breaks.begin(), breaks.end(), [&](double b) { return b > lambda + kLambdaTol; });
    const double dl = std::min(dlambda_trial, next_break - lambda);

    // 3. Frames of the supports and contact nodes on the current geometry.
    PetscCall(scene_->BeginIncrement(*model_, lambda));
    if (contact_) {
      contact_->SetStroke(scene_->ToolStroke(lambda));
      if (contact_->active()) PetscCall(contact_->BeginIncrement());
    }

    // 4. The trial solution cut by r_min (paper eq. 16).
    Increment taken;
    PetscCall(controller.Advance(lambda, dl, end, du, taken));

    // 5. Commit: stresses, plastic states and geometry; inertia; contact.
    Committed done;
    for (auto [now, start] : {std::pair{forces_.f_app, forces_.f_app0}, std::pair{forces_.f_ext, forces_.f_ext0},
                              std::pair{forces_.f_int, forces_.f_int0}})
      PetscCall(VecCopy(now, start));
    PetscCall(body_.Commit(du, taken.r_event, done.body));
    if (inertia_) PetscCall(inertia_->Advance(du, taken.dl * path_.duration, done.dw_inertia));
    if (contact_ && contact_->active())
      PetscCall(contact_->Commit(du, taken.react_scale * taken.dU, taken.react_scale, taken.r_event, done.contact));
    const double lambda0 = lambda;
    const bool on_break = std::abs(lambda + taken.dl - next_break) < kSnapToBreak * dlambda_trial;
    lambda = on_break ? next_break : lambda + taken.dl;
    unsettled_ += taken.unsettled;
    events_inside_ += taken.event_inside;
    inconsistent_ += taken.inconsistent > 0;

    // 6. Forces, energies and the scene's measurements on the new configuration.
    PetscCall(Record(inc, lambda0, lambda, taken, done, du));
    if (inc % opt_.output_every == 0 || lambda >= end - kLambdaTol) PetscCall(WriteFields(writer, step++, lambda));
  }
  if (stalled && inc % opt_.output_every != 0) PetscCall(WriteFields(writer, step++, lambda));
  PetscCall(PetscLogStagePop());

  // 7. Final metrics and the result file (renamed into place only now).
  PetscCall(PetscLogStagePush(Log::output_stage));
  const HistoryRow &last = history_.rows().back();
  std::vector<std::pair<std::string, double>> metrics = {{"final_stroke", last.stroke},
                                                         {"final_load", last.load},
                                                         {"x_max", last.x_max},
                                                         {"y_max", last.y_max},
                                                         {"stalled", stalled ? 1.0 : 0.0}};
  for (const auto &m : scene_->FinalMetrics(history_)) metrics.push_back(m);
  PetscCall(writer.Close(history_, metrics));
  PetscCheck(history_.FinishCsv(), comm_, PETSC_ERR_FILE_WRITE,
             "-history_csv %s: cannot rename the finished file into place", opt_.history_csv.c_str());
  PetscCall(PetscLogStagePop());
  if (!stalled) {
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
  // A stall is a failure of the run, reported after its results are written.
  PetscCheck(!stalled, comm_, PETSC_ERR_NOT_CONVERGED,
             "the load path stalled at stroke %g (lambda %.6g): %d increments (-rmin_stall_increments) advanced "
             "lambda by less than %g; the history column limiter names what cut them (docs/theory.md, \"Stalls\"); "
             "results up to there are in %s",
             history_.rows().back().stroke, lambda, (int)opt_.rmin_stall_increments, kStall, opt_.output.c_str());
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Problem::ContactColumns(const ContactCommit &report, HistoryRow &row) const
{
  PetscFunctionBeginUser;
  if (!contact_) PetscFunctionReturn(PETSC_SUCCESS);
  PetscInt n;
  PetscCall(contact_->Count(n));
  row.n_contact = n;
  PetscCall(contact_->NormalForceSum(row.fn_sum));
  if (!contact_->active()) PetscFunctionReturn(PETSC_SUCCESS); // the tools are gone
  PetscCall(contact_->Penetration(row.penetration));
  row.tension = report.tension;
  row.release_force = report.release_force;
  row.contact_gap = report.gap;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Problem::ExternalForces(double lambda)
{
  PetscFunctionBeginUser;
  PetscCall(scene_->ExternalForce(*model_, lambda, forces_.f_app));
  PetscCall(VecCopy(forces_.f_app, forces_.f_ext));
  if (contact_ && contact_->active()) PetscCall(contact_->AddFrictionForces(forces_.f_ext));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Problem::Record(PetscInt inc, double lambda0, double lambda, const Increment &taken,
                               const Committed &done, Vec du)
{
  Vec f_int = forces_.f_int;
  double residual, dw_body, dw_applied;
  const bool inertia = inertia_ && inertia_->active();

  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(Log::measure, 0, 0, 0, 0));
  // Work of the increment by the trapezoidal rule: of the loads and supports
  // at the nodes (loads on free dofs, reactions on supported ones), and of
  // the scene's applied loads alone.
  PetscCall(ExternalForces(lambda));
  PetscCall(body_.InternalForce(f_int));
  if (inertia) PetscCall(inertia_->AddForce(f_int)); // f_int + M a: what the loads and reactions balance
  for (auto [start, now] : {std::pair{forces_.f_app0, forces_.f_app}, std::pair{forces_.f_ext0, forces_.f_ext},
                            std::pair{forces_.f_int0, f_int}})
    PetscCall(VecAXPBY(start, 0.5, 0.5, now));
  PetscCall(system_.ExternalWork(forces_.f_ext0, forces_.f_int0, du, dw_body));
  PetscCall(system_.ExternalWork(forces_.f_app0, nullptr, du, dw_applied));
  PetscCall(VecWAXPY(forces_.f_res, -1.0, f_int, forces_.f_ext));
  PetscCall(system_.FreeNorm(forces_.f_res, residual));

  HistoryRow row;
  row.increment = inc;
  row.rmin = taken.r;
  row.limiter = static_cast<double>(taken.who);
  row.limiter_where = taken.where;
  row.n_plastic = done.body.n_plastic;
  row.friction_iters = taken.solves;
  row.residual = residual;
  row.redo = taken.redo;
  row.drift = done.body.drift;
  row.unsettled = unsettled_;
  row.events_inside = events_inside_;
  row.inconsistent = inconsistent_;
  row.inertia = inertia ? 1 : 0;
  PetscCall(ContactColumns(done.contact, row));
  if (contact_ && contact_->active()) {
    // The net force the body needs at the contact nodes, f_int - f_app, ghost-summed.
    Vec g;
    PetscCall(VecWAXPY(forces_.f_net, -1.0, forces_.f_app, f_int));
    PetscCall(DMGetGlobalVector(mesh_.dm, &g));
    PetscCall(VecZeroEntries(g));
    PetscCall(DMLocalToGlobal(mesh_.dm, forces_.f_net, ADD_VALUES, g));
    PetscCall(DMGlobalToLocal(mesh_.dm, g, INSERT_VALUES, forces_.f_net));
    PetscCall(DMRestoreGlobalVector(mesh_.dm, &g));
    PetscCall(contact_->NormalForceMismatch(forces_.f_net, row.fn_mismatch));
  }
  PetscCall(scene_->Measure(*model_, lambda, f_int, row));

  // Check (a)'s input: from the reported load and stroke where the scene
  // says they are work-conjugate in this stage, else the loads' and supports'
  // work plus what friction dissipated (the tools' side of it).
  const HistoryRow &prev = history_.rows().back();
  const double share = scene_->LoadWorkShare(0.5 * (lambda0 + lambda));
  const double dw_tool = share * 0.5 * (prev.load + row.load) * (row.stroke - prev.stroke);
  energy_.w_tool += dw_tool;
  energy_.w_ext += share > 0 ? dw_tool + dw_applied : dw_body + done.contact.w_friction;
  energy_.w_friction += done.contact.w_friction;
  energy_.w_int += done.body.dw_int;
  energy_.w_plastic += done.body.dw_plastic;
  energy_.w_inertia += done.dw_inertia;
  row.w_ext = energy_.w_ext;
  row.w_tool = energy_.w_tool;
  row.w_int = energy_.w_int;
  row.w_plastic = energy_.w_plastic;
  row.w_friction = energy_.w_friction;
  row.w_inertia = energy_.w_inertia;
  PetscCall(body_.ElasticEnergy(row.w_elastic));
  if (inertia) PetscCall(inertia_->KineticEnergy(row.w_kinetic));
  row.w_damped = energy_.Damped(row.w_kinetic);
  row.energy_error = energy_.BalanceError(row.w_kinetic);
  row.internal_error = energy_.InternalError(row.w_elastic);
  history_.Append(row);
  PetscCall(PetscLogEventEnd(Log::measure, 0, 0, 0, 0));

  if (inc > kEnergyWarningAfter) {
    worst_error_ = std::max(worst_error_, std::abs(row.energy_error));
    worst_internal_ = std::max(worst_internal_, std::abs(row.internal_error));
  }
  if (!warned_ && std::abs(row.energy_error) > kEnergyWarning && inc > kEnergyWarningAfter) {
    warned_ = true;
    PetscCall(PetscPrintf(comm_,
                          "tubeform: warning: energy balance error %.1f %% at increment %d (lambda %.4f): the solution "
                          "is drifting from equilibrium; try smaller -rmin_deps / -increments, or see docs/theory.md\n",
                          100 * row.energy_error, (int)inc, lambda));
  }
  if (opt_.monitor) PetscCall(PrintMonitor(inc, lambda, taken, row));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Problem::PrintMonitor(PetscInt inc, double lambda, const Increment &taken, const HistoryRow &row)
{
  Vec g;
  PetscReal fnorm;

  PetscFunctionBeginUser;
  // Scale of the forces: the internal force over all dofs.
  PetscCall(DMGetGlobalVector(mesh_.dm, &g));
  PetscCall(VecZeroEntries(g));
  PetscCall(DMLocalToGlobal(mesh_.dm, forces_.f_int, ADD_VALUES, g));
  PetscCall(VecNorm(g, NORM_2, &fnorm));
  PetscCall(DMRestoreGlobalVector(mesh_.dm, &g));
  const std::string where = taken.where >= 0 ? " @" + std::to_string(taken.where) : "";
  PetscCall(PetscPrintf(comm_, "inc %5d  lambda %.5f  stroke %-11.5g load %-11.5g r_min %.3g (%s%s)", (int)inc, lambda,
                        row.stroke, row.load, taken.r, LimiterName((int)taken.who), where.c_str()));
  PetscCall(PetscPrintf(comm_, "  plastic %d  contact %d  iters %d", (int)row.n_plastic, (int)row.n_contact,
                        (int)taken.solves));
  PetscCall(PetscPrintf(comm_, "  residual %.2e (rel %.1e)  energy err %.1e\n", row.residual,
                        row.residual / std::max((double)fnorm, kTiny), row.energy_error));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Problem::WriteFields(ResultWriter &writer, PetscInt step, double t)
{
  std::vector<CellField> cells = {{"sigma_xx", {}},  {"sigma_yy", {}}, {"sigma_zz", {}}, {"sigma_xy", {}},
                                  {"von_mises", {}}, {"eps_p", {}},    {"plastic", {}}};
  PetscFunctionBeginUser;
  for (auto &c : cells) c.values.assign(mesh_.num_cells, 0.0);
  // Cell values are Gauss-point averages.
  for (PetscInt e = 0; e < mesh_.num_cells; ++e)
    for (int g = 0; g < fe::kGauss; ++g) {
      const PointState &ps = body_.state()[fe::kGauss * e + g];
      const Voigt &s = ps.sigma;
      const double vals[7] = {s[0], s[1], s[2], s[3], VonMises(s), ps.ep, ps.plastic ? 1.0 : 0.0};
      for (int k = 0; k < 7; ++k) cells[k].values[e] += vals[k] / fe::kGauss;
    }
  PetscCall(writer.WriteStep(step, t, body_.displacement(), cells));
  PetscFunctionReturn(PETSC_SUCCESS);
}

} // namespace tf
