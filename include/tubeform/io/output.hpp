// Results through PETSc's HDF5 viewer: the mesh, vertex and cell fields as a
// time series (ParaView reads them through the .xmf written beside), the
// history in /history (one 1-D dataset per column), the options and metrics
// as attributes. The file is written as <output>.partial and renamed only when
// the run finishes, so a failed run never overwrites an earlier result.
#pragma once

#include <petscviewer.h>

#include <string>
#include <vector>

#include "tubeform/io/history.hpp"
#include "tubeform/mesh/mesh.hpp"

namespace tf {

struct CellField {
  std::string name;
  std::vector<double> values; // one per local cell
};

class ResultWriter {
public:
  ~ResultWriter();
  // Collective. Checks the path first: a clear error if it cannot be written.
  PetscErrorCode Open(const Mesh &mesh, const std::string &path);
  // Collective: one time-series entry. `u` holds 2 values per local node.
  PetscErrorCode WriteStep(PetscInt step, double time, const std::vector<double> &u,
                           const std::vector<CellField> &cells);
  // Collective: history, attributes, the .xmf, then the rename.
  PetscErrorCode Close(const History &history, const std::vector<std::pair<std::string, double>> &metrics);

private:
  const Mesh *mesh_ = nullptr;
  PetscViewer viewer_ = nullptr;
  std::string path_;
  std::vector<double> times_;
  std::vector<std::string> cell_names_;
  PetscErrorCode WriteXdmf() const;
};

// Collective: an error on every rank unless a file can be created at `path`
// (tested on rank 0 with a scratch file, after creating missing parent directories).
PetscErrorCode CheckWritable(MPI_Comm comm, const std::string &path, const char *option);

} // namespace tf
