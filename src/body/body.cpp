#include "tubeform/body/body.hpp"

#include <algorithm>
#include <cmath>

#include "tubeform/core/log.hpp"
#include "tubeform/material/factory.hpp"
#include "tubeform/material/j2.hpp"

namespace tf {

void GatherCell(const Mesh &mesh, PetscInt e, const PetscScalar *v, fe::ElemVec &ve)
{
  for (int a = 0; a < fe::kNodes; ++a) {
    const PetscInt n = mesh.cell_nodes[fe::kNodes * e + a];
    ve[2 * a] = PetscRealPart(v[mesh.node_dof[n]]);
    ve[2 * a + 1] = PetscRealPart(v[mesh.node_dof[n] + 1]);
  }
}

PetscErrorCode Body::Setup(const Mesh &mesh, const BodyParams &prm)
{
  PetscFunctionBeginUser;
  mesh_ = &mesh;
  prm_ = prm;
  // Before a point has yielded, H' is the secant over one strain-limit step.
  material_ = MakeMaterial(prm.material, prm.rmin_deps, prm.drift_correction, prm.plastic_update);
  deps_limit_ = prm.rmin_deps;
  if (prm.rmin_deps_yield > 0 && material_->plastic_law())
    deps_limit_ = std::min(deps_limit_, prm.rmin_deps_yield * material_->YieldStress(0.0) / prm.material.E);
  cells_ = fe::CellFormulation(prm.element, (int)mesh.num_cells);
  state_.assign(fe::kGauss * mesh.num_cells, PointState{});
  if (material_->anisotropic())
    for (PetscInt e = 0; e < mesh.num_cells; ++e) {
      double xe[2 * fe::kNodes], xg[fe::kGauss][2];
      for (int a = 0; a < fe::kNodes; ++a)
        for (int k = 0; k < 2; ++k) xe[2 * a + k] = mesh.x0[2 * mesh.cell_nodes[fe::kNodes * e + a] + k];
      fe::GaussPoints(xe, xg);
      for (int g = 0; g < fe::kGauss; ++g)
        state_[fe::kGauss * e + g].frame =
          prm.material.axes == MaterialAxes::Tube ? std::atan2(xg[g][1], xg[g][0]) : prm.material.axes_angle;
    }
  yield_factor_.assign(state_.size(), kNever);
  fraction_.assign(state_.size(), 1.0);
  onset_.assign(state_.size(), PointState{});
  ke_.resize(mesh.num_cells);
  ke_stale_.assign(mesh.num_cells, 1);
  block_.assign(mesh.num_cells, kBlockStart);
  held_.resize(mesh.num_cells);
  x_ = mesh.x0;
  u_.assign(2 * mesh.num_nodes, 0.0);
  PetscFunctionReturn(PETSC_SUCCESS);
}

void Body::CellCoordinates(PetscInt cell, double xe[2 * fe::kNodes]) const
{
  for (int a = 0; a < fe::kNodes; ++a) {
    const PetscInt n = mesh_->cell_nodes[fe::kNodes * cell + a];
    xe[2 * a] = x_[2 * n];
    xe[2 * a + 1] = x_[2 * n + 1];
  }
}

const fe::QuadGeometry *Body::CellGeometry(PetscInt e, double xe[2 * fe::kNodes]) const
{
  CellCoordinates(e, xe);
  if (!geometry_.valid) {
    geometry_.geo.resize(mesh_->num_cells);
    geometry_.ok.resize(mesh_->num_cells);
    double x[2 * fe::kNodes];
    for (PetscInt c = 0; c < mesh_->num_cells; ++c) {
      CellCoordinates(c, x);
      geometry_.ok[c] = fe::ComputeGeometry(x, geometry_.geo[c]);
    }
    geometry_.valid = true;
  }
  return geometry_.ok[e] ? &geometry_.geo[e] : nullptr;
}

bool Body::OwnLoading(size_t i, const Voigt &deps) const
{
  PointState start = state_[i];
  start.plastic = false;
  return material_->Loading(start, deps);
}

bool Body::ScanTransition(size_t i, const Voigt &deps, double omega, bool apply)
{
  const double m = std::min(1.0, yield_factor_[i]);
  if (!(std::abs(m - fraction_[i]) > prm_.yield_tol)) return false;
  if (!apply) return true;
  fraction_[i] = m;
  Stale(i);
  if (m < 1) onset_[i] = OnsetState(state_[i], deps, omega, m); // (on the linear elastic path)
  return true;
}

void Body::StepTangents(bool on)
{
  if (!material_->has_step_tangent() || on == step_tangents_) return;
  step_tangents_ = on;
  for (size_t i = 0; i < state_.size(); ++i)
    if (state_[i].plastic) Stale(i);
}

void Body::ResetTransitions()
{
  for (size_t i = 0; i < fraction_.size(); ++i)
    if (fraction_[i] < 1) fraction_[i] = 1, Stale(i);
}

void Body::ScaleTransitions(double factor)
{
  for (size_t i = 0; i < fraction_.size(); ++i)
    if (fraction_[i] < 1) fraction_[i] = std::min(1.0, fraction_[i] / factor), Stale(i);
}

PetscErrorCode Body::ScanTrial(Vec du_local, bool apply, StepLimit &limit, PetscInt &switches, PetscInt &transitions)
{
  const PetscScalar *du;
  double xe[2 * fe::kNodes];
  PetscInt local_switches = 0, local_transitions = 0;
  StepLimit yield, strain, rotation;

  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(Log::scan, 0, 0, 0, 0));
  PetscCall(VecGetArrayRead(du_local, &du));
  // Kinematics of every point (the trial increment is linear in r on the
  // start configuration), r2 and r3; then, with a plastic law only, the
  // loading states, r1 and the transitions (event TfYield).
  trial_.resize(state_.size());
  for (PetscInt e = 0; e < mesh_->num_cells; ++e) {
    fe::ElemVec due;
    const fe::QuadGeometry *geo = CellGeometry(e, xe);
    if (!geo) continue;
    GatherCell(*mesh_, e, du, due);
    for (int g = 0; g < fe::kGauss; ++g) {
      auto &[deps, omega] = trial_[fe::kGauss * e + g];
      cells_.Kinematics((int)e, xe, *geo, g, due, deps, omega);
      strain.Offer(StrainFactor(deps, deps_limit_), Limiter::Strain, mesh_->cell_orig[e]);
      rotation.Offer(RotationFactor(omega, prm_.rmin_domega), Limiter::Rotation, mesh_->cell_orig[e]);
    }
  }
  if (material_->plastic_law()) {
    PetscCall(PetscLogEventBegin(Log::yield, 0, 0, 0, 0));
    for (PetscInt e = 0; e < mesh_->num_cells; ++e) {
      if (!geometry_.ok[e]) continue; // inverted (the first loop made the cache)
      for (int g = 0; g < fe::kGauss; ++g) {
        const size_t i = fe::kGauss * e + g;
        const auto &[deps, omega] = trial_[i];
        PointState &ps = state_[i];
        // Own tangents: the state AdvanceCell selects (OwnLoading).
        const bool loading = OwnTangents() ? OwnLoading(i, deps) : material_->Loading(ps, deps);
        if (loading != ps.plastic) {
          ++local_switches;
          if (apply) ps.plastic = loading, Stale(i);
        }
        PointState start = ps;
        if (OwnTangents()) start.plastic = loading; // (the onset of the selected state)
        const double r1 = yield_factor_[i] = material_->YieldOnset(start, deps, omega);
        if (!prm_.yield_inside) {
          yield.Offer(r1, Limiter::Yield, mesh_->cell_orig[e]);
        } else if (!ps.plastic) {
          local_transitions += r1 < 1;
          local_switches += ScanTransition(i, deps, omega, apply);
        }
      }
    }
    PetscCall(PetscLogEventEnd(Log::yield, 0, 0, 0, 0));
  }
  PetscCall(VecRestoreArrayRead(du_local, &du));
  {
    PetscInt local[2] = {local_switches, local_transitions}, global[2];
    PetscCall(MPIU_Allreduce(local, global, 2, MPIU_INT, MPI_SUM, comm()));
    switches = global[0];
    transitions = global[1];
  }
  for (StepLimit *l : {&yield, &strain, &rotation}) {
    PetscCall(ReduceStepLimit(comm(), *l));
    limit.Offer(l->r, l->who, l->where);
  }
  PetscCall(PetscLogEventEnd(Log::scan, 0, 0, 0, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Body::Commit(Vec du_local, double r, CommitInfo &info)
{
  const PetscScalar *du;
  Advanced acc;
  double sums[3], global_sums[3];

  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(Log::commit, 0, 0, 0, 0));
  PetscCall(VecGetArrayRead(du_local, &du));
  PetscInt n;
  PetscCall(VecGetLocalSize(du_local, &n));
  if (last_trial_.valid && last_trial_.r == r && (PetscInt)last_trial_.du.size() == n &&
      std::equal(du, du + n, last_trial_.du.begin())) {
    // The equilibrium iterations evaluated this very increment last: its states.
    state_.swap(last_trial_.states);
    acc = last_trial_.acc;
    if (cells_.has_modes())
      for (PetscInt e = 0; e < mesh_->num_cells; ++e) cells_.SetCommitted((int)e, last_trial_.conds[e]);
  } else {
    std::vector<PointState> next(state_.size());
    for (PetscInt e = 0; e < mesh_->num_cells; ++e) {
      fe::ElemVec due;
      fe::Condensation used;
      GatherCell(*mesh_, e, du, due);
      PointState *to = &next[fe::kGauss * e];
      if (!AdvanceCell(e, due, r, to, acc, &used))
        for (int g = 0; g < fe::kGauss; ++g) to[g] = state_[fe::kGauss * e + g];
      if (cells_.has_modes()) cells_.SetCommitted((int)e, used);
    }
    state_.swap(next);
  }
  last_trial_.valid = false;
  for (PetscInt n = 0; n < mesh_->num_nodes; ++n)
    for (int k = 0; k < kDim; ++k) {
      const double d = PetscRealPart(du[mesh_->node_dof[n] + k]);
      x_[2 * n + k] += d;
      u_[2 * n + k] += d;
    }
  StaleAll(); // new geometry and stresses
  geometry_.valid = false;
  PetscCall(VecRestoreArrayRead(du_local, &du));
  // Sums (internal work, plastic work, plastic points: exact in a double) and a maximum (drift).
  sums[0] = acc.w_int, sums[1] = acc.w_plastic, sums[2] = (double)acc.n_plastic;
  PetscCall(MPIU_Allreduce(sums, global_sums, 3, MPIU_REAL, MPIU_SUM, comm()));
  PetscCall(MPIU_Allreduce(&acc.drift, &info.drift, 1, MPIU_REAL, MPIU_MAX, comm()));
  info.dw_int = global_sums[0];
  info.dw_plastic = global_sums[1];
  info.n_plastic = (PetscInt)global_sums[2];
  PetscCall(PetscLogEventEnd(Log::commit, 0, 0, 0, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

void Body::ActElastic(bool elastic)
{
  if (elastic == (law_ != nullptr)) return;
  if (elastic) {
    law_ = std::move(material_);
    material_ = std::make_unique<Elastic>(prm_.material.E, prm_.material.nu);
    for (auto &ps : state_) ps.plastic = false;
  } else {
    material_ = std::move(law_);
  }
  StaleAll();
}

void Body::BeginRelease(bool elastic, bool by_loads)
{
  releasing_ = true;
  release_start_.resize(kReleaseStart * state_.size());
  for (size_t i = 0; i < state_.size(); ++i) {
    release_start_[kReleaseStart * i] = material().YieldRatio(state_[i]);
    release_start_[kReleaseStart * i + 1] = state_[i].ep;
    if (by_loads) state_[i].plastic = false;
  }
  StaleAll();
  ActElastic(elastic);
}

void Body::EndRelease()
{
  releasing_ = false;
  release_start_.clear();
  ActElastic(false);
}

PetscErrorCode Body::MeasureRelease(ReleaseYield &y) const
{
  double local[2] = {0, 0}, global[2];
  PetscInt reached = 0;
  PetscFunctionBeginUser;
  y = ReleaseYield{};
  if (!releasing_) PetscFunctionReturn(PETSC_SUCCESS);
  const bool elastic = law_ != nullptr;
  y.releasing = true, y.elastic = elastic;
  for (size_t i = 0; i < state_.size(); ++i) {
    const double *start = &release_start_[kReleaseStart * i];
    if (elastic) {
      // (a point past the surface at the start, by the drift of its last plastic step, from there)
      const double excess = material().YieldRatio(state_[i]) - std::max(start[0], 1.0);
      local[0] = std::max(local[0], excess);
      reached += excess > kOnSurface;
    } else {
      const double dep = state_[i].ep - start[1];
      local[1] = std::max(local[1], dep);
      reached += dep > 0;
    }
  }
  PetscCall(MPIU_Allreduce(local, global, 2, MPIU_REAL, MPIU_MAX, comm()));
  PetscCall(MPIU_Allreduce(&reached, &y.reached, 1, MPIU_INT, MPI_SUM, comm()));
  y.excess = global[0], y.dep = global[1];
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Body::InternalForce(Vec f_local, double *magnitude, double *count) const
{
  PetscScalar *f;
  double xe[2 * fe::kNodes];

  PetscFunctionBeginUser;
  if (magnitude) *magnitude = 0;
  if (count) *count = 0;
  PetscCall(VecZeroEntries(f_local));
  PetscCall(VecGetArray(f_local, &f));
  for (PetscInt e = 0; e < mesh_->num_cells; ++e) {
    Voigt s[fe::kGauss];
    fe::ElemVec fe_;
    const fe::QuadGeometry *geo = CellGeometry(e, xe);
    if (!geo) continue;
    for (int g = 0; g < fe::kGauss; ++g) s[g] = state_[fe::kGauss * e + g].sigma;
    cells_.InternalForce((int)e, xe, *geo, s, fe_);
    if (magnitude)
      for (double v : fe_) *magnitude += std::abs(v);
    if (count) *count += 2 * fe::kNodes;
    for (int a = 0; a < fe::kNodes; ++a) {
      const PetscInt n = mesh_->cell_nodes[fe::kNodes * e + a];
      f[mesh_->node_dof[n]] += fe_[2 * a];
      f[mesh_->node_dof[n] + 1] += fe_[2 * a + 1];
    }
  }
  PetscCall(VecRestoreArray(f_local, &f));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Body::ElasticEnergy(double &w) const
{
  double xe[2 * fe::kNodes], local = 0;

  PetscFunctionBeginUser;
  for (PetscInt e = 0; e < mesh_->num_cells; ++e) {
    const fe::QuadGeometry *geo = CellGeometry(e, xe);
    if (!geo) continue;
    for (int g = 0; g < fe::kGauss; ++g)
      local += geo->wdet[g] * material_->ElasticEnergy(state_[fe::kGauss * e + g].sigma);
  }
  PetscCall(MPIU_Allreduce(&local, &w, 1, MPIU_REAL, MPIU_SUM, comm()));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Body::NonFiniteCell(PetscInt &cell) const
{
  PetscInt local = PETSC_MAX_INT;

  PetscFunctionBeginUser;
  for (PetscInt e = 0; e < mesh_->num_cells; ++e) {
    bool finite = true;
    for (int g = 0; g < fe::kGauss; ++g) {
      const PointState &p = state_[fe::kGauss * e + g];
      for (double v : p.sigma) finite = finite && std::isfinite(v);
      finite = finite && std::isfinite(p.ep);
    }
    for (int a = 0; a < fe::kNodes; ++a)
      for (int k = 0; k < 2; ++k) finite = finite && std::isfinite(x_[2 * mesh_->cell_nodes[fe::kNodes * e + a] + k]);
    if (!finite) local = std::min(local, mesh_->cell_orig[e]);
  }
  PetscCall(MPIU_Allreduce(&local, &cell, 1, MPIU_INT, MPI_MIN, comm()));
  if (cell == PETSC_MAX_INT) cell = -1;
  PetscFunctionReturn(PETSC_SUCCESS);
}

} // namespace tf
