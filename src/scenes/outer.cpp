// The tool scenes' outer surface gathered on every rank (scenes/common.hpp).
#include <algorithm>
#include <cmath>

#include "tubeform/scenes/common.hpp"

namespace tf {

// The segment of the upper die a node touches (-1: free, or on the lower die): the shape metrics' apex count.
static double UpperSegment(const Model &m, PetscInt n)
{
  if (!m.contact || !m.contact->InContact(n) || m.contact->ToolOf(n) != 0) return -1.0;
  return double(m.contact->Segment(n));
}

// Each rank's owned outer nodes (x, y, contact, segment, input number), gathered and sorted by angle.
// (the nodes at `x`: where they are, or where the mesh put them)
static PetscErrorCode GatherOuterAt(Model &m, const std::vector<double> &x, std::vector<SurfacePoint> &all, bool upper,
                                    const TurnMap &press)
{
  std::vector<double> mine;
  PetscMPIInt size;
  PetscFunctionBeginUser;
  for (PetscInt n : m.mesh.node_sets["outer"]) {
    const Vec2 p = press({x[2 * n], x[2 * n + 1]}), p0 = press({m.mesh.x0[2 * n], m.mesh.x0[2 * n + 1]});
    if (m.mesh.node_owned[n] && (!upper || (p0[1] >= -kAxisPin * std::abs(p0[0]) && p0[0] >= -kAxisPin * p0[1])))
      mine.insert(mine.end(), {p[0], p[1], m.contact ? double(m.contact->InContact(n)) : 0.0, UpperSegment(m, n),
                               double(m.mesh.node_orig[n])});
  }
  PetscCallMPI(MPI_Comm_size(m.comm, &size));
  std::vector<int> counts(size), displs(size);
  int count = (int)mine.size();
  PetscCallMPI(MPI_Allgather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, m.comm));
  int total = 0;
  for (int r = 0; r < size; ++r) displs[r] = total, total += counts[r];
  std::vector<double> buf(total);
  PetscCallMPI(
    MPI_Allgatherv(mine.data(), count, MPI_DOUBLE, buf.data(), counts.data(), displs.data(), MPI_DOUBLE, m.comm));
  all.clear();
  for (int k = 0; k + 4 < total; k += 5)
    all.push_back({buf[k], buf[k + 1], (int)buf[k + 2], (int)buf[k + 3], (long)buf[k + 4]});
  std::sort(all.begin(), all.end(),
            [](const SurfacePoint &a, const SurfacePoint &b) { return std::atan2(a.y, a.x) < std::atan2(b.y, b.x); });
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode GatherOuter(Model &m, std::vector<SurfacePoint> &all, bool upper, const TurnMap &press)
{
  PetscFunctionBeginUser;
  PetscCall(GatherOuterAt(m, m.body.position(), all, upper, press));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode GatherRoundOuter(Model &m, std::vector<SurfacePoint> &all)
{
  PetscFunctionBeginUser;
  PetscCall(GatherOuterAt(m, m.mesh.x0, all, false, {}));
  PetscFunctionReturn(PETSC_SUCCESS);
}

void OrderAroundSide(std::vector<SurfacePoint> &all, const long ends[2])
{
  double mid[2] = {0, 0};
  for (const auto &o : all)
    if (o.id == ends[0] || o.id == ends[1]) mid[0] += o.x, mid[1] += o.y;
  const double at = std::atan2(mid[1], mid[0]);
  const auto around = [at](const SurfacePoint &o) { return std::remainder(std::atan2(o.y, o.x) - at, 2 * M_PI); };
  std::stable_sort(all.begin(), all.end(),
                   [&](const SurfacePoint &a, const SurfacePoint &b) { return around(a) < around(b); });
}

PetscErrorCode LowestOuterY(Model &m, double &y, const TurnMap &press)
{
  double low = 0, lowest;
  PetscFunctionBeginUser;
  const auto &x = m.body.position();
  for (PetscInt n : m.mesh.node_sets["outer"]) low = std::max(low, -press({x[2 * n], x[2 * n + 1]})[1]);
  PetscCallMPI(MPI_Allreduce(&low, &lowest, 1, MPI_DOUBLE, MPI_MAX, m.comm));
  y = -lowest;
  PetscFunctionReturn(PETSC_SUCCESS);
}

} // namespace tf
