// What a run records: the history row of each increment (forces on the new
// geometry, the energy accounts and self-checks, the contact columns, the
// scene's measurements), the -monitor line, and the cell fields.
#include <algorithm>
#include <cmath>

#include "tubeform/core/log.hpp"
#include "tubeform/driver/problem.hpp"

namespace tf {

namespace {
// The energy balance error above which the run warns once.
constexpr double kEnergyWarning = 0.05;
// The first increments are left out of the warning and the summary's worst
// self-checks: their work is too small for a relative error to mean much.
constexpr PetscInt kEnergyWarningAfter = 10;

// g (a global vector) = the rank sum of the per-rank contributions f_local.
PetscErrorCode SumContributions(DM dm, Vec f_local, Vec g)
{
  PetscFunctionBeginUser;
  PetscCall(VecZeroEntries(g));
  PetscCall(DMLocalToGlobal(dm, f_local, ADD_VALUES, g));
  PetscFunctionReturn(PETSC_SUCCESS);
}
} // namespace

PetscErrorCode Problem::ContactColumns(const ContactCommit *report, HistoryRow &row)
{
  PetscFunctionBeginUser;
  if (!contact_) PetscFunctionReturn(PETSC_SUCCESS);
  PetscInt n;
  PetscCall(contact_->Count(n));
  row.n_contact = n;
  PetscCall(contact_->NormalForceSum(row.fn_sum));
  if (!contact_->active()) PetscFunctionReturn(PETSC_SUCCESS); // the tools are gone
  if (!report) {                                               // the initial state
    PetscCall(contact_->Penetration(row.penetration));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  row.penetration = report->penetration;
  row.tension = report->tension;
  row.release_force = report->release_force;
  row.contact_gap = report->gap;
  // The normal forces the body needs at the contact nodes: f_int - f_app, rank-summed.
  Vec g;
  PetscCall(VecWAXPY(forces_.f_net, -1.0, forces_.f_app, forces_.f_int));
  PetscCall(DMGetGlobalVector(mesh_.dm, &g));
  PetscCall(SumContributions(mesh_.dm, forces_.f_net, g));
  PetscCall(DMGlobalToLocal(mesh_.dm, g, INSERT_VALUES, forces_.f_net));
  PetscCall(DMRestoreGlobalVector(mesh_.dm, &g));
  PetscCall(contact_->NormalForceMismatch(forces_.f_net, row.fn_mismatch));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Problem::ExternalForces(double lambda)
{
  PetscFunctionBeginUser;
  PetscCall(scene_->ExternalForce(*model_, lambda, forces_.f_app));
  // Forces of released contact nodes not yet unloaded act as applied loads.
  if (contact_ && contact_->active()) PetscCall(contact_->AddPendingForces(forces_.f_app));
  PetscCall(VecCopy(forces_.f_app, forces_.f_ext));
  if (contact_ && contact_->active()) PetscCall(contact_->AddFrictionForces(forces_.f_ext));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Problem::EndForces(double lambda)
{
  PetscFunctionBeginUser;
  PetscCall(ExternalForces(lambda));
  double sums[2], global[2];
  PetscCall(body_.InternalForce(forces_.f_int, &sums[0], &sums[1]));
  PetscCall(MPIU_Allreduce(sums, global, 2, MPIU_REAL, MPIU_SUM, comm_));
  q_now_ = global[0] / std::max(global[1], 1.0);
  if (inertia_ && inertia_->active()) PetscCall(inertia_->AddForce(forces_.f_int));
  PetscCall(VecWAXPY(forces_.f_res, -1.0, forces_.f_int, forces_.f_ext));
  // The start of the next increment: applied loads, the contact nodes' forces
  // (normal and friction; the pending forces are in f_app) and the inertia
  // force, which the internal force of the stresses balances.
  PetscCall(VecCopy(forces_.f_app, forces_.f_start));
  if (contact_ && contact_->active()) PetscCall(contact_->AddNodeForces(forces_.f_start));
  if (inertia_ && inertia_->active()) {
    PetscCall(VecScale(forces_.f_start, -1.0));
    PetscCall(inertia_->AddForce(forces_.f_start));
    PetscCall(VecScale(forces_.f_start, -1.0));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Problem::Record(PetscInt inc, double lambda0, double lambda, const Increment &taken,
                               const Committed &done, Vec du)
{
  HistoryRow row;

  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(Log::measure, 0, 0, 0, 0));
  PetscCall(StepColumns(inc, lambda, taken, done, row));
  PetscCall(ContactColumns(&done.contact, row));
  PetscCall(scene_->Measure(*model_, lambda, forces_.f_int, row));
  PetscCall(EnergyColumns(lambda0, lambda, done, du, row));
  // NaN, or Inf where it can only come from an overflow, is never written:
  // the run stops at the increment before (Run reads nonfinite_).
  for (const auto &col : history_.columns())
    if (std::isnan(col.Of(row)) || (std::isinf(col.Of(row)) && !col.may_be_infinite)) {
      nonfinite_ = col.name;
      PetscCall(PetscLogEventEnd(Log::measure, 0, 0, 0, 0));
      PetscFunctionReturn(PETSC_SUCCESS);
    }
  history_.Append(row);
  PetscCall(PetscLogEventEnd(Log::measure, 0, 0, 0, 0));
  PetscCall(WatchEnergy(inc, lambda, row));
  if (opt_.monitor) PetscCall(PrintMonitor(inc, lambda, taken, row));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Problem::StepColumns(PetscInt inc, double lambda, const Increment &taken, const Committed &done,
                                    HistoryRow &row)
{
  double residual;

  PetscFunctionBeginUser;
  // Forces on the new geometry (f_int + M a: what the loads and reactions
  // balance), the mean of start and end for the trapezoidal work, the
  // out-of-balance force of the free dofs.
  PetscCall(EndForces(lambda));
  for (auto [start, now] : {std::pair{forces_.f_app0, forces_.f_app}, std::pair{forces_.f_ext0, forces_.f_ext},
                            std::pair{forces_.f_int0, forces_.f_int}})
    PetscCall(VecAXPBY(start, 0.5, 0.5, now));
  double r_max;
  PetscCall(system_.FreeNorms(forces_.f_res, residual, r_max));
  q_sum_ += q_now_, q_count_ += 1;

  row.increment = inc;
  row.rmin = taken.r;
  row.limiter = static_cast<double>(taken.who);
  row.limiter_where = taken.where;
  row.n_plastic = done.body.n_plastic;
  row.friction_iters = taken.solves;
  row.residual = residual;
  row.r_max = r_max;
  int sign;
  PetscCall(system_.DeterminantSign(sign));
  row.det_sign = sign;
  row.q_avg = q_sum_ / q_count_;
  row.redo = taken.redo;
  row.drift = done.body.drift;
  row.unsettled = unsettled_;
  row.events_inside = events_inside_;
  row.inconsistent = inconsistent_;
  row.inertia = inertia_ && inertia_->active() ? 1 : 0;
  Body::ReleaseYield release;
  PetscCall(body_.MeasureRelease(release));
  row.release = release.releasing ? (release.elastic ? 2 : 1) : 0, row.release_yielded = release.reached,
  row.release_excess = release.excess, row.release_dep = release.dep;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Problem::EnergyColumns(double lambda0, double lambda, const Committed &done, Vec du, HistoryRow &row)
{
  PetscFunctionBeginUser;
  // Check (a)'s input: from the reported load and stroke (and the scene's
  // applied loads) where the scene says they are work-conjugate in this
  // stage; else the work of the loads and supports at the nodes plus what
  // friction dissipated (the tools' side of it).
  const HistoryRow &prev = history_.rows().back();
  const double share = scene_->LoadWorkShare(0.5 * (lambda0 + lambda));
  double dw_in;
  if (share > 0) {
    const double dw_tool = scene_->ToolWork(prev, row, share);
    PetscCall(system_.ExternalWork(forces_.f_app0, nullptr, du, dw_in));
    dw_in += dw_tool;
    energy_.w_tool += dw_tool;
  } else {
    PetscCall(system_.ExternalWork(forces_.f_ext0, forces_.f_int0, du, dw_in));
    dw_in += done.contact.w_friction;
  }
  energy_.w_ext += dw_in;
  energy_.w_friction += done.contact.w_friction;
  energy_.w_int += done.body.dw_int;
  energy_.w_plastic += done.body.dw_plastic;
  energy_.w_inertia += done.dw_inertia;
  energy_.TakePeaks();
  row.w_ext = energy_.w_ext;
  row.w_tool = energy_.w_tool;
  row.w_int = energy_.w_int;
  row.w_plastic = energy_.w_plastic;
  row.w_friction = energy_.w_friction;
  row.w_inertia = energy_.w_inertia;
  PetscCall(body_.ElasticEnergy(row.w_elastic));
  if (inertia_ && inertia_->active()) PetscCall(inertia_->KineticEnergy(row.w_kinetic));
  row.w_damped = energy_.w_inertia - row.w_kinetic;
  row.energy_error = energy_.BalanceError();
  row.internal_error = energy_.InternalError(row.w_elastic);
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Problem::WatchEnergy(PetscInt inc, double lambda, const HistoryRow &row)
{
  PetscFunctionBeginUser;
  if (inc <= kEnergyWarningAfter) PetscFunctionReturn(PETSC_SUCCESS);
  worst_error_ = std::max(worst_error_, std::abs(row.energy_error));
  worst_internal_ = std::max(worst_internal_, std::abs(row.internal_error));
  if (!warned_ && std::abs(row.energy_error) > kEnergyWarning) {
    warned_ = true;
    PetscCall(PetscPrintf(
      comm_,
      "tubeform: warning: energy balance error %.1f %% at increment %d (lambda %.4f): the "
      "solution is drifting from equilibrium; try shorter steps (more -increments, a smaller -rmin_deps), or see "
      "docs/theory.md\n",
      100 * row.energy_error, (int)inc, lambda));
  }
  diverged_ = std::abs(row.energy_error) > opt_.driver.max_energy_error;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Problem::PrintMonitor(PetscInt inc, double lambda, const Increment &taken, const HistoryRow &row)
{
  PetscFunctionBeginUser;
  const std::string where = taken.where >= 0 ? " @" + std::to_string(taken.where) : "";
  PetscCall(PetscPrintf(comm_, "inc %5d  lambda %.5f  stroke %-11.5g load %-11.5g r_min %.3g (%s%s)", (int)inc, lambda,
                        row.stroke, row.load, taken.r, LimiterName((int)taken.who), where.c_str()));
  PetscCall(PetscPrintf(comm_, "  plastic %d  contact %d  iters %d", (int)row.n_plastic, (int)row.n_contact,
                        (int)taken.solves));
  // The out-of-balance force as the equilibrium criterion reads it: the
  // largest on a free dof against the time-averaged nodal force.
  PetscCall(PetscPrintf(comm_, "  R_max %.2e (%.1e q)  energy err %.1e\n", row.r_max,
                        row.r_max / std::max(row.q_avg, kTiny), row.energy_error));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Problem::WriteFields(ResultWriter &writer, PetscInt step, double t)
{
  std::vector<CellField> cells = {{"sigma_xx", {}},  {"sigma_yy", {}}, {"sigma_zz", {}}, {"sigma_xy", {}},
                                  {"von_mises", {}}, {"eps_p", {}},    {"plastic", {}}};
  PetscFunctionBeginUser;
  if (opt_.output.empty()) PetscFunctionReturn(PETSC_SUCCESS); // (a companion run: no files)
  for (auto &c : cells) c.values.assign(mesh_.num_cells, 0.0);
  // Cell values are Gauss-point averages.
  for (PetscInt e = 0; e < mesh_.num_cells; ++e)
    for (int g = 0; g < fe::kGauss; ++g) {
      const PointState &ps = body_.state()[fe::kGauss * e + g];
      const Voigt &s = ps.sigma;
      const double vals[7] = {s[0], s[1], s[2], s[3], VonMises(s), ps.ep, ps.plastic ? 1.0 : 0.0};
      for (int k = 0; k < 7; ++k) cells[k].values[e] += vals[k] / fe::kGauss;
    }
  // Anisotropic yield: the material's radial axis (degrees from x; the cell's mean of its points').
  if (body_.material().anisotropic()) {
    CellField f{"material_axes", std::vector<double>(mesh_.num_cells, 0.0)};
    for (PetscInt e = 0; e < mesh_.num_cells; ++e)
      for (int g = 0; g < fe::kGauss; ++g)
        f.values[e] += body_.state()[fe::kGauss * e + g].frame * 180 / M_PI / fe::kGauss;
    cells.push_back(std::move(f));
  }
  // Kinematic hardening: the sum of the backstresses (the yield surface's centre).
  if (body_.material().backstresses() > 0) {
    const char *names[kNumStress] = {"backstress_xx", "backstress_yy", "backstress_zz", "backstress_xy"};
    for (int c = 0; c < kNumStress; ++c) {
      CellField f{names[c], std::vector<double>(mesh_.num_cells, 0.0)};
      for (PetscInt e = 0; e < mesh_.num_cells; ++e)
        for (int g = 0; g < fe::kGauss; ++g)
          for (int b = 0; b < body_.material().backstresses(); ++b)
            f.values[e] += body_.state()[fe::kGauss * e + g].back[b][c] / fe::kGauss;
      cells.push_back(std::move(f));
    }
  }
  // Node fields: the displacement and, with a tool, each node's contact state
  // (0 free, 1 in contact) and its contact force in the global frame (N/mm).
  std::vector<NodeField> nodes = {{"displacement_u", 2, body_.displacement()}};
  if (contact_) {
    NodeField state{"contact_state", 1, std::vector<double>(mesh_.num_nodes, 0.0)};
    NodeField force{"contact_force", 2, std::vector<double>(2 * mesh_.num_nodes, 0.0)};
    Vec f = system_.CreateLocalVector();
    const PetscScalar *a;
    PetscCall(VecZeroEntries(f));
    PetscCall(contact_->AddContactForces(f)); // none once the tools are removed (springback)
    PetscCall(VecGetArrayRead(f, &a));
    for (PetscInt n = 0; n < mesh_.num_nodes; ++n) {
      state.values[n] = contact_->InContact(n) ? 1.0 : 0.0;
      for (int k = 0; k < 2; ++k) force.values[2 * n + k] = PetscRealPart(a[mesh_.node_dof[n] + k]);
    }
    PetscCall(VecRestoreArrayRead(f, &a));
    PetscCall(VecDestroy(&f));
    nodes.push_back(std::move(state));
    nodes.push_back(std::move(force));
  }
  // The tools' outlines where they are (kept at every step once written: in place after the paper's
  // unloading removed them).
  std::vector<ToolShape> tools;
  for (int k = 0; contact_ && k < contact_->num_tools(); ++k) {
    Tool start = contact_->tool(k);
    start.stroke = 0;
    const Outline o = ToolOutline(contact_->tool(k)), o0 = ToolOutline(start);
    ToolShape shape{contact_->tool(k).name, {}, {}, {}};
    for (const Vec2 &p : o0.points) shape.xy0.insert(shape.xy0.end(), {p[0], p[1]});
    for (const Vec2 &p : o.points) shape.xy.insert(shape.xy.end(), {p[0], p[1]});
    for (const auto &l : o.lines) shape.lines.insert(shape.lines.end(), {l[0], l[1]});
    tools.push_back(std::move(shape));
  }
  PetscCall(writer.WriteStep(step, t, nodes, cells, tools));
  PetscFunctionReturn(PETSC_SUCCESS);
}

} // namespace tf
