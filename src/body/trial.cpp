// The state a trial increment would reach, without committing it: the
// internal force the equilibrium iterations of an increment need
// (docs/theory.md, "Equilibrium").
#include <cmath>

#include "tubeform/body/body.hpp"
#include "tubeform/core/log.hpp"

namespace tf {

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
  for (PetscInt e = 0; e < mesh_->num_cells; ++e) {
    fe::ElemVec due, fe_;
    PointState *to = &last_trial_.states[fe::kGauss * e];
    Voigt s[fe::kGauss];
    GatherCell(*mesh_, e, du, due);
    if (!AdvanceCell(e, due, r, to, acc)) { // inverted: the next assembly reports it
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
