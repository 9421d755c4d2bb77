#include "tubeform/io/series.hpp"

#include <cstring>
#include <string>

#include "tubeform/core/core.hpp"

namespace tf {

namespace {

// Opens dataset `path` grown to `step` + 1 steps of `dims` (dims[0] ignored),
// creating it (chunked by step, unlimited in steps) at step 0, or with `create`.
PetscErrorCode OpenStep(hid_t file, const char *path, int ndims, hsize_t dims[], PetscInt step, const char *type,
                        hid_t *dset, bool create = false)
{
  PetscFunctionBeginUser;
  dims[0] = (hsize_t)step + 1;
  if (step == 0 || create) {
    hsize_t maxdims[3] = {H5S_UNLIMITED, dims[1], ndims > 2 ? dims[2] : 0}, chunk[3] = {1, dims[1], dims[2]};
    const hid_t space = H5Screate_simple(ndims, dims, maxdims), plist = H5Pcreate(H5P_DATASET_CREATE);
    TF_CHECK_HDF5(space);
    TF_CHECK_HDF5(plist);
    TF_CHECK_HDF5(H5Pset_chunk(plist, ndims, chunk));
    *dset = H5Dcreate2(file, path, H5T_NATIVE_DOUBLE, space, H5P_DEFAULT, plist, H5P_DEFAULT);
    TF_CHECK_HDF5(*dset);
    TF_CHECK_HDF5(H5Pclose(plist));
    TF_CHECK_HDF5(H5Sclose(space));
    // The attributes PETSc's readers and petsc_gen_xdmf.py look for.
    const int timestepping = 1;
    const hid_t scalar = H5Screate(H5S_SCALAR), str = H5Tcopy(H5T_C_S1);
    TF_CHECK_HDF5(H5Tset_size(str, std::strlen(type) + 1));
    hid_t attr = H5Acreate2(*dset, "timestepping", H5T_NATIVE_INT, scalar, H5P_DEFAULT, H5P_DEFAULT);
    TF_CHECK_HDF5(attr);
    TF_CHECK_HDF5(H5Awrite(attr, H5T_NATIVE_INT, &timestepping));
    TF_CHECK_HDF5(H5Aclose(attr));
    attr = H5Acreate2(*dset, "vector_field_type", str, scalar, H5P_DEFAULT, H5P_DEFAULT);
    TF_CHECK_HDF5(attr);
    TF_CHECK_HDF5(H5Awrite(attr, str, type));
    TF_CHECK_HDF5(H5Aclose(attr));
    if (step > 0) {
      const int first = (int)step; // the step a series starts at, if not the first (a tool of a second pass)
      attr = H5Acreate2(*dset, "first_step", H5T_NATIVE_INT, scalar, H5P_DEFAULT, H5P_DEFAULT);
      TF_CHECK_HDF5(attr);
      TF_CHECK_HDF5(H5Awrite(attr, H5T_NATIVE_INT, &first));
      TF_CHECK_HDF5(H5Aclose(attr));
    }
    TF_CHECK_HDF5(H5Tclose(str));
    TF_CHECK_HDF5(H5Sclose(scalar));
  } else {
    *dset = H5Dopen2(file, path, H5P_DEFAULT);
    TF_CHECK_HDF5(*dset);
    TF_CHECK_HDF5(H5Dset_extent(*dset, dims));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

// Writes `count` rows of `dims[1..]` at (step, first) from `values`; count 0: nothing from this rank.
PetscErrorCode WriteRows(hid_t dset, int ndims, const hsize_t dims[], PetscInt step, hsize_t first, hsize_t count,
                         const double *values)
{
  PetscFunctionBeginUser;
  const hid_t file_space = H5Dget_space(dset);
  TF_CHECK_HDF5(file_space);
  hsize_t start[3] = {(hsize_t)step, first, 0}, block[3] = {1, count, dims[2]};
  const hid_t mem_space = H5Screate_simple(ndims, block, nullptr);
  TF_CHECK_HDF5(mem_space);
  if (count > 0) {
    TF_CHECK_HDF5(H5Sselect_hyperslab(file_space, H5S_SELECT_SET, start, nullptr, block, nullptr));
  } else {
    TF_CHECK_HDF5(H5Sselect_none(file_space));
    TF_CHECK_HDF5(H5Sselect_none(mem_space));
  }
  TF_CHECK_HDF5(H5Dwrite(dset, H5T_NATIVE_DOUBLE, mem_space, file_space, H5P_DEFAULT, values));
  TF_CHECK_HDF5(H5Sclose(mem_space));
  TF_CHECK_HDF5(H5Sclose(file_space));
  PetscFunctionReturn(PETSC_SUCCESS);
}

} // namespace

PetscErrorCode WriteSeriesPairs(hid_t file, const char *path, const double *values, hsize_t rows, PetscInt step,
                                bool writer)
{
  hid_t dset;

  PetscFunctionBeginUser;
  hsize_t dims[3] = {0, rows, 2};
  PetscCall(OpenStep(file, path, 3, dims, step, "vector", &dset, !PathExists(file, path)));
  PetscCall(WriteRows(dset, 3, dims, step, 0, writer ? rows : 0, values));
  TF_CHECK_HDF5(H5Dclose(dset));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode WritePairsOnce(hid_t file, const char *path, hid_t type, const void *values, hsize_t rows, bool writer)
{
  PetscFunctionBeginUser;
  const std::string p = path;
  for (size_t slash = p.find('/', 1); slash != std::string::npos; slash = p.find('/', slash + 1)) {
    const std::string group = p.substr(0, slash);
    if (H5Lexists(file, group.c_str(), H5P_DEFAULT) > 0) continue;
    const hid_t g = H5Gcreate2(file, group.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    TF_CHECK_HDF5(g);
    TF_CHECK_HDF5(H5Gclose(g));
  }
  if (H5Lexists(file, path, H5P_DEFAULT) > 0) PetscFunctionReturn(PETSC_SUCCESS);
  hsize_t dims[2] = {rows, 2};
  const hid_t space = H5Screate_simple(2, dims, nullptr);
  TF_CHECK_HDF5(space);
  const hid_t dset = H5Dcreate2(file, path, type, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  TF_CHECK_HDF5(dset);
  if (!writer) TF_CHECK_HDF5(H5Sselect_none(space));
  const hid_t mem = H5Screate_simple(2, dims, nullptr);
  TF_CHECK_HDF5(mem);
  if (!writer) TF_CHECK_HDF5(H5Sselect_none(mem));
  TF_CHECK_HDF5(H5Dwrite(dset, type, mem, space, H5P_DEFAULT, values));
  TF_CHECK_HDF5(H5Sclose(mem));
  TF_CHECK_HDF5(H5Sclose(space));
  TF_CHECK_HDF5(H5Dclose(dset));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode WriteSeriesStep(hid_t file, const char *path, Vec global, PetscInt bs, PetscInt step)
{
  PetscInt n, lo, hi;
  const PetscScalar *a;
  hid_t dset;

  PetscFunctionBeginUser;
  PetscCall(VecGetSize(global, &n));
  PetscCall(VecGetOwnershipRange(global, &lo, &hi));
  const int ndims = bs > 1 ? 3 : 2;
  hsize_t dims[3] = {0, (hsize_t)(n / bs), (hsize_t)bs};
  PetscCall(OpenStep(file, path, ndims, dims, step, bs > 1 ? "vector" : "scalar", &dset));
  PetscCall(VecGetArrayRead(global, &a));
  PetscCall(WriteRows(dset, ndims, dims, step, (hsize_t)(lo / bs), (hsize_t)((hi - lo) / bs), a));
  PetscCall(VecRestoreArrayRead(global, &a));
  TF_CHECK_HDF5(H5Dclose(dset));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode WriteSeriesValue(hid_t file, const char *path, double value, PetscInt step, bool writer)
{
  hid_t dset;

  PetscFunctionBeginUser;
  hsize_t dims[3] = {0, 1, 1};
  PetscCall(OpenStep(file, path, 2, dims, step, "scalar", &dset));
  PetscCall(WriteRows(dset, 2, dims, step, 0, writer ? 1 : 0, &value));
  TF_CHECK_HDF5(H5Dclose(dset));
  PetscFunctionReturn(PETSC_SUCCESS);
}

bool PathExists(hid_t file, const std::string &path)
{
  for (size_t slash = path.find('/', 1);; slash = path.find('/', slash + 1)) {
    const std::string part = path.substr(0, slash);
    if (H5Lexists(file, part.c_str(), H5P_DEFAULT) <= 0) return false;
    if (slash == std::string::npos) return true;
  }
}

} // namespace tf
