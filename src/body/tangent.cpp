// The body's tangent K (docs/theory.md, sections 4 and 5a): the increment
// start's, kept per cell and updated where the points' tangents or the
// geometry changed, and with midpoint kinematics an equilibrium correction's at
// its iterate (the start's rows on the iterate's configuration, the columns of
// its mid-increment strain: fe/midpoint.hpp), where the start's would be off.
#include <algorithm>
#include <cmath>

#include "tubeform/body/body.hpp"
#include "tubeform/core/log.hpp"

namespace tf {

namespace {
// a - b
fe::ElemMat Difference(const fe::ElemMat &a, const fe::ElemMat &b)
{
  fe::ElemMat d;
  for (int r = 0; r < 2 * fe::kNodes; ++r)
    for (int k = 0; k < 2 * fe::kNodes; ++k) d[r][k] = a[r][k] - b[r][k];
  return d;
}
} // namespace

bool Body::RefreshCell(PetscInt e)
{
  if (!ke_stale_[e]) return true;
  Mat4 c[fe::kGauss];
  Voigt s[fe::kGauss];
  double xe[2 * fe::kNodes];
  fe::ElemMat ke;
  const fe::QuadGeometry *geo = CellGeometry(e, xe);
  StartTangents(e, c, s);
  if (!geo || !cells_.Stiffness((int)e, xe, *geo, c, s, ke)) return false; // (still stale)
  // The kept matrix's block of the cell is outdated (a start tangent: kept to be subtracted).
  if (block_[e] == kBlockStart) held_[e] = ke_[e];
  block_[e] = kBlockOutdated;
  ke_[e] = ke;
  ke_stale_[e] = 0;
  return true;
}

PetscErrorCode Body::CheckInverted(PetscInt bad, System &system) const
{
  PetscInt anybad;
  PetscFunctionBeginUser;
  PetscCall(MPIU_Allreduce(&bad, &anybad, 1, MPIU_INT, MPI_MAX, comm()));
  if (anybad >= 0) system.InvalidateBody(); // it lacks the inverted cell's block
  PetscCheck(
    anybad < 0, comm(), PETSC_ERR_USER_INPUT,
    "element %d is inverted (det J <= 0): the increment is too large (lower -rmin_deps) or the mesh is tangled",
    (int)anybad);
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Body::AssembleTangent(System &system)
{
  PetscInt bad = -1;

  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(Log::assemble, 0, 0, 0, 0));
  // Rebuilt when most cells changed (a new configuration after a commit): a
  // kept matrix updated by differences would carry their round-off along.
  long changed = 0;
  for (PetscInt e = 0; e < mesh_->num_cells; ++e) changed += ke_stale_[e] || block_[e] != kBlockStart;
  bool rebuild = 2 * changed > (long)mesh_->num_cells;
  PetscCall(system.BeginBody(rebuild));
  for (PetscInt e = 0; e < mesh_->num_cells; ++e) {
    if (!RefreshCell(e)) {
      bad = mesh_->cell_orig[e];
      continue;
    }
    if (rebuild)
      PetscCall(system.AddElement(e, ke_[e]));
    else if (block_[e] != kBlockStart)
      PetscCall(system.AddElement(e, Difference(ke_[e], held_[e])));
    block_[e] = kBlockStart;
  }
  PetscCall(system.EndBody());
  PetscCall(CheckInverted(bad, system));
  PetscCall(PetscLogEventEnd(Log::assemble, 0, 0, 0, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Body::UpdateTangents(System &system)
{
  PetscInt bad = -1;
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(Log::assemble, 0, 0, 0, 0));
  for (PetscInt e = 0; e < mesh_->num_cells; ++e)
    if (!RefreshCell(e)) bad = mesh_->cell_orig[e];
  PetscCall(CheckInverted(bad, system));
  PetscCall(PetscLogEventEnd(Log::assemble, 0, 0, 0, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

void Body::StartTangents(PetscInt e, Mat4 c[fe::kGauss], Voigt s[fe::kGauss]) const
{
  for (int g = 0; g < fe::kGauss; ++g) {
    const size_t i = fe::kGauss * e + g;
    if (fraction_[i] < 1)
      c[g] = TransitionTangent(i);
    else if (step_tangents_ && state_[i].plastic)
      c[g] = material_->StepTangent(state_[i], trial_[i].first);
    else
      c[g] = material_->Tangent(state_[i]);
    s[g] = state_[i].sigma;
  }
}

PointState Body::OnsetState(const PointState &elastic, const Voigt &deps, double omega, double m) const
{
  PointState on = elastic;
  const StressRotation turn(ObjectiveScheme::Forward, m * omega);
  turn.Apply(on.sigma);
  for (int k = 0; k < material_->backstresses(); ++k) turn.Apply(on.back[k]);
  if (material_->anisotropic()) on.frame += turn.Angle();
  material_->Update(on, Scaled(deps, m));
  on.plastic = true;
  return on;
}

Mat4 Body::TransitionTangent(const PointState &elastic, const PointState &onset, double m) const
{
  const Mat4 de = material_->Tangent(elastic), dep = material_->Tangent(onset);
  Mat4 c;
  for (int r = 0; r < 4; ++r)
    for (int k = 0; k < 4; ++k) c[r][k] = m * de[r][k] + (1 - m) * dep[r][k];
  return c;
}

PetscErrorCode Body::AssembleIterateTangent(System &system)
{
  fe::ElemMat ki;

  PetscFunctionBeginUser;
  PetscCheck(last_trial_.valid, comm(), PETSC_ERR_ORDER, "the iterate's tangent needs its forces first (TrialForce)");
  PetscCall(PetscLogEventBegin(Log::assemble, 0, 0, 0, 0));
  // Every cell takes the iterate's tangent (IterateTangent: K/G past kNearlyIncompressible), or the start's where
  // the iterate inverts it: the whole body assembled again, each block kept for AssembleTangent's differences.
  bool rebuild = true;
  PetscCall(system.BeginBody(rebuild));
  for (PetscInt e = 0; e < mesh_->num_cells; ++e) {
    const bool iterate = IterateCellTangent(e, ki);
    PetscCall(system.AddElement(e, iterate ? ki : ke_[e]));
    if (iterate) held_[e] = ki;
    block_[e] = iterate ? kBlockIterate : kBlockStart;
  }
  PetscCall(system.EndBody());
  PetscCall(PetscLogEventEnd(Log::assemble, 0, 0, 0, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

bool Body::IterateCellTangent(PetscInt e, fe::ElemMat &ke) const
{
  Mat4 c[fe::kGauss];
  Voigt s[fe::kGauss];
  double xs[2 * fe::kNodes], x1[2 * fe::kNodes];
  fe::ElemVec due;
  fe::QuadGeometry rows;
  fe::MidpointColumns m;
  // The forces of the iterate are taken on its configuration x1 = xs + du: the
  // rows' (with the start's point tangents and stresses); the columns are the
  // derivative of its strain on the mid configuration, from its own velocity
  // gradients (QM6: its balanced modes included).
  if (!CellGeometry(e, xs)) return false;
  GatherCell(*mesh_, e, last_trial_.du.data(), due);
  for (int k = 0; k < 2 * fe::kNodes; ++k) x1[k] = xs[k] + due[k];
  if (!fe::ComputeGeometry(x1, rows) || !fe::LinearizeMidpoint(xs, due, &last_trial_.grad[fe::kGauss * e], m))
    return false;
  StartTangents(e, c, s);
  return cells_.MidpointStiffness(rows, c, s, m, ke);
}

} // namespace tf
