#include "tubeform/mesh/partition.hpp"

#include <metis.h>

#include "tubeform/core/core.hpp"
#include "tubeform/core/signals.hpp"

namespace tf {

PetscErrorCode PartitionCells(const SerialMesh &mesh, int nparts, std::vector<int> &part)
{
  PetscFunctionBeginUser;
  idx_t ne = mesh.num_cells(), nn = mesh.num_nodes();
  part.assign(ne, 0);
  if (nparts <= 1 || ne == 0) PetscFunctionReturn(PETSC_SUCCESS);
  // Runs on rank 0 alone: a user error raised here would leave the other ranks
  // waiting. The caller refuses such a mesh on every rank first (Problem::Setup),
  // so this is a program error (main aborts the job on it).
  PetscCheck(ne >= nparts, PETSC_COMM_SELF, PETSC_ERR_PLIB,
             "Mesh has %d cells, fewer than the %d MPI ranks (the caller must refuse this on every rank)", (int)ne,
             nparts);

  std::vector<idx_t> eptr(ne + 1), eind(mesh.quads.begin(), mesh.quads.end()), epart(ne), npart(nn);
  for (idx_t c = 0; c <= ne; ++c) eptr[c] = 4 * c;
  idx_t ncommon = 2, np = nparts, objval = 0;
  idx_t options[METIS_NOPTIONS];
  METIS_SetDefaultOptions(options);
  options[METIS_OPTION_SEED] = 7; // deterministic partitions, run to run
  PetscStackPushExternal("METIS_PartMeshDual");
  const int err = METIS_PartMeshDual(&ne, &nn, eptr.data(), eind.data(), nullptr, nullptr, &ncommon, &np, nullptr,
                                     options, &objval, epart.data(), npart.data());
  PetscStackPop;
  // METIS (its GKlib) catches SIGTERM while it runs and gives the handler back
  // through signal() with System V semantics: good for one signal only, the
  // next would end this rank at once (mpirun forwards a batch system's SIGTERM
  // a second later). The stop signals are installed again.
  RearmStopSignals();
  PetscCheck(err == METIS_OK, PETSC_COMM_SELF, PETSC_ERR_LIB, "METIS_PartMeshDual failed with code %d", err);
  for (idx_t c = 0; c < ne; ++c) part[c] = static_cast<int>(epart[c]);
  PetscFunctionReturn(PETSC_SUCCESS);
}

} // namespace tf
