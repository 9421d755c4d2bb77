// The full model's rotation hold (scenes/hold.hpp).
#include "tubeform/scenes/hold.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "tubeform/scenes/common.hpp"

namespace tf {

PetscErrorCode RotationHold::Mark(Model &m, const SquareMap &press)
{
  PetscFunctionBeginUser;
  m_ = &m;
  PetscCall(MarkAxisPins(m, press, "inner", "hold"));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode RotationHold::Constrain(Model &m, const Vec2 &along)
{
  PetscFunctionBeginUser;
  m_ = &m, along_ = along;
  for (PetscInt n : m.mesh.node_sets["hold"])
    PetscCheck(m.system.PrescribeAlong(n, along[0], along[1], 0.0, 1.0), PETSC_COMM_SELF, PETSC_ERR_PLIB,
               "the rotation hold's node is not along a node frame axis");
  m.system.SetExtraUnknown(this);
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode RotationHold::Missing(double &missing)
{
  const PetscScalar *r;
  double local = 0, sum;
  PetscFunctionBeginUser;
  // (the inner nodes carry no frame: the reactions' global components)
  const Mesh &mesh = m_->mesh;
  PetscCall(VecGetArrayRead(m_->system.reactions_local(), &r));
  for (PetscInt n : m_->mesh.node_sets["hold"])
    if (mesh.node_owned[n])
      local += along_[0] * PetscRealPart(r[mesh.node_dof[n]]) + along_[1] * PetscRealPart(r[mesh.node_dof[n] + 1]);
  PetscCall(VecRestoreArrayRead(m_->system.reactions_local(), &r));
  PetscCall(MPIU_Allreduce(&local, &sum, 1, MPIU_REAL, MPIU_SUM, m_->comm));
  missing = -sum;
  PetscFunctionReturn(PETSC_SUCCESS);
}

std::string RotationHold::Stalled(double slope) const
{
  if (slope != 0) return ""; // (negative: the tube's sway is unstable; the equilibrium is still the answer)
  char why[256];
  std::snprintf(why, sizeof(why),
                "the dies do not hold the tube's slide along the press's x (its stiffness %g N/mm per mm); hold it by "
                "the pins (-full_hold pins, a die on the axis)",
                slope);
  return why;
}

PetscErrorCode RotationHold::Moment(Model &m, Vec f_int, double &moment, double &friction) const
{
  const PetscScalar *f;
  double local = 0, global; // the moment about the origin (a couple: about any point)
  PetscFunctionBeginUser;
  const auto &x = m.body.position();
  // (f_int holds each rank's cells' contributions: summed over the nodes' copies on every rank)
  PetscCall(VecGetArrayRead(f_int, &f));
  for (PetscInt n : m.mesh.node_sets["hold"]) {
    const double fx = PetscRealPart(f[m.mesh.node_dof[n]]), fy = PetscRealPart(f[m.mesh.node_dof[n] + 1]);
    local += x[2 * n] * fy - x[2 * n + 1] * fx;
  }
  PetscCall(VecRestoreArrayRead(f_int, &f));
  double c[2] = {0, 0}, cg[2];
  int count = 0, countg;
  for (PetscInt n : m.mesh.node_sets["hold"])
    if (m.mesh.node_owned[n]) c[0] += x[2 * n], c[1] += x[2 * n + 1], ++count;
  PetscCall(MPIU_Allreduce(&local, &global, 1, MPIU_REAL, MPIU_SUM, m.comm));
  PetscCall(MPIU_Allreduce(c, cg, 2, MPIU_REAL, MPIU_SUM, m.comm));
  PetscCallMPI(MPI_Allreduce(&count, &countg, 1, MPI_INT, MPI_SUM, m.comm));
  moment = global;
  friction = 0;
  if (m.contact && m.contact->active() && countg > 0)
    PetscCall(m.contact->FrictionMoment({cg[0] / countg, cg[1] / countg}, friction));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode RotationHold::Measure(Model &m, Vec f_int, double det, double ro, HistoryRow &row)
{
  PetscFunctionBeginUser;
  PetscCall(Moment(m, f_int, row.hold_moment, row.hold_friction));
  row.hold_moment *= det;
  const bool over = std::abs(row.hold_moment) > std::max(row.hold_friction, kNoise * std::abs(row.load) * ro);
  if (over && !warned_ && !m.quiet)
    PetscCall(PetscPrintf(m.comm,
                          "tubeform: warning: at U = %.4g mm the rotation hold carries %.4g N mm/mm, more than the "
                          "contacts' friction could (%.4g): the real tube would turn (docs/dies.md, \"A die off the "
                          "axis\")\n",
                          row.stroke, row.hold_moment, row.hold_friction));
  warned_ = warned_ || over;
  PetscFunctionReturn(PETSC_SUCCESS);
}

} // namespace tf
