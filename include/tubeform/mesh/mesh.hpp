// The distributed mesh: a DMPlex partitioned by METIS, plus the per-rank tables
// the element loops use (cell -> node lists, node -> dof offsets, boundary sets).
#pragma once

#include <petscdmplex.h>

#include <array>
#include <map>
#include <string>
#include <vector>

#include "tubeform/mesh/serial_mesh.hpp"

namespace tf {

struct BoundaryEdge {
  PetscInt cell;    // local cell the edge bounds
  PetscInt node[2]; // local node indices
};

class Mesh {
public:
  Mesh() = default;
  Mesh(const Mesh &) = delete;
  Mesh &operator=(const Mesh &) = delete;
  ~Mesh();

  // Collective. `serial` is read on rank 0 only; the other ranks pass an empty
  // mesh. Boundary sets named in `sets` are carried to every rank.
  PetscErrorCode Create(MPI_Comm comm, const SerialMesh &serial, const std::vector<std::string> &sets);

  MPI_Comm comm = MPI_COMM_NULL;
  DM dm = nullptr;      // 2 displacement dofs per vertex
  DM cell_dm = nullptr; // 1 dof per cell, for cell (quadrature-averaged) fields
  DM node_dm = nullptr; // 1 dof per vertex, for scalar node fields (its offsets are dm's halved)

  PetscInt num_cells = 0, num_nodes = 0; // local, nodes include ghosts
  PetscInt num_global_cells = 0, num_global_nodes = 0;
  std::vector<PetscInt> cell_nodes;                           // 4 local node ids per local cell, counter-clockwise
  std::vector<PetscInt> node_dof;                             // local vector offset of each node's first dof
  std::vector<char> node_owned;                               // 1 where this rank owns the node
  std::vector<PetscInt> node_orig;                            // node id in the serial (input) mesh
  std::vector<PetscInt> cell_orig;                            // cell id in the serial (input) mesh
  std::vector<double> x0;                                     // initial coordinates, 2 per local node
  std::map<std::string, std::vector<PetscInt>> node_sets;     // local node ids
  std::map<std::string, std::vector<BoundaryEdge>> edge_sets; // edges of local cells

  PetscInt vertex_point(PetscInt node) const { return vstart_ + node; }

private:
  PetscInt vstart_ = 0, cstart_ = 0;
  // The per-rank tables of the distributed dm: counts, original numbers, then the pieces below.
  PetscErrorCode BuildTables(const std::vector<std::string> &sets, PetscSF migration);
  // Each node's original number, dof offset, owner flag and initial coordinates (orig: BuildTables').
  PetscErrorCode BuildNodeTables(const std::vector<PetscInt> &orig, PetscInt pstart);
  // The cell -> node table from each cell's closure (vertex order = input order).
  PetscErrorCode BuildCellNodes();
  // Boundary sets: vertices of the label become node sets; labelled edges
  // (each bounds exactly one cell, so exactly one rank has it) become edge sets.
  PetscErrorCode BuildSets(const std::vector<std::string> &sets);
};

} // namespace tf
