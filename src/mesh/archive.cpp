#include "tubeform/mesh/archive.hpp"

#include <petscviewerhdf5.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>

#include "tubeform/core/core.hpp"
#include "tubeform/core/job_end.hpp"

namespace tf {

namespace {
// Whether every group on `path` and its last link exist (H5Lexists needs the parents).
bool Exists(hid_t file, const std::string &path)
{
  for (size_t slash = path.find('/', 1);; slash = path.find('/', slash + 1)) {
    const std::string part = path.substr(0, slash);
    if (H5Lexists(file, part.c_str(), H5P_DEFAULT) <= 0) return false;
    if (slash == std::string::npos) return true;
  }
}
// Creates the double dataset `path` (rank `ndims`, dims) with its groups and
// calls write(dataset). Every rank makes the same HDF5 calls whatever fails
// (dataset creation and closing are collective, so one rank returning early
// would leave the others waiting): the outcome is returned, to be agreed on.
template <class F>
bool Write(hid_t file, const std::string &path, int ndims, const hsize_t *dims, F &&write)
{
  const hid_t lcpl = H5Pcreate(H5P_LINK_CREATE), space = H5Screate_simple(ndims, dims, nullptr);
  bool ok = lcpl >= 0 && space >= 0 && H5Pset_create_intermediate_group(lcpl, 1) >= 0;
  const hid_t dset = H5Dcreate2(file, path.c_str(), H5T_NATIVE_DOUBLE, space, lcpl, H5P_DEFAULT, H5P_DEFAULT);
  ok = ok && dset >= 0 && write(dset) >= 0;
  if (dset >= 0) ok = H5Dclose(dset) >= 0 && ok;
  if (space >= 0) H5Sclose(space);
  if (lcpl >= 0) H5Pclose(lcpl);
  return ok;
}
} // namespace

PetscErrorCode Archive::WriteVector(Vec g, const std::string &path) const
{
  hid_t file;
  PetscInt n, lo, hi;
  const PetscScalar *a;

  PetscFunctionBeginUser;
  // Written with HDF5 directly, each rank its rows: VecView flushes the file
  // after every vector (an fsync each; it made a checkpoint 0.7 s). VecLoad
  // reads the plain 1-D dataset back.
  PetscCall(PetscViewerHDF5GetFileId(viewer_, &file));
  PetscCall(VecGetSize(g, &n));
  PetscCall(VecGetOwnershipRange(g, &lo, &hi));
  PetscCall(VecGetArrayRead(g, &a));
  const hsize_t dims = (hsize_t)n, start = (hsize_t)lo, count = (hsize_t)(hi - lo);
  const bool ok = Write(file, path, 1, &dims, [&](hid_t dset) {
    const hid_t space = H5Dget_space(dset), mem = H5Screate_simple(1, &count, nullptr);
    herr_t status = space < 0 || mem < 0 ? -1 : 0;
    if (status >= 0 && count > 0)
      status = H5Sselect_hyperslab(space, H5S_SELECT_SET, &start, nullptr, &count, nullptr);
    else if (status >= 0)
      status = std::min(H5Sselect_none(space), H5Sselect_none(mem));
    if (status >= 0) status = H5Dwrite(dset, H5T_NATIVE_DOUBLE, mem, space, H5P_DEFAULT, a);
    if (mem >= 0) H5Sclose(mem);
    if (space >= 0) H5Sclose(space);
    return status;
  });
  PetscCall(VecRestoreArrayRead(g, &a));
  PetscCall(Agree(ok, path));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Archive::Agree(bool ok, const std::string &path) const
{
  int mine = ok ? 0 : 1, any = 0;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Allreduce(&mine, &any, 1, MPI_INT, MPI_MAX, mesh_->comm));
  PetscCheck(!any, mesh_->comm, PETSC_ERR_FILE_WRITE,
             "%s %s: writing %s into %s.tmp failed (HDF5; a full disk?); the previous checkpoint is kept", option_,
             path_.c_str(), path.c_str(), path_.c_str());
  PetscFunctionReturn(PETSC_SUCCESS);
}

Archive::~Archive()
{
  // (a close that fails too, on the disk that stopped the checkpoint, keeps its error: KeepErrorText)
  if (viewer_) KeepErrorText([this] { (void)PetscViewerDestroy(&viewer_); });
}

PetscErrorCode Archive::Open(const Mesh &mesh, const std::string &path, bool write, const char *option, double bytes)
{
  PetscMPIInt rank;
  int ok = 1;
  double free_mb = -1; // set when there is too little room

  PetscFunctionBeginUser;
  mesh_ = &mesh;
  path_ = path;
  write_ = write;
  option_ = option;
  PetscCallMPI(MPI_Comm_rank(mesh.comm, &rank));
  if (rank == 0) {
    std::error_code ec;
    if (write) {
      const auto parent = std::filesystem::path(path).parent_path();
      if (!parent.empty()) std::filesystem::create_directories(parent, ec);
      std::FILE *f = std::fopen((path + ".tmp").c_str(), "w");
      ok = f != nullptr;
      if (f) std::fclose(f);
      // A write that fails inside parallel HDF5 can leave the ranks waiting on
      // each other in its close; a full disk is refused before the first byte.
      const auto room = std::filesystem::space(parent.empty() ? "." : parent, ec);
      if (ok && !ec && (double)room.available < bytes) {
        ok = 0, free_mb = room.available / 1e6;
        std::remove((path + ".tmp").c_str());
      }
    } else {
      ok = std::filesystem::is_regular_file(path, ec) && H5Fis_hdf5(path.c_str()) > 0;
    }
  }
  PetscCallMPI(MPI_Bcast(&ok, 1, MPI_INT, 0, mesh.comm));
  PetscCallMPI(MPI_Bcast(&free_mb, 1, MPI_DOUBLE, 0, mesh.comm));
  PetscCheck(ok || !write || free_mb < 0, mesh.comm, PETSC_ERR_FILE_WRITE,
             "%s %s: %.3g MB free on its file system, a checkpoint needs about %.3g MB (a full disk?)", option,
             path.c_str(), free_mb, bytes / 1e6);
  PetscCheck(ok || !write, mesh.comm, PETSC_ERR_FILE_WRITE,
             "%s %s: cannot create %s.tmp (does the directory exist and is it writable?)", option, path.c_str(),
             path.c_str());
  PetscCheck(ok, mesh.comm, PETSC_ERR_USER_INPUT, "%s %s: no such checkpoint (not a readable HDF5 file)", option,
             path.c_str());
  PetscCall(PetscViewerHDF5Open(mesh.comm, (write ? path + ".tmp" : path).c_str(),
                                write ? FILE_MODE_WRITE : FILE_MODE_READ, &viewer_));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Archive::Close()
{
  PetscMPIInt rank;
  int ok = 1;

  PetscFunctionBeginUser;
  PetscCall(PetscViewerDestroy(&viewer_));
  if (!write_) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCallMPI(MPI_Barrier(mesh_->comm));
  PetscCallMPI(MPI_Comm_rank(mesh_->comm, &rank));
  if (rank == 0) ok = std::rename((path_ + ".tmp").c_str(), path_.c_str()) == 0;
  PetscCallMPI(MPI_Bcast(&ok, 1, MPI_INT, 0, mesh_->comm));
  PetscCheck(ok, mesh_->comm, PETSC_ERR_FILE_WRITE, "%s %s: cannot rename %s.tmp into place", option_, path_.c_str(),
             path_.c_str());
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Archive::Values(const char *name, std::vector<double> &v)
{
  hid_t file;
  PetscMPIInt rank;

  PetscFunctionBeginUser;
  PetscCall(PetscViewerHDF5GetFileId(viewer_, &file));
  PetscCallMPI(MPI_Comm_rank(mesh_->comm, &rank));
  const std::string path = Path(name);
  if (write_) {
    // Dataset creation is collective; rank 0 writes the values every rank holds.
    const hsize_t n = v.size();
    const bool ok = Write(file, path, 1, &n, [&](hid_t dset) {
      return rank == 0 && n > 0 ? H5Dwrite(dset, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data()) : 0;
    });
    PetscCall(Agree(ok, path));
  } else {
    PetscCheck(Exists(file, path), mesh_->comm, PETSC_ERR_USER_INPUT,
               "-restart %s: the checkpoint has no %s (written by another version of tubeform?)", path_.c_str(),
               path.c_str());
    const hid_t dset = H5Dopen2(file, path.c_str(), H5P_DEFAULT);
    TF_CHECK_HDF5(dset);
    const hid_t space = H5Dget_space(dset);
    TF_CHECK_HDF5(space);
    const hssize_t n = H5Sget_simple_extent_npoints(space);
    TF_CHECK_HDF5(n);
    v.resize(n);
    if (n > 0) TF_CHECK_HDF5(H5Dread(dset, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data()));
    TF_CHECK_HDF5(H5Sclose(space));
    TF_CHECK_HDF5(H5Dclose(dset));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Archive::Text(const char *name, std::string &text)
{
  PetscFunctionBeginUser;
  if (write_) {
    PetscCall(PetscViewerHDF5WriteAttribute(viewer_, group_.c_str(), name, PETSC_STRING, text.c_str()));
  } else {
    PetscBool has;
    char *value = nullptr;
    PetscCall(PetscViewerHDF5HasAttribute(viewer_, group_.c_str(), name, &has));
    PetscCheck(has, mesh_->comm, PETSC_ERR_USER_INPUT,
               "-restart %s: the checkpoint has no %s (written by another version of tubeform?)", path_.c_str(),
               Path(name).c_str());
    PetscCall(PetscViewerHDF5ReadAttribute(viewer_, group_.c_str(), name, PETSC_STRING, nullptr, &value));
    text = value;
    PetscCall(PetscFree(value));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Archive::Value(const char *name, double &v)
{
  std::vector<double> one = {v};
  PetscFunctionBeginUser;
  PetscCall(Values(name, one));
  PetscCheck(one.size() == 1, mesh_->comm, PETSC_ERR_USER_INPUT, "-restart %s: %s is not one number", path_.c_str(),
             Path(name).c_str());
  v = one[0];
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Archive::Value(const char *name, PetscInt &v)
{
  double d = static_cast<double>(v);
  PetscFunctionBeginUser;
  PetscCall(Value(name, d));
  v = static_cast<PetscInt>(d);
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Archive::Value(const char *name, bool &v)
{
  double d = v ? 1.0 : 0.0;
  PetscFunctionBeginUser;
  PetscCall(Value(name, d));
  v = d != 0;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Archive::NodeData(const char *name, std::vector<double> &v, int comps, bool owned_only)
{
  PetscFunctionBeginUser;
  PetscCall(Entities(name, v, comps, mesh_->node_orig, mesh_->num_global_nodes, &mesh_->node_owned, owned_only));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Archive::CellData(const char *name, std::vector<double> &v, int comps)
{
  PetscFunctionBeginUser;
  PetscCall(Entities(name, v, comps, mesh_->cell_orig, mesh_->num_global_cells, nullptr, false));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Archive::Entities(const char *name, std::vector<double> &v, int comps, const std::vector<PetscInt> &orig,
                                 PetscInt nglobal, const std::vector<char> *owned, bool owned_only)
{
  Vec g;
  const PetscInt n = (PetscInt)orig.size();

  PetscFunctionBeginUser;
  PetscCheck((PetscInt)v.size() == comps * n, PETSC_COMM_SELF, PETSC_ERR_PLIB, "%s: %d values for %d entities of %d",
             name, (int)v.size(), (int)n, comps);
  // A vector in the input numbering, split over the ranks as PETSc likes.
  PetscCall(VecCreateMPI(mesh_->comm, PETSC_DECIDE, comps * nglobal, &g));
  PetscCall(PetscObjectSetName((PetscObject)g, name));
  PetscCall(PetscViewerHDF5PushGroup(viewer_, group_.c_str()));
  if (write_) {
    std::vector<PetscInt> idx;
    std::vector<PetscScalar> val;
    for (PetscInt i = 0; i < n; ++i) {
      if (owned && !(*owned)[i]) continue;
      for (int k = 0; k < comps; ++k) idx.push_back(comps * orig[i] + k), val.push_back(v[comps * i + k]);
    }
    PetscCall(VecSetValues(g, (PetscInt)idx.size(), idx.data(), val.data(), INSERT_VALUES));
    PetscCall(VecAssemblyBegin(g));
    PetscCall(VecAssemblyEnd(g));
    PetscCall(WriteVector(g, Path(name)));
  } else {
    PetscBool has;
    PetscCall(PetscViewerHDF5HasObject(viewer_, (PetscObject)g, &has));
    if (!has) {
      PetscCall(PetscViewerHDF5PopGroup(viewer_));
      PetscCall(VecDestroy(&g));
    }
    PetscCheck(has, mesh_->comm, PETSC_ERR_USER_INPUT,
               "-restart %s: the checkpoint has no %s (written by another version of tubeform?)", path_.c_str(),
               Path(name).c_str());
    PetscCall(VecLoad(g, viewer_));
    // Every local entity's numbers from wherever they are stored.
    std::vector<PetscInt> idx(comps * n);
    for (PetscInt i = 0; i < n; ++i)
      for (int k = 0; k < comps; ++k) idx[comps * i + k] = comps * orig[i] + k;
    IS from;
    Vec local;
    VecScatter scatter;
    PetscCall(ISCreateGeneral(PETSC_COMM_SELF, comps * n, idx.data(), PETSC_COPY_VALUES, &from));
    PetscCall(VecCreateSeqWithArray(PETSC_COMM_SELF, 1, comps * n, v.data(), &local));
    PetscCall(VecScatterCreate(g, from, local, nullptr, &scatter));
    PetscCall(VecScatterBegin(scatter, g, local, INSERT_VALUES, SCATTER_FORWARD));
    PetscCall(VecScatterEnd(scatter, g, local, INSERT_VALUES, SCATTER_FORWARD));
    PetscCall(VecScatterDestroy(&scatter));
    PetscCall(VecDestroy(&local));
    PetscCall(ISDestroy(&from));
    if (owned_only)
      for (PetscInt i = 0; i < n; ++i)
        if (!(*owned)[i])
          for (int k = 0; k < comps; ++k) v[comps * i + k] = 0;
  }
  PetscCall(PetscViewerHDF5PopGroup(viewer_));
  PetscCall(VecDestroy(&g));
  PetscFunctionReturn(PETSC_SUCCESS);
}

} // namespace tf
