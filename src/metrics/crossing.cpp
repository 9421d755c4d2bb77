#include "tubeform/metrics/crossing.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <tuple>

namespace tf {

namespace {
// Twice the signed area of (p, q, r): > 0 when r lies left of p -> q.
double Orient(const Vec2 &p, const Vec2 &q, const Vec2 &r)
{
  return (q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0]);
}

bool Cross(const SurfaceEdge &e, const SurfaceEdge &f)
{
  const double o1 = Orient(e.a, e.b, f.a), o2 = Orient(e.a, e.b, f.b);
  const double o3 = Orient(f.a, f.b, e.a), o4 = Orient(f.a, f.b, e.b);
  return ((o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0)) && ((o3 > 0 && o4 < 0) || (o3 < 0 && o4 > 0));
}

// Where two crossing edges meet.
Vec2 Meet(const SurfaceEdge &e, const SurfaceEdge &f)
{
  const double o1 = Orient(f.a, f.b, e.a), o2 = Orient(f.a, f.b, e.b), s = o1 / (o1 - o2);
  return {e.a[0] + s * (e.b[0] - e.a[0]), e.a[1] + s * (e.b[1] - e.a[1])};
}
} // namespace

SelfCrossing FindSelfCrossing(std::vector<SurfaceEdge> edges)
{
  SelfCrossing best;
  const auto lo = [](const SurfaceEdge &e) { return std::min(e.a[0], e.b[0]); };
  const auto hi = [](const SurfaceEdge &e) { return std::max(e.a[0], e.b[0]); };
  // (a fixed order whatever the order gathered: by least x, then by the nodes)
  std::sort(edges.begin(), edges.end(), [&](const SurfaceEdge &e, const SurfaceEdge &f) {
    return std::make_tuple(lo(e), e.na, e.nb) < std::make_tuple(lo(f), f.na, f.nb);
  });
  std::array<long, 4> key{};
  for (size_t i = 0; i < edges.size(); ++i) {
    const SurfaceEdge &e = edges[i];
    for (size_t j = i + 1; j < edges.size() && lo(edges[j]) <= hi(e); ++j) {
      const SurfaceEdge &f = edges[j];
      if (f.na == e.na || f.na == e.nb || f.nb == e.na || f.nb == e.nb) continue;
      if (std::min(f.a[1], f.b[1]) > std::max(e.a[1], e.b[1]) || std::max(f.a[1], f.b[1]) < std::min(e.a[1], e.b[1]))
        continue;
      if (!Cross(e, f)) continue;
      std::array<long, 4> k = {std::min(e.na, e.nb), std::max(e.na, e.nb), std::min(f.na, f.nb), std::max(f.na, f.nb)};
      if (k[2] < k[0]) std::swap(k[0], k[2]), std::swap(k[1], k[3]);
      if (best.found && !(k < key)) continue;
      best.found = true, key = k, best.at = Meet(e, f);
      std::copy(k.begin(), k.end(), best.nodes);
    }
  }
  return best;
}

PetscErrorCode SurfaceSelfCrossing(const Mesh &mesh, const std::vector<double> &x, const std::vector<std::string> &sets,
                                   SelfCrossing &c)
{
  std::vector<double> mine;
  PetscMPIInt size;
  PetscFunctionBeginUser;
  for (const std::string &set : sets) {
    const auto it = mesh.edge_sets.find(set);
    if (it == mesh.edge_sets.end()) continue;
    for (const BoundaryEdge &e : it->second) {
      const PetscInt a = e.node[0], b = e.node[1];
      mine.insert(mine.end(), {x[2 * a], x[2 * a + 1], x[2 * b], x[2 * b + 1], (double)mesh.node_orig[a],
                               (double)mesh.node_orig[b]});
    }
  }
  PetscCallMPI(MPI_Comm_size(mesh.comm, &size));
  std::vector<int> counts(size), displs(size);
  int count = (int)mine.size(), total = 0;
  PetscCallMPI(MPI_Allgather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, mesh.comm));
  for (int r = 0; r < size; ++r) displs[r] = total, total += counts[r];
  std::vector<double> all(total);
  PetscCallMPI(
    MPI_Allgatherv(mine.data(), count, MPI_DOUBLE, all.data(), counts.data(), displs.data(), MPI_DOUBLE, mesh.comm));
  std::vector<SurfaceEdge> edges;
  for (int k = 0; k + 5 < total; k += 6)
    edges.push_back({{all[k], all[k + 1]}, {all[k + 2], all[k + 3]}, (long)all[k + 4], (long)all[k + 5]});
  c = FindSelfCrossing(std::move(edges));
  PetscFunctionReturn(PETSC_SUCCESS);
}

} // namespace tf
