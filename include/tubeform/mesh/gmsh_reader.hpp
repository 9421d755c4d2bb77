// Reader for Gmsh 4.1 ASCII meshes of 4-node quadrilaterals.
#pragma once

#include <string>

#include "tubeform/mesh/serial_mesh.hpp"

namespace tf {

// Reads `path` into `mesh`. Quads (type 3) become cells, re-ordered
// counter-clockwise when Gmsh wrote them clockwise; 2-node lines (type 1) in
// named physical curves become the edge sets of that name. Returns an empty
// string on success, else a one-line reason naming the file.
std::string ReadGmsh(const std::string &path, SerialMesh &mesh);

} // namespace tf
