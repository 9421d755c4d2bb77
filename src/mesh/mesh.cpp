#include "tubeform/mesh/mesh.hpp"

#include <petscsf.h>

#include "tubeform/core/core.hpp"
#include "tubeform/mesh/partition.hpp"

namespace tf {

namespace {

// One field of `dofs` components on the points [from, to) of a DMPlex.
PetscErrorCode SetSection(DM dm, const char *name, PetscInt from, PetscInt to, PetscInt dofs)
{
  PetscSection s;
  PetscInt pstart, pend;
  PetscFunctionBeginUser;
  PetscCall(DMPlexGetChart(dm, &pstart, &pend));
  PetscCall(PetscSectionCreate(PetscObjectComm((PetscObject)dm), &s));
  PetscCall(PetscSectionSetNumFields(s, 1));
  PetscCall(PetscSectionSetFieldName(s, 0, name));
  PetscCall(PetscSectionSetFieldComponents(s, 0, dofs));
  PetscCall(PetscSectionSetChart(s, pstart, pend));
  for (PetscInt p = from; p < to; ++p) {
    PetscCall(PetscSectionSetDof(s, p, dofs));
    PetscCall(PetscSectionSetFieldDof(s, p, 0, dofs));
  }
  PetscCall(PetscSectionSetUp(s));
  PetscCall(DMSetLocalSection(dm, s));
  PetscCall(PetscSectionDestroy(&s));
  PetscFunctionReturn(PETSC_SUCCESS);
}

// Each local point's number in the serial mesh (`orig`, indexed from pstart): each serial point's own number
// broadcast along the migration SF (none: one rank, the identity).
PetscErrorCode OriginalPoints(PetscSF migration, PetscInt pstart, PetscInt pend, std::vector<PetscInt> &orig)
{
  PetscFunctionBeginUser;
  if (migration) {
    PetscInt nroots;
    PetscCall(PetscSFGetGraph(migration, &nroots, nullptr, nullptr, nullptr));
    std::vector<PetscInt> roots(nroots);
    for (PetscInt p = 0; p < nroots; ++p) roots[p] = p;
    PetscCall(PetscSFBcastBegin(migration, MPIU_INT, roots.data(), orig.data(), MPI_REPLACE));
    PetscCall(PetscSFBcastEnd(migration, MPIU_INT, roots.data(), orig.data(), MPI_REPLACE));
  } else
    for (PetscInt p = pstart; p < pend; ++p) orig[p - pstart] = p;
  PetscFunctionReturn(PETSC_SUCCESS);
}

// The boundary sets as labels on the edges of the serial mesh (and, completed, their vertices); labels travel
// with the points when the mesh is distributed. Only rank 0 sees the segments: a segment that is no cell edge
// (SerialMesh::validate refuses such meshes first) is agreed on by every rank before it is raised, the serial mesh
// destroyed.
PetscErrorCode LabelBoundarySets(MPI_Comm comm, const SerialMesh &serial, const std::vector<std::string> &sets,
                                 DM *serial_dm)
{
  PetscMPIInt rank;
  char bad[PETSC_MAX_PATH_LEN] = "";

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  for (const auto &name : sets) {
    DMLabel label;
    PetscCall(DMCreateLabel(*serial_dm, name.c_str()));
    PetscCall(DMGetLabel(*serial_dm, name.c_str(), &label));
    if (rank == 0 && serial.edge_sets.count(name)) {
      const PetscInt nc = serial.num_cells(); // (the vertices are numbered after the cells)
      for (const auto &e : serial.edge_sets.at(name)) {
        const PetscInt verts[2] = {nc + e[0], nc + e[1]};
        PetscInt njoin;
        const PetscInt *join;
        PetscCall(DMPlexGetJoin(*serial_dm, 2, verts, &njoin, &join));
        if (njoin == 1)
          PetscCall(DMLabelSetValue(label, join[0], 1));
        else if (!bad[0])
          PetscCall(PetscSNPrintf(bad, sizeof(bad), "boundary set '%s': nodes %d and %d are not joined by a cell edge",
                                  name.c_str(), (int)e[0], (int)e[1]));
        PetscCall(DMPlexRestoreJoin(*serial_dm, 2, verts, &njoin, &join));
      }
    }
    PetscCall(DMPlexLabelComplete(*serial_dm, label));
  }
  PetscCallMPI(MPI_Bcast(bad, sizeof(bad), MPI_CHAR, 0, comm));
  if (bad[0]) PetscCall(DMDestroy(serial_dm));
  PetscCheck(!bad[0], comm, PETSC_ERR_USER_INPUT, "%s", bad);
  PetscFunctionReturn(PETSC_SUCCESS);
}

// The serial mesh distributed over several ranks (`dist`, `migration`): METIS decides which rank owns each cell;
// a shell partitioner hands that to DMPlexDistribute. A rank left without cells is seen on rank 0 alone: agreed on
// first, the serial mesh destroyed.
PetscErrorCode Distribute(MPI_Comm comm, const SerialMesh &serial, DM *serial_dm, PetscSF *migration, DM *dist)
{
  PetscMPIInt rank, size;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCallMPI(MPI_Comm_size(comm, &size));
  std::vector<PetscInt> sizes(size, 0), points;
  int empty = -1; // a rank METIS left without cells
  if (rank == 0) {
    std::vector<int> part;
    PetscCall(PartitionCells(serial, size, part));
    std::vector<std::vector<PetscInt>> byrank(size);
    for (PetscInt cidx = 0; cidx < serial.num_cells(); ++cidx) byrank[part[cidx]].push_back(cidx);
    for (int r = 0; r < size; ++r) {
      if (byrank[r].empty() && empty < 0) empty = r;
      sizes[r] = (PetscInt)byrank[r].size();
      points.insert(points.end(), byrank[r].begin(), byrank[r].end());
    }
  }
  PetscCallMPI(MPI_Bcast(&empty, 1, MPI_INT, 0, comm));
  if (empty >= 0) PetscCall(DMDestroy(serial_dm));
  PetscCheck(empty < 0, comm, PETSC_ERR_USER_INPUT, "METIS left rank %d without cells: use fewer ranks or a finer mesh",
             empty);
  PetscPartitioner part;
  PetscCall(DMPlexGetPartitioner(*serial_dm, &part));
  PetscCall(PetscPartitionerSetType(part, PETSCPARTITIONERSHELL));
  PetscCall(PetscPartitionerShellSetPartition(part, size, sizes.data(), rank == 0 ? points.data() : nullptr));
  PetscCall(DMPlexDistribute(*serial_dm, 0, migration, dist));
  PetscFunctionReturn(PETSC_SUCCESS);
}

} // namespace

Mesh::~Mesh()
{
  // Destructors cannot return error codes; destruction failures are not actionable.
  if (cell_dm) (void)DMDestroy(&cell_dm);
  if (node_dm) (void)DMDestroy(&node_dm);
  if (dm) (void)DMDestroy(&dm);
}

PetscErrorCode Mesh::Create(MPI_Comm c, const SerialMesh &serial, const std::vector<std::string> &sets)
{
  PetscMPIInt rank, size;
  DM serial_dm, dist = nullptr;
  PetscSF migration = nullptr;

  PetscFunctionBeginUser;
  comm = c;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCallMPI(MPI_Comm_size(comm, &size));

  // 1. Rank 0 builds the whole mesh; the others contribute nothing.
  const PetscInt nc = rank == 0 ? serial.num_cells() : 0, nv = rank == 0 ? serial.num_nodes() : 0;
  std::vector<PetscInt> cells(serial.quads.begin(), serial.quads.end());
  PetscCall(DMPlexCreateFromCellListPetsc(comm, 2, nc, nv, 4, PETSC_TRUE, rank == 0 ? cells.data() : nullptr, 2,
                                          rank == 0 ? serial.xy.data() : nullptr, &serial_dm));
  PetscCall(PetscObjectSetName((PetscObject)serial_dm, "mesh"));

  // 2. The boundary sets become labels, which travel with the points.
  PetscCall(LabelBoundarySets(comm, serial, sets, &serial_dm));

  // 3. Each cell to the rank METIS gives it.
  if (size > 1) PetscCall(Distribute(comm, serial, &serial_dm, &migration, &dist));
  if (dist) {
    PetscCall(DMDestroy(&serial_dm));
    dm = dist;
  } else
    dm = serial_dm;
  PetscCall(PetscObjectSetName((PetscObject)dm, "mesh"));

  // 4. Two displacement dofs per vertex; one value per cell and one per
  // vertex on clones (for output fields).
  PetscInt cs, ce, vs, ve;
  PetscCall(DMPlexGetHeightStratum(dm, 0, &cs, &ce));
  PetscCall(DMPlexGetDepthStratum(dm, 0, &vs, &ve));
  PetscCall(SetSection(dm, "u", vs, ve, 2));
  PetscCall(DMSetMatType(dm, MATAIJ));
  PetscCall(DMClone(dm, &cell_dm));
  PetscCall(SetSection(cell_dm, "c", cs, ce, 1));
  PetscCall(DMClone(dm, &node_dm));
  PetscCall(SetSection(node_dm, "n", vs, ve, 1));

  PetscCall(BuildTables(sets, migration));
  PetscCall(PetscSFDestroy(&migration));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Mesh::BuildTables(const std::vector<std::string> &sets, PetscSF migration)
{
  PetscInt pstart, pend, ce, ve;

  PetscFunctionBeginUser;
  PetscCall(DMPlexGetChart(dm, &pstart, &pend));
  PetscCall(DMPlexGetHeightStratum(dm, 0, &cstart_, &ce));
  PetscCall(DMPlexGetDepthStratum(dm, 0, &vstart_, &ve));
  num_cells = ce - cstart_;
  num_nodes = ve - vstart_;
  std::vector<PetscInt> orig(pend - pstart);
  PetscCall(OriginalPoints(migration, pstart, pend, orig));
  PetscCall(MPIU_Allreduce(&num_cells, &num_global_cells, 1, MPIU_INT, MPI_SUM, comm));

  // Serial points are numbered cells first, then vertices.
  cell_orig.resize(num_cells);
  for (PetscInt c = 0; c < num_cells; ++c) cell_orig[c] = orig[cstart_ + c - pstart];
  PetscCall(BuildNodeTables(orig, pstart));
  PetscCall(BuildCellNodes());
  PetscCall(BuildSets(sets));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Mesh::BuildNodeTables(const std::vector<PetscInt> &orig, PetscInt pstart)
{
  PetscSection local, global, coord_section;
  Vec coords;
  const PetscScalar *xa;

  PetscFunctionBeginUser;
  PetscCall(DMGetLocalSection(dm, &local));
  PetscCall(DMGetGlobalSection(dm, &global));
  node_orig.resize(num_nodes);
  node_dof.resize(num_nodes);
  node_owned.resize(num_nodes);
  x0.resize(2 * num_nodes);
  PetscCall(DMGetCoordinateSection(dm, &coord_section));
  PetscCall(DMGetCoordinatesLocal(dm, &coords));
  PetscCall(VecGetArrayRead(coords, &xa));
  PetscInt owned = 0;
  for (PetscInt n = 0; n < num_nodes; ++n) {
    const PetscInt v = vstart_ + n;
    PetscInt off, goff, coff;
    node_orig[n] = orig[v - pstart] - num_global_cells;
    PetscCall(PetscSectionGetOffset(local, v, &off));
    PetscCall(PetscSectionGetOffset(global, v, &goff));
    PetscCall(PetscSectionGetOffset(coord_section, v, &coff));
    node_dof[n] = off;
    node_owned[n] = goff >= 0;
    owned += goff >= 0;
    x0[2 * n] = PetscRealPart(xa[coff]);
    x0[2 * n + 1] = PetscRealPart(xa[coff + 1]);
  }
  PetscCall(VecRestoreArrayRead(coords, &xa));
  PetscCall(MPIU_Allreduce(&owned, &num_global_nodes, 1, MPIU_INT, MPI_SUM, comm));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Mesh::BuildCellNodes()
{
  const PetscInt ve = vstart_ + num_nodes;

  PetscFunctionBeginUser;
  cell_nodes.resize(4 * num_cells);
  for (PetscInt c = 0; c < num_cells; ++c) {
    PetscInt nclosure, *closure = nullptr, k = 0;
    PetscCall(DMPlexGetTransitiveClosure(dm, cstart_ + c, PETSC_TRUE, &nclosure, &closure));
    for (PetscInt q = 0; q < nclosure; ++q) {
      const PetscInt p = closure[2 * q];
      if (p >= vstart_ && p < ve) {
        PetscCheck(k < 4, PETSC_COMM_SELF, PETSC_ERR_PLIB, "Cell %d has more than 4 vertices", (int)c);
        cell_nodes[4 * c + k++] = p - vstart_;
      }
    }
    PetscCall(DMPlexRestoreTransitiveClosure(dm, cstart_ + c, PETSC_TRUE, &nclosure, &closure));
    PetscCheck(k == 4, PETSC_COMM_SELF, PETSC_ERR_PLIB, "Cell %d has %d vertices, expected 4", (int)c, (int)k);
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Mesh::BuildSets(const std::vector<std::string> &sets)
{
  const PetscInt ce = cstart_ + num_cells, ve = vstart_ + num_nodes;

  PetscFunctionBeginUser;
  for (const auto &name : sets) {
    DMLabel label;
    IS is;
    PetscCall(DMGetLabel(dm, name.c_str(), &label));
    auto &nodes = node_sets[name];
    auto &edges = edge_sets[name];
    if (!label) continue;
    PetscCall(DMLabelGetStratumIS(label, 1, &is));
    if (!is) continue;
    PetscInt n;
    const PetscInt *pts;
    PetscCall(ISGetLocalSize(is, &n));
    PetscCall(ISGetIndices(is, &pts));
    for (PetscInt q = 0; q < n; ++q) {
      const PetscInt p = pts[q];
      if (p >= vstart_ && p < ve)
        nodes.push_back(p - vstart_);
      else if (p < cstart_ || p >= ce) {
        PetscInt nsupp, ncone;
        const PetscInt *supp, *cone;
        PetscCall(DMPlexGetSupportSize(dm, p, &nsupp));
        PetscCall(DMPlexGetConeSize(dm, p, &ncone));
        if (nsupp != 1 || ncone != 2) continue;
        PetscCall(DMPlexGetSupport(dm, p, &supp));
        PetscCall(DMPlexGetCone(dm, p, &cone));
        edges.push_back({supp[0] - cstart_, {cone[0] - vstart_, cone[1] - vstart_}});
      }
    }
    PetscCall(ISRestoreIndices(is, &pts));
    PetscCall(ISDestroy(&is));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

} // namespace tf
