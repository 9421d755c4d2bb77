// The full model's rotation hold (scenes/hold.hpp).
#include "tubeform/scenes/hold.hpp"

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdio>

#include "tubeform/scenes/common.hpp"

namespace tf {

PetscErrorCode RotationHold::Mark(Model &m, const TurnMap &press)
{
  PetscFunctionBeginUser;
  m_ = &m;
  PetscCall(MarkAxisPins(m, press, "inner", "hold", false)); // (a pair across the tube carries a couple anyway)
  PetscFunctionReturn(PETSC_SUCCESS);
}

void RotationHold::TakeFrames(Model &m, const TurnMap &to_tube) const
{
  TurnFrames(m, m.mesh.node_sets["hold"], to_tube);
}

PetscErrorCode RotationHold::Constrain(Model &m, const SupportStep &step)
{
  PetscFunctionBeginUser;
  const Vec2 along = step.to_tube({1, 0}); // (the press's x)
  m_ = &m, along_ = along;
  // (fixed while they hold the slide too: no unknown, the nodes carry a force with the couple)
  for (PetscInt n : m.mesh.node_sets["hold"])
    PetscCheck(m.system.PrescribeAlong(n, along[0], along[1], 0.0, pins_ ? 0.0 : 1.0), PETSC_COMM_SELF, PETSC_ERR_PLIB,
               "the rotation hold's node is not along a node frame axis");
  if (!pins_) m.system.SetExtraUnknown(this);
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode RotationHold::Missing(double &missing)
{
  const PetscScalar *r;
  double local = 0, sum;
  PetscFunctionBeginUser;
  // (the reactions in the node's frame: turned by its angle into the global one)
  const Mesh &mesh = m_->mesh;
  PetscCall(VecGetArrayRead(m_->system.reactions_local(), &r));
  for (PetscInt n : m_->mesh.node_sets["hold"]) {
    if (!mesh.node_owned[n]) continue;
    const double a = m_->system.HasFrame(n) ? m_->system.FrameAngle(n) : 0.0, c = std::cos(a), s = std::sin(a);
    const double rl = PetscRealPart(r[mesh.node_dof[n]]), rn = PetscRealPart(r[mesh.node_dof[n] + 1]);
    local += along_[0] * (c * rl - s * rn) + along_[1] * (s * rl + c * rn);
  }
  PetscCall(VecRestoreArrayRead(m_->system.reactions_local(), &r));
  PetscCall(MPIU_Allreduce(&local, &sum, 1, MPIU_REAL, MPIU_SUM, m_->comm));
  missing = -sum;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode RotationHold::FreeSlide(Model &m, double stroke)
{
  double spread;
  PetscFunctionBeginUser;
  if (!pins_) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(m.contact->NormalSpread(spread));
  if (spread <= kSlideHeld) {
    ++pinned_steps_;
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  pins_ = false;
  if (pinned_steps_ > 0 && !m.quiet)
    PetscCall(PetscPrintf(
      m.comm, "tubeform: the dies hold the tube's slide from U = %.4g mm: the rotation hold lets it go\n", stroke));
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

// Collective: the tube's centre (the hold's nodes' midpoint) and the moment about it of the forces f_int less
// share x f_rev (f_rev may be null) at the local nodes `nodes` (each rank's contributions summed over the
// nodes' copies, f_rev's at owned nodes).
static PetscErrorCode NodesMoment(Model &m, Vec f_int, Vec f_rev, double share, const std::vector<PetscInt> &nodes,
                                  Vec2 &centre, double &moment)
{
  const PetscScalar *f, *r = nullptr;
  double c[3] = {0, 0, 0}, cg[3], local = 0;
  PetscFunctionBeginUser;
  const auto &x = m.body.position();
  for (PetscInt n : m.mesh.node_sets["hold"])
    if (m.mesh.node_owned[n]) c[0] += x[2 * n], c[1] += x[2 * n + 1], c[2] += 1;
  PetscCall(MPIU_Allreduce(c, cg, 3, MPIU_REAL, MPIU_SUM, m.comm));
  centre = {cg[0] / std::max(cg[2], 1.0), cg[1] / std::max(cg[2], 1.0)};
  PetscCall(VecGetArrayRead(f_int, &f));
  if (f_rev) PetscCall(VecGetArrayRead(f_rev, &r));
  for (PetscInt n : nodes) {
    const PetscInt d = m.mesh.node_dof[n];
    const double fx = PetscRealPart(f[d]) - (r ? share * PetscRealPart(r[d]) : 0.0);
    const double fy = PetscRealPart(f[d + 1]) - (r ? share * PetscRealPart(r[d + 1]) : 0.0);
    local += (x[2 * n] - centre[0]) * fy - (x[2 * n + 1] - centre[1]) * fx;
  }
  if (f_rev) PetscCall(VecRestoreArrayRead(f_rev, &r));
  PetscCall(VecRestoreArrayRead(f_int, &f));
  PetscCall(MPIU_Allreduce(&local, &moment, 1, MPIU_REAL, MPIU_SUM, m.comm));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode RotationHold::Moment(Model &m, Vec f_int, double &moment, double &friction) const
{
  Vec2 centre;
  PetscFunctionBeginUser;
  PetscCall(NodesMoment(m, f_int, nullptr, 0.0, m.mesh.node_sets["hold"], centre, moment));
  friction = 0;
  if (m.contact && m.contact->active()) PetscCall(m.contact->FrictionMoment(centre, friction));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode RotationHold::SupportMoment(Model &m, Vec f_int, Vec f_rev, double share, PetscInt pin,
                                           double &moment) const
{
  Vec2 centre;
  PetscFunctionBeginUser;
  std::vector<PetscInt> nodes = m.mesh.node_sets["axis"];
  if (pin >= 0) nodes.push_back(pin);
  PetscCall(NodesMoment(m, f_int, f_rev, share, nodes, centre, moment));
  PetscFunctionReturn(PETSC_SUCCESS);
}

const ToolColumns &RotationHold::Columns()
{
  static const ToolColumns c({
    {"hold_moment",
     "full model, the rotation hold: the couple it puts on the tube (N mm/mm, counter-clockwise positive, in the "
     "press's frame; 0 without it); in its springback, the moment the springback's pins carry",
     "side_stroke"},
    {"hold_friction",
     "the rotation hold: the largest moment the contacts' friction could carry about the tube's centre (N mm/mm): "
     "a hold_moment above it is one the real tube may turn under",
     "hold_moment"},
  });
  return c;
}

PetscErrorCode RotationHold::Measure(Model &m, Vec f_int, double det, double ro, HistoryRow &row)
{
  double &moment = Columns()(row, kMoment), &friction = Columns()(row, kFriction);
  PetscFunctionBeginUser;
  PetscCall(Moment(m, f_int, moment, friction));
  moment *= det;
  const bool over = std::abs(moment) > friction + kUnresolved * largest_load_ * ro;
  if (over && !warned_ && !m.quiet)
    PetscCall(PetscPrintf(m.comm,
                          "tubeform: warning: at U = %.4g mm the rotation hold carries %.4g N mm/mm, more than the "
                          "contacts' friction could against a turn (%.4g): the real tube may turn (docs/dies.md, "
                          "\"A die off the axis\")\n",
                          row.stroke, moment, friction));
  warned_ = warned_ || over;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode RotationHold::AddForces(Model &m, Vec f) const
{
  Vec f_int;
  const PetscScalar *fi;
  PetscScalar *fa;
  double local[4] = {0, 0, 0, 0}, sum[4]; // each node's force (top, bottom), summed over its copies' cells
  PetscFunctionBeginUser;
  const auto &nodes = m.mesh.node_sets["hold"];
  PetscCall(VecDuplicate(f, &f_int));
  PetscCall(m.body.InternalForce(f_int));
  PetscCall(VecGetArrayRead(f_int, &fi));
  // (the two nodes told apart by their input numbers, alike on every rank)
  long first = LONG_MAX, lowest;
  for (PetscInt n : nodes) first = std::min(first, (long)m.mesh.node_orig[n]);
  PetscCallMPI(MPI_Allreduce(&first, &lowest, 1, MPI_LONG, MPI_MIN, m.comm));
  const auto slot = [&](PetscInt n) { return (long)m.mesh.node_orig[n] == lowest ? 0 : 2; };
  for (PetscInt n : nodes)
    for (int c = 0; c < 2; ++c) local[slot(n) + c] += PetscRealPart(fi[m.mesh.node_dof[n] + c]);
  PetscCall(VecRestoreArrayRead(f_int, &fi));
  PetscCall(VecDestroy(&f_int));
  PetscCall(MPIU_Allreduce(local, sum, 4, MPIU_REAL, MPIU_SUM, m.comm));
  PetscCall(VecGetArray(f, &fa));
  for (PetscInt n : nodes)
    if (m.mesh.node_owned[n])
      for (int c = 0; c < 2; ++c) fa[m.mesh.node_dof[n] + c] += sum[slot(n) + c];
  PetscCall(VecRestoreArray(f, &fa));
  PetscFunctionReturn(PETSC_SUCCESS);
}

} // namespace tf
