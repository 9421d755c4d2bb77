// How the half and full models are held where no die holds them
// (scenes/support.hpp, scenes/common.hpp): the springback's pin along y, and
// the full model's pins along x on the y axis (the press's axes: a turned
// pass's), with their node frames in a press turned by any angle.
#include <cmath>

#include "tubeform/scenes/common.hpp"
#include "tubeform/scenes/support.hpp"

namespace tf {

PetscErrorCode ChooseSpringbackPin(Model &m, PetscInt &pin, const TurnMap &press)
{
  struct {
    double y;
    int id;
  } mine = {kNever, -1}, best;
  PetscFunctionBeginUser;
  for (PetscInt n : m.mesh.node_sets["inner"]) {
    const Vec2 p0 = press({m.mesh.x0[2 * n], m.mesh.x0[2 * n + 1]});
    const double y = std::abs(p0[1]);
    const int id = (int)m.mesh.node_orig[n];
    if (p0[0] > 0 && (y < mine.y || (y == mine.y && id < mine.id))) mine = {y, id};
  }
  PetscCallMPI(MPI_Allreduce(&mine, &best, 1, MPI_DOUBLE_INT, MPI_MINLOC, m.comm));
  pin = -1;
  for (PetscInt n : m.mesh.node_sets["inner"])
    if (m.mesh.node_orig[n] == best.id) pin = n;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MarkAxisPins(Model &m, const TurnMap &press, const char *surface, const char *set, bool exact)
{
  struct {
    double y;
    int id;
  } mine[2] = {{-kNever, -1}, {-kNever, -1}}, best[2];
  PetscFunctionBeginUser;
  // The surface's nodes on the y axis at its top and at its bottom (the largest |y| among those on it); in a press
  // turned by an angle no node need lie on, the nearest.
  exact = exact && press.angle == 0;
  for (PetscInt n : m.mesh.node_sets[surface]) {
    const Vec2 p0 = press({m.mesh.x0[2 * n], m.mesh.x0[2 * n + 1]});
    const double x = p0[0], y = p0[1];
    const int side = y > 0 ? 0 : 1, id = (int)m.mesh.node_orig[n];
    const double score = exact ? std::abs(y) - kNever * (std::abs(x) > kAxisPin * std::abs(y))
                               : std::abs(y) / std::hypot(x, y); // (the cosine of its angle from the axis)
    if (score > mine[side].y || (score == mine[side].y && id < mine[side].id)) mine[side] = {score, id};
  }
  PetscCallMPI(MPI_Allreduce(mine, best, 2, MPI_DOUBLE_INT, MPI_MAXLOC, m.comm));
  PetscCheck(best[0].y > 0 && best[1].y > 0, m.comm, PETSC_ERR_USER_INPUT,
             "the full model needs an %s node on the press's y axis at the tube's top and at its bottom (the "
             "mesh has none there)",
             surface);
  auto &axis = m.mesh.node_sets[set];
  axis.clear();
  for (PetscInt n : m.mesh.node_sets[surface])
    if (m.mesh.node_orig[n] == best[0].id || m.mesh.node_orig[n] == best[1].id) axis.push_back(n);
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode AxisPins::Mark(Model &m, const TurnMap &press)
{
  PetscFunctionBeginUser;
  PetscCall(MarkAxisPins(m, press));
  PetscFunctionReturn(PETSC_SUCCESS);
}

void AxisPins::TakeFrames(Model &m, const TurnMap &to_tube) const { TurnFrames(m, m.mesh.node_sets["axis"], to_tube); }

PetscErrorCode AxisPins::Constrain(Model &m, const SupportStep &step)
{
  PetscFunctionBeginUser;
  const Vec2 along = step.to_tube({1, 0}); // (the press's x)
  PetscCall(HoldAlong(m, "axis", along[0], along[1]));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode SpringbackPin::Mark(Model &m, const TurnMap &press)
{
  PetscFunctionBeginUser;
  PetscCall(ChooseSpringbackPin(m, node_, press));
  holds_ = true;
  PetscFunctionReturn(PETSC_SUCCESS);
}

void SpringbackPin::TakeFrames(Model &m, const TurnMap &to_tube) const
{
  if (node() >= 0) TurnFrames(m, {node_}, to_tube);
}

PetscErrorCode SpringbackPin::Constrain(Model &m, const SupportStep &step)
{
  PetscFunctionBeginUser;
  if (step.pressing) PetscCall(ReleaseOnTouch(m));
  const Vec2 along = step.to_tube({0, 1}); // (the press's y)
  if (node() >= 0)
    PetscCheck(m.system.PrescribeAlong(node_, along[0], along[1], 0.0), PETSC_COMM_SELF, PETSC_ERR_PLIB,
               "the springback's pin is not along a node frame axis");
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode SpringbackPin::ReleaseOnTouch(Model &m)
{
  PetscInt touching;
  PetscFunctionBeginUser;
  if (!holds_) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(m.contact->Count(touching, false));
  holds_ = touching == 0;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode SpringbackPin::Persist(Model &m, Archive &ar, const TurnMap &press)
{
  PetscFunctionBeginUser;
  PetscCall(ar.Value("pinned", holds_));
  if (holds_ && ar.reading()) PetscCall(Mark(m, press));
  PetscFunctionReturn(PETSC_SUCCESS);
}

} // namespace tf
