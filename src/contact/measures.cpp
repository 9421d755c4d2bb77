// What the contact set reports: forces on the body, counts, penetration.
#include <algorithm>
#include <cmath>

#include "tubeform/contact/contact.hpp"

#include "tubeform/contact/friction.hpp"
#include "tubeform/core/log.hpp"

namespace tf {

Vec2 ContactSet::NodeForce(PetscInt node, bool with_normal) const
{
  const double fl = Frictional(node) ? friction::Force(prm_.mu, prm_.vcri, fn_[node], x_[node]) : 0.0;
  const double fn = with_normal ? fn_[node] : 0.0;
  return {fn * n_[node][0] + fl * l_[node][0], fn * n_[node][1] + fl * l_[node][1]};
}

PetscErrorCode ContactSet::AddFrictionForces(Vec f) const
{
  PetscScalar *a;
  PetscFunctionBeginUser;
  if (!friction()) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PetscLogEventBegin(Log::friction, 0, 0, 0, 0));
  PetscCall(VecGetArray(f, &a));
  for (PetscInt node : candidates_) {
    if (!SlipFree(node) || !mesh_->node_owned[node]) continue;
    const Vec2 fc = NodeForce(node, false);
    for (int k = 0; k < 2; ++k) a[mesh_->node_dof[node] + k] += fc[k];
  }
  PetscCall(VecRestoreArray(f, &a));
  PetscCall(PetscLogEventEnd(Log::friction, 0, 0, 0, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode ContactSet::AddNodeForces(Vec f) const
{
  PetscScalar *a;
  PetscFunctionBeginUser;
  PetscCall(VecGetArray(f, &a));
  for (PetscInt node : candidates_) {
    if (!contact_[node] || !mesh_->node_owned[node]) continue;
    const Vec2 fc = NodeForce(node, true);
    for (int k = 0; k < 2; ++k) a[mesh_->node_dof[node] + k] += fc[k];
  }
  PetscCall(VecRestoreArray(f, &a));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode ContactSet::AddContactForces(Vec f, bool dies_only) const
{
  PetscScalar *a;
  PetscFunctionBeginUser;
  if (!dies_only) PetscCall(AddNodeForces(f));
  PetscCall(VecGetArray(f, &a));
  for (PetscInt node : candidates_) {
    if (!dies_only || !contact_[node] || !mesh_->node_owned[node] || tool_of_[node] >= num_dies_) continue;
    const Vec2 fc = NodeForce(node, true);
    for (int k = 0; k < 2; ++k) a[mesh_->node_dof[node] + k] += fc[k];
  }
  PetscCall(VecRestoreArray(f, &a));
  PetscCall(AddPendingForces(f));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode ContactSet::AddPendingForces(Vec f) const
{
  PetscScalar *a;
  PetscFunctionBeginUser;
  PetscCall(VecGetArray(f, &a));
  for (PetscInt node : candidates_)
    for (int k = 0; k < 2; ++k) a[mesh_->node_dof[node] + k] += pending_[node][k];
  PetscCall(VecRestoreArray(f, &a));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode ContactSet::TotalForce(int k, double force[2], double *moment) const
{
  double local[3] = {0, 0, 0}, global[3];
  PetscFunctionBeginUser;
  const Vec2 off = tools_[k].Offset(), o = {tools_[k].origin[0] + off[0], tools_[k].origin[1] + off[1]};
  for (PetscInt node : candidates_) {
    if (!contact_[node] || tool_of_[node] != k || !mesh_->node_owned[node]) continue;
    const Vec2 fc = NodeForce(node, true), x = Position(node);
    for (int k = 0; k < 2; ++k) local[k] += fc[k];
    local[2] += (x[0] - o[0]) * fc[1] - (x[1] - o[1]) * fc[0];
  }
  PetscCallMPI(MPI_Allreduce(local, global, 3, MPI_DOUBLE, MPI_SUM, comm()));
  force[0] = global[0], force[1] = global[1];
  if (moment) *moment = global[2];
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode ContactSet::FrictionMoment(const Vec2 &c, double &capacity) const
{
  double local = 0;
  PetscFunctionBeginUser;
  for (PetscInt node : candidates_) {
    if (!contact_[node] || !mesh_->node_owned[node] || !Frictional(node)) continue;
    const Vec2 x = Position(node), l = l_[node];
    local += prm_.mu * std::abs(fn_[node]) * std::abs((x[0] - c[0]) * l[1] - (x[1] - c[1]) * l[0]);
  }
  PetscCall(MPIU_Allreduce(&local, &capacity, 1, MPIU_REAL, MPIU_SUM, comm()));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode ContactSet::Count(PetscInt &n, bool walls) const
{
  PetscInt local = 0;
  PetscFunctionBeginUser;
  for (PetscInt node : candidates_)
    local += contact_[node] && mesh_->node_owned[node] && (walls || tool_of_[node] < num_dies_);
  PetscCall(MPIU_Allreduce(&local, &n, 1, MPIU_INT, MPI_SUM, comm()));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode ContactSet::Crossing(PlaneCrossing &c) const
{
  const int ntools = (int)tools_.size();
  struct {
    double depth;
    int where; // input number x tools + tool
  } mine = {0.0, -1}, deepest;
  PetscFunctionBeginUser;
  c = PlaneCrossing{};
  c.tol = kCrossingTol * size_;
  for (PetscInt node : candidates_)
    for (int k = 0; k < ntools && mesh_->node_owned[node]; ++k) {
      if (!MayTouch(node, k) || (contact_[node] && tool_of_[node] == k)) continue;
      const Projection pr = tools_[k].Project(Position(node));
      if (pr.segment >= 0 && -pr.gap > mine.depth) mine = {-pr.gap, (int)mesh_->node_orig[node] * ntools + k};
    }
  PetscCallMPI(MPI_Allreduce(&mine, &deepest, 1, MPI_DOUBLE_INT, MPI_MAXLOC, comm()));
  if (deepest.where < 0) PetscFunctionReturn(PETSC_SUCCESS);
  c.depth = deepest.depth;
  c.tool = deepest.where % ntools;
  c.node = deepest.where / ntools;
  // Where it is and what it touches, from the rank that owns it.
  double at[3] = {0, 0, 0}, global[3];
  for (PetscInt node : candidates_)
    if (mesh_->node_owned[node] && mesh_->node_orig[node] == c.node)
      at[0] = Position(node)[0], at[1] = Position(node)[1], at[2] = contact_[node] ? tool_of_[node] : -1;
  PetscCallMPI(MPI_Allreduce(at, global, 3, MPI_DOUBLE, MPI_SUM, comm()));
  c.x = {global[0], global[1]};
  c.held = (int)global[2];
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode ContactSet::NormalForceSum(double &sum) const
{
  double local = 0;
  PetscFunctionBeginUser;
  for (PetscInt node : candidates_)
    if (contact_[node] && mesh_->node_owned[node]) local += fn_[node];
  PetscCallMPI(MPI_Allreduce(&local, &sum, 1, MPI_DOUBLE, MPI_SUM, comm()));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode ContactSet::Penetration(double &penetration) const
{
  double local = 0;
  PetscFunctionBeginUser;
  for (PetscInt node : candidates_)
    for (int k = 0; k < (int)tools_.size(); ++k) {
      if (!MayTouch(node, k)) continue;
      const Projection pr = tools_[k].Project(Position(node));
      if (pr.segment >= 0) local = std::max(local, -pr.gap);
    }
  PetscCallMPI(MPI_Allreduce(&local, &penetration, 1, MPI_DOUBLE, MPI_MAX, comm()));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode ContactSet::NormalForceMismatch(Vec f_net, double &mismatch) const
{
  const PetscScalar *f;
  double local = 0;
  PetscFunctionBeginUser;
  PetscCall(VecGetArrayRead(f_net, &f));
  for (PetscInt node : candidates_) {
    if (!contact_[node] || global_frame_[node] || !mesh_->node_owned[node]) continue;
    const PetscInt o = mesh_->node_dof[node];
    const double fn_body = n_[node][0] * PetscRealPart(f[o]) + n_[node][1] * PetscRealPart(f[o + 1]);
    local = std::max(local, std::abs(fn_[node] - fn_body));
  }
  PetscCall(VecRestoreArrayRead(f_net, &f));
  PetscCallMPI(MPI_Allreduce(&local, &mismatch, 1, MPI_DOUBLE, MPI_MAX, comm()));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode ContactSet::NormalSpread(double &spread) const
{
  double a[3] = {0, 0, 0}, g[3];
  PetscFunctionBeginUser;
  for (PetscInt node : candidates_) {
    if (!contact_[node] || !mesh_->node_owned[node]) continue;
    // (from the node's tool where it is now: the set's frames are those of the last commit, none before the first)
    const Vec2 n = tools_[tool_of_[node]].Project(Position(node)).n;
    a[0] += n[0] * n[0], a[1] += n[0] * n[1], a[2] += n[1] * n[1];
  }
  PetscCall(MPIU_Allreduce(a, g, 3, MPIU_REAL, MPIU_SUM, comm()));
  const double trace = g[0] + g[2], root = std::sqrt(std::max(0.0, 0.25 * (g[0] - g[2]) * (g[0] - g[2]) + g[1] * g[1]));
  spread = trace > 0 ? std::max(0.0, 0.5 * trace - root) / (0.5 * trace + root) : 0.0;
  PetscFunctionReturn(PETSC_SUCCESS);
}

} // namespace tf
