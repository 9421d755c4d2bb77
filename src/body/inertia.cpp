#include "tubeform/body/inertia.hpp"

namespace tf {

PetscErrorCode Inertia::Setup(const Body &body, double rho, bool active)
{
  Vec local;
  PetscScalar *m;
  PetscFunctionBeginUser;
  const Mesh &mesh = body.mesh();
  body_ = &body;
  active_ = active;
  mass_.assign(fe::kNodes * mesh.num_cells, 0.0);
  v_.assign(2 * mesh.num_nodes, 0.0);
  a_.assign(2 * mesh.num_nodes, 0.0);
  double xe[2 * fe::kNodes];
  for (PetscInt e = 0; e < mesh.num_cells; ++e) {
    body.CellCoordinates(e, xe);
    fe::LumpedMass(xe, rho, &mass_[fe::kNodes * e]);
  }
  PetscCall(VecDestroy(&mass_global_));
  PetscCall(DMCreateGlobalVector(mesh.dm, &mass_global_));
  PetscCall(DMGetLocalVector(mesh.dm, &local));
  PetscCall(VecZeroEntries(local));
  PetscCall(VecGetArray(local, &m));
  ForEachMassShare([&](PetscInt n, double share) {
    for (int k = 0; k < 2; ++k) m[mesh.node_dof[n] + k] += share;
  });
  PetscCall(VecRestoreArray(local, &m));
  PetscCall(VecZeroEntries(mass_global_));
  PetscCall(DMLocalToGlobal(mesh.dm, local, ADD_VALUES, mass_global_));
  PetscCall(DMRestoreLocalVector(mesh.dm, &local));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Inertia::AddMass(System &system, double dt) const
{
  PetscFunctionBeginUser;
  PetscCall(system.AddDiagonal(mass_global_, 1.0 / (dt * dt)));
  PetscFunctionReturn(PETSC_SUCCESS);
}

void Inertia::AddLoad(System &system, double dt) const
{
  ForEachMassShare([&](PetscInt n, double m) {
    system.AddForce(n, m * (a_[2 * n] + v_[2 * n] / dt), m * (a_[2 * n + 1] + v_[2 * n + 1] / dt));
  });
}

PetscErrorCode Inertia::Advance(Vec du_local, double dt, double &dw_inertia)
{
  const Mesh &mesh = body_->mesh();
  const PetscScalar *du;
  double local = 0;

  PetscFunctionBeginUser;
  dw_inertia = 0;
  PetscCall(VecGetArrayRead(du_local, &du));
  if (!active_) {
    for (PetscInt n = 0; n < mesh.num_nodes; ++n)
      for (int k = 0; k < kDim; ++k) v_[2 * n + k] = PetscRealPart(du[mesh.node_dof[n] + k]) / dt;
    PetscCall(VecRestoreArrayRead(du_local, &du));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  // The work with the old and new accelerations first, then the update.
  const auto a_new = [&](PetscInt n, int k) {
    return (PetscRealPart(du[mesh.node_dof[n] + k]) / dt - v_[2 * n + k]) / dt;
  };
  ForEachMassShare([&](PetscInt n, double m) {
    for (int k = 0; k < kDim; ++k)
      local += m * 0.5 * (a_[2 * n + k] + a_new(n, k)) * PetscRealPart(du[mesh.node_dof[n] + k]);
  });
  for (PetscInt n = 0; n < mesh.num_nodes; ++n)
    for (int k = 0; k < kDim; ++k) {
      a_[2 * n + k] = a_new(n, k);
      v_[2 * n + k] = PetscRealPart(du[mesh.node_dof[n] + k]) / dt;
    }
  PetscCall(VecRestoreArrayRead(du_local, &du));
  PetscCall(MPIU_Allreduce(&local, &dw_inertia, 1, MPIU_REAL, MPIU_SUM, body_->comm()));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Inertia::AddForce(Vec f_local) const
{
  const Mesh &mesh = body_->mesh();
  PetscScalar *f;

  PetscFunctionBeginUser;
  PetscCall(VecGetArray(f_local, &f));
  ForEachMassShare([&](PetscInt n, double m) {
    for (int k = 0; k < kDim; ++k) f[mesh.node_dof[n] + k] += m * a_[2 * n + k];
  });
  PetscCall(VecRestoreArray(f_local, &f));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Inertia::KineticEnergy(double &w) const
{
  double local = 0;

  PetscFunctionBeginUser;
  ForEachMassShare(
    [&](PetscInt n, double m) { local += 0.5 * m * (v_[2 * n] * v_[2 * n] + v_[2 * n + 1] * v_[2 * n + 1]); });
  PetscCall(MPIU_Allreduce(&local, &w, 1, MPIU_REAL, MPIU_SUM, body_->comm()));
  PetscFunctionReturn(PETSC_SUCCESS);
}

} // namespace tf
