// The force-controlled tool's condition (contact.hpp): the force it puts on
// the body along its direction, for the reactions of a solution, against the
// scene's target. The normal force of each of its contact nodes is its start
// force plus the solution's increment (the reaction less the turning of the
// friction force on arcs), the friction force that of the latest iterate: the
// condition is affine in the reactions, as the system's extra unknown needs,
// and exact once the friction iterations have settled.
#include <cmath>

#include "tubeform/contact/contact.hpp"
#include "tubeform/contact/friction.hpp"

namespace tf {

double ContactSet::ForceAlong(PetscInt node, double fn, double fl) const
{
  const Vec2 d = Direction(node);
  const double len = std::hypot(d[0], d[1]);
  return (fn * (n_[node][0] * d[0] + n_[node][1] * d[1]) + fl * (l_[node][0] * d[0] + l_[node][1] * d[1])) / len;
}

PetscErrorCode ContactSet::PadForce(double &force) const
{
  double local = 0;
  PetscFunctionBeginUser;
  for (PetscInt node : candidates_) {
    if (!contact_[node] || !mesh_->node_owned[node] || !tools_[tool_of_[node]].Unknown()) continue;
    const double fl = Frictional(node) ? friction::Force(prm_.mu, prm_.vcri, fn_[node], x_[node]) : 0.0;
    local += ForceAlong(node, fn_[node], fl); // (NodeForce's, along the tool's direction)
  }
  PetscCallMPI(MPI_Allreduce(&local, &force, 1, MPI_DOUBLE, MPI_SUM, comm()));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode ContactSet::Missing(double &missing)
{
  const PetscScalar *react;
  double local = 0, force;
  PetscFunctionBeginUser;
  PetscCall(VecGetArrayRead(system_->reactions_local(), &react));
  for (PetscInt node : candidates_) {
    if (!contact_[node] || !mesh_->node_owned[node] || !tools_[tool_of_[node]].Unknown()) continue;
    const double fn = fn_[node] + NormalIncrement(node, NormalReaction(node, react), dxk_[node], pad_step_);
    const double fl = SlipFree(node) ? friction::Force(prm_.mu, prm_.vcri, fnk_[node], x_[node] + dxk_[node]) : 0.0;
    local += ForceAlong(node, fn, fl);
  }
  PetscCall(VecRestoreArrayRead(system_->reactions_local(), &react));
  PetscCallMPI(MPI_Allreduce(&local, &force, 1, MPI_DOUBLE, MPI_SUM, comm()));
  missing = pad_target_ - force;
  PetscFunctionReturn(PETSC_SUCCESS);
}

} // namespace tf
