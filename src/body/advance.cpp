// The state an increment takes the body's points to (AdvanceCell,
// AdvancePoint: shared by the commit and the trial), and the internal force
// of a trial increment's state without committing it, which the equilibrium
// iterations of an increment need (docs/theory.md, "Equilibrium iterations").
#include <algorithm>
#include <cmath>

#include "tubeform/body/body.hpp"
#include "tubeform/core/log.hpp"
#include "tubeform/material/j2.hpp"

namespace tf {

namespace {
// Passes of the fixed point between a cell's loading states and its modes'
// condensation (AdvanceCell): a state switched by the new condensation's
// modes is itself at the loading/unloading boundary.
constexpr int kSelectPasses = 3;
// Elastic fractions m (of the step before a point's yield onset) that move by
// less than this between passes select the same tangent.
constexpr double kSelectTol = 1e-6;
} // namespace

bool Body::SelectStates(PetscInt e, const double xs[2 * fe::kNodes], const fe::QuadGeometry &gs, const fe::ElemVec &due,
                        const fe::Condensation &cond, Selected sel[fe::kGauss]) const
{
  bool differ = false;
  const fe::InternalVec alpha = fe::CellFormulation::ModesOf(cond, due);
  for (int g = 0; g < fe::kGauss; ++g) {
    const size_t i = fe::kGauss * e + g;
    Selected &p = sel[g];
    cells_.KinematicsWith(xs, gs, g, due, alpha, p.deps, p.omega);
    p.plastic = OwnLoading(i, p.deps);
    p.m = 1;
    if (!p.plastic && prm_.yield_inside) {
      PointState start = state_[i];
      start.plastic = false;
      p.m = std::min(1.0, material_->YieldOnset(start, p.deps, p.omega));
    }
    // The assembled tangent is this one when the loading state and the elastic
    // fraction are the same (ScanTrial took both from the same increment).
    differ = differ || p.plastic != state_[i].plastic || p.m != fraction_[i];
  }
  return differ;
}

void Body::SelectedTangents(PetscInt e, const Selected sel[fe::kGauss], Mat4 c[fe::kGauss]) const
{
  for (int g = 0; g < fe::kGauss; ++g) {
    const Selected &p = sel[g];
    PointState ps = state_[fe::kGauss * e + g];
    ps.plastic = p.plastic;
    c[g] = p.m < 1 ? TransitionTangent(ps, OnsetState(ps, p.deps, p.omega, p.m), p.m) : material_->Tangent(ps);
  }
}

void Body::SelectCondensation(PetscInt e, const double xs[2 * fe::kNodes], const fe::QuadGeometry &start,
                              const fe::ElemVec &due, fe::Condensation &own, fe::ModeMatrix &own_kii_inv,
                              const fe::Condensation *&cond, const fe::ModeMatrix *&kii_inv) const
{
  // A fixed point: the states the modes of a condensation select, then the
  // condensation of those states, until they select themselves (from the
  // assembled one, which ScanTrial took from the last iterate's increment).
  Mat4 c[fe::kGauss];
  Voigt s[fe::kGauss];
  Selected sel[fe::kGauss], last[fe::kGauss];
  const auto same = [](const Selected &a, const Selected &b) {
    return a.plastic == b.plastic && std::abs(a.m - b.m) <= kSelectTol;
  };
  for (int g = 0; g < fe::kGauss; ++g) s[g] = state_[fe::kGauss * e + g].sigma;
  for (int pass = 0; pass < kSelectPasses; ++pass) {
    const bool differ = SelectStates(e, xs, start, due, *cond, sel);
    if (pass == 0 && !differ) break;
    if (pass > 0 && std::equal(sel, sel + fe::kGauss, last, same)) break;
    SelectedTangents(e, sel, c);
    if (!cells_.Condense(xs, start, c, s, own, own_kii_inv)) break;
    cond = &own, kii_inv = &own_kii_inv;
    std::copy(sel, sel + fe::kGauss, last);
  }
}

bool Body::AdvanceCell(PetscInt e, const fe::ElemVec &due, double r, PointState *to, Advanced &acc,
                       fe::Condensation *used, fe::Gradient *grad) const
{
  fe::QuadGeometry mid, moved;
  double xe[2 * fe::kNodes], xm[2 * fe::kNodes], xs[2 * fe::kNodes];
  const bool midpoint = prm_.kinematics == ObjectiveScheme::Midpoint;
  // Gradients on the start configuration (the paper's forward form: the
  // cached geometry), or on the mid-increment one (Hughes-Winget: a rigid
  // rotation then gives zero strain and an exact rotation of the stress).
  const fe::QuadGeometry *geo = CellGeometry(e, xe);
  const fe::QuadGeometry *start = geo;
  if (used && cells_.has_modes()) *used = cells_.assembled((int)e); // (unless the own one below)
  for (int k = 0; k < 2 * fe::kNodes; ++k) xs[k] = xe[k], xm[k] = xe[k] + due[k];
  if (midpoint) {
    for (int k = 0; k < 2 * fe::kNodes; ++k) xe[k] += 0.5 * due[k];
    geo = fe::ComputeGeometry(xe, mid) ? &mid : nullptr;
  }
  if (!geo) return false; // reported by the next assembly
  // QM6 with equilibrium iterations: the increment's modes are the cell's own
  // unknowns, corrected (alpha -= Kii^{-1} f_i, f_i on the moved cell) until
  // their force vanishes, so that the cell's nodal forces are those of a state
  // in balance inside it and the condensed tangent is their derivative.
  const bool balance = prm_.state_from_strain && cells_.has_modes() && fe::ComputeGeometry(xm, moved);
  // The condensation they take is that of the tangents the increment itself
  // selects (the assembled one where those are the assembled tangents): the
  // forces are then a function of the nodal increments, whatever loading
  // states the assembly took (docs/theory.md, 5a).
  fe::Condensation own;
  fe::ModeMatrix own_kii_inv;
  const fe::Condensation *cond = balance ? &cells_.assembled((int)e) : nullptr;
  const fe::ModeMatrix *kii_inv = balance ? &cells_.assembled_kii_inv((int)e) : nullptr;
  if (balance && OwnTangents()) SelectCondensation(e, xs, *start, due, own, own_kii_inv, cond, kii_inv);
  if (used && balance) *used = *cond;
  fe::InternalVec alpha = balance ? fe::CellFormulation::ModesOf(*cond, due) : fe::InternalVec{};
  for (int it = 0;; ++it) {
    // Without balancing (one pass) the sums go straight into acc, in the order they always did.
    Advanced local;
    Advanced &sink = balance ? local : acc;
    for (int g = 0; g < fe::kGauss; ++g) {
      Voigt deps;
      double omega;
      if (balance)
        cells_.KinematicsWith(xe, *geo, g, due, alpha, deps, omega);
      else
        cells_.Kinematics((int)e, xe, *geo, g, due, deps, omega);
      to[g] = AdvancePoint(fe::kGauss * e + g, deps, omega, r, geo->wdet[g], sink);
      // (zz is the mean dilatation's part of xx and yy; omega = (L_xy - L_yx) / 2)
      if (grad) grad[g] = {deps[0] - deps[2], 0.5 * deps[3] + omega, 0.5 * deps[3] - omega, deps[1] - deps[2]};
    }
    // A fixed number of corrections (not a tolerance): the forces are then a
    // smooth function of the nodal increments, which the Newton iterations of
    // the increment need.
    const bool done = !balance || it == kModeCorrections;
    if (!done) {
      Voigt s[fe::kGauss];
      fe::InternalVec fi;
      for (int g = 0; g < fe::kGauss; ++g) s[g] = to[g].sigma;
      cells_.ModeForce(xm, moved, s, fi);
      fe::CellFormulation::CorrectModesOf(*kii_inv, fi, alpha);
    }
    if (done) {
      if (balance) {
        acc.w_int += local.w_int, acc.w_plastic += local.w_plastic, acc.n_plastic += local.n_plastic;
        acc.drift = std::max(acc.drift, local.drift);
      }
      return true;
    }
  }
}

PointState Body::AdvancePoint(size_t i, const Voigt &deps, double omega, double r, double wdet, Advanced &acc) const
{
  const bool midpoint = prm_.kinematics == ObjectiveScheme::Midpoint;
  PointState ps = state_[i];
  // Strang splitting: half the rotation, the constitutive increment in the
  // mid-rotated frame, the other half (forward scheme: all at once, first order).
  const StressRotation turn(prm_.kinematics, omega, midpoint ? 0.5 : 1.0);
  // (the material's own backstresses and axes turn with the spin in an elastic release too)
  const int nback = material().backstresses();
  const bool axes = material().anisotropic();
  turn.Apply(ps.sigma);
  for (int k = 0; k < nback; ++k) turn.Apply(ps.back[k]);
  if (axes) ps.frame += turn.Angle();
  // The internal work is taken in the frame of the constitutive increment: the
  // stress turned by the first half rotation and the updated one before the
  // second (midpoint); the forward scheme's start stress as it always was.
  const Voigt before = midpoint ? ps.sigma : state_[i].sigma;
  // yield_inside: a point that meets the surface inside the step takes the
  // part up to it elastically and the rest with the plastic law.
  const double yf = yield_factor_[i];
  // With equilibrium iterations the update is a function of the strain
  // increment alone: a point on the yield surface flows if it loads, whatever
  // loading state its tangent took (the iterations may cycle the tangent of
  // a point at the loading/unloading boundary; the forces then stay continuous).
  // So is the onset of yield inside the step: found on this strain increment's
  // own stress path (the stored yield factor is its trial's).
  double onset = prm_.yield_inside ? yf / r : kNever;
  if (prm_.state_from_strain && material_->plastic_law()) {
    ps.plastic = material_->OnSurface(ps);
    // (the onset of a point off the surface, whatever its last increment's flag)
    PointState start = state_[i];
    start.plastic = false;
    onset = ps.plastic ? kNever : material_->YieldOnset(start, deps, omega);
  }
  UpdateInfo u;
  if (material_->plastic_law() && !ps.plastic && onset < 1) {
    const double m = onset;
    material_->Update(ps, Scaled(deps, m));
    ps.plastic = true;
    u = material_->Update(ps, Scaled(deps, 1 - m));
  } else {
    u = material_->Update(ps, deps);
  }
  const Voigt after = ps.sigma;
  if (midpoint) {
    turn.Apply(ps.sigma);
    for (int k = 0; k < nback; ++k) turn.Apply(ps.back[k]);
    if (axes) ps.frame += turn.Angle();
  }
  // Points that reach the yield surface in this increment (the limiter and
  // those grouped with it), or pass it, are plastic from now on.
  const bool reached = !prm_.yield_inside && !prm_.state_from_strain && yf <= r * (1 + prm_.group_tol);
  const bool on_surface = material_->OnSurface(ps);
  if (!ps.plastic && material_->plastic_law() && (reached || on_surface)) ps.plastic = true;
  acc.n_plastic += ps.plastic;
  for (int c = 0; c < kNumStress; ++c)
    acc.w_int += wdet * 0.5 * (before[c] + (midpoint ? after[c] : ps.sigma[c])) * deps[c];
  acc.w_plastic += wdet * u.dwp;
  acc.drift = std::max(acc.drift, std::abs(u.drift));
  return ps;
}

PetscErrorCode Body::TrialForce(Vec du_local, double r, Vec f_local, double *magnitude, double *count) const
{
  const PetscScalar *du;
  PetscScalar *f;
  Advanced acc;

  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(Log::trial, 0, 0, 0, 0));
  *magnitude = *count = 0;
  PetscCall(VecGetArrayRead(du_local, &du));
  PetscCall(VecZeroEntries(f_local));
  PetscCall(VecGetArray(f_local, &f));
  // The states are kept: a commit of the same increment takes them (Commit).
  PetscInt n;
  PetscCall(VecGetLocalSize(du_local, &n));
  last_trial_.du.assign(du, du + n);
  last_trial_.r = r;
  last_trial_.states.resize(state_.size());
  if (cells_.has_modes()) last_trial_.conds.resize(mesh_->num_cells);
  last_trial_.grad.assign(state_.size(), fe::Gradient{});
  for (PetscInt e = 0; e < mesh_->num_cells; ++e) {
    fe::ElemVec due, fe_;
    PointState *to = &last_trial_.states[fe::kGauss * e];
    Voigt s[fe::kGauss];
    fe::Condensation cond;
    GatherCell(*mesh_, e, du, due);
    const bool advanced = AdvanceCell(e, due, r, to, acc, &cond, &last_trial_.grad[fe::kGauss * e]);
    if (cells_.has_modes()) last_trial_.conds[e] = cond;
    if (!advanced) { // inverted: the next assembly reports it
      for (int g = 0; g < fe::kGauss; ++g) to[g] = state_[fe::kGauss * e + g];
      continue;
    }
    // Forces of the new stresses on the moved corners (as the commit's next InternalForce).
    double xe[2 * fe::kNodes];
    fe::QuadGeometry geo;
    CellCoordinates(e, xe);
    for (int k = 0; k < 2 * fe::kNodes; ++k) xe[k] += due[k];
    if (!fe::ComputeGeometry(xe, geo)) continue;
    for (int g = 0; g < fe::kGauss; ++g) s[g] = to[g].sigma;
    if (cells_.has_modes())
      cells_.InternalForceOf(xe, geo, s, cond, fe_);
    else
      cells_.InternalForce((int)e, xe, geo, s, fe_);
    for (double v : fe_) *magnitude += std::abs(v);
    *count += 2 * fe::kNodes;
    for (int a = 0; a < fe::kNodes; ++a) {
      const PetscInt n = mesh_->cell_nodes[fe::kNodes * e + a];
      f[mesh_->node_dof[n]] += fe_[2 * a];
      f[mesh_->node_dof[n] + 1] += fe_[2 * a + 1];
    }
  }
  PetscCall(VecRestoreArray(f_local, &f));
  PetscCall(VecRestoreArrayRead(du_local, &du));
  last_trial_.acc = acc;
  last_trial_.valid = true;
  PetscCall(PetscLogEventEnd(Log::trial, 0, 0, 0, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

} // namespace tf
