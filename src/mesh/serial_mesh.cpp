#include "tubeform/mesh/serial_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>
#include <utility>

namespace tf {

std::vector<int> SerialMesh::node_set(const std::string &name) const
{
  std::vector<int> nodes;
  auto it = edge_sets.find(name);
  if (it == edge_sets.end()) return nodes;
  for (const auto &e : it->second) {
    nodes.push_back(e[0]);
    nodes.push_back(e[1]);
  }
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  return nodes;
}

double SerialMesh::cell_area(int c) const
{
  // Shoelace formula over the four corners.
  double a = 0.0;
  for (int k = 0; k < 4; ++k) {
    const int p = quads[4 * c + k], q = quads[4 * c + (k + 1) % 4];
    a += xy[2 * p] * xy[2 * q + 1] - xy[2 * q] * xy[2 * p + 1];
  }
  return 0.5 * a;
}

std::string SerialMesh::validate(const std::vector<std::string> &required_sets) const
{
  std::ostringstream why;
  if (num_cells() == 0) return "mesh has no quadrilateral cells";
  for (int id : quads)
    if (id < 0 || id >= num_nodes()) {
      why << "cell refers to node " << id << " outside 0.." << num_nodes() - 1;
      return why.str();
    }
  for (int c = 0; c < num_cells(); ++c)
    if (!(cell_area(c) > 0.0)) {
      why << "cell " << c << " has non-positive area " << cell_area(c) << " (degenerate or clockwise)";
      return why.str();
    }
  for (const auto &name : required_sets)
    if (edge_sets.count(name) == 0 || edge_sets.at(name).empty()) {
      why << "boundary set '" << name << "' is missing or empty";
      return why.str();
    }
  // Each segment of a boundary set must be a side of a cell: the distributed
  // mesh labels it by the cell edge joining its two nodes (Mesh::Create), and
  // a segment with no such edge could only be found there, on rank 0 alone.
  std::set<std::pair<int, int>> sides;
  for (int c = 0; c < num_cells(); ++c)
    for (int k = 0; k < 4; ++k) {
      const int p = quads[4 * c + k], q = quads[4 * c + (k + 1) % 4];
      if (p != q) sides.insert({std::min(p, q), std::max(p, q)});
    }
  const auto known = [&](int n) { return n >= 0 && n < num_nodes(); };
  for (const auto &name : required_sets)
    for (const auto &e : edge_sets.at(name)) {
      if (!known(e[0]) || !known(e[1])) {
        why << "boundary set (physical curve) '" << name << "': a segment refers to a node outside 0.."
            << num_nodes() - 1;
        return why.str();
      }
      if (!sides.count({std::min(e[0], e[1]), std::max(e[0], e[1])})) {
        why << "boundary set (physical curve) '" << name << "': the segment from (" << xy[2 * e[0]] << ", "
            << xy[2 * e[0] + 1] << ") to (" << xy[2 * e[1]] << ", " << xy[2 * e[1] + 1]
            << ") is not a side of any cell";
        return why.str();
      }
    }
  return "";
}

} // namespace tf
