// A mesh held whole on one rank, before partitioning: the common output of the
// structured generator and the Gmsh reader.
#pragma once

#include <array>
#include <map>
#include <string>
#include <vector>

namespace tf {

// Names of the boundary sets every tube mesh carries.
inline const std::array<std::string, 4> kBoundaryNames = {"inner", "outer", "x0", "y0"};

struct SerialMesh {
  std::vector<double> xy;                                           // 2 * num_nodes coordinates
  std::vector<int> quads;                                           // 4 * num_cells node ids, counter-clockwise
  std::map<std::string, std::vector<std::array<int, 2>>> edge_sets; // boundary edges by name

  int num_nodes() const { return static_cast<int>(xy.size() / 2); }
  int num_cells() const { return static_cast<int>(quads.size() / 4); }

  // Node ids touched by the edges of a set, sorted and unique.
  std::vector<int> node_set(const std::string &name) const;

  // Signed area of cell c (positive for counter-clockwise node order).
  double cell_area(int c) const;

  // Empty string when the mesh is usable (cells counter-clockwise with positive
  // area, ids in range, each required boundary set present and made of cell
  // sides); else a one-line reason.
  std::string validate(const std::vector<std::string> &required_sets) const;
};

} // namespace tf
