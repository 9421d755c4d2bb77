// METIS partition of a serial mesh's cells (dual graph: cells sharing an edge).
#pragma once

#include <petscsys.h>

#include <vector>

#include "tubeform/mesh/serial_mesh.hpp"

namespace tf {

// part[c] in [0, nparts) for each cell c. Balanced by cell count; cuts edges.
PetscErrorCode PartitionCells(const SerialMesh &mesh, int nparts, std::vector<int> &part);

} // namespace tf
