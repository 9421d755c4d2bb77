// Changes to a finished result file that cannot lose it. The estimate of a run
// (attributes and columns of /history) is added on a copy, which replaces the
// file whole only once it is written (a rename), so that nothing that fails or
// stops meanwhile can touch the results; a level of accuracy on demand is kept
// as a copy while a finer one runs.
#include <hdf5.h>

#include <cstdio>
#include <filesystem>

#include "tubeform/io/output.hpp"

namespace tf {

namespace {

// Rank 0: the columns written into the open group (1-D datasets of doubles, replacing any of the same name).
bool WriteColumns(hid_t group, const std::vector<std::pair<std::string, std::vector<double>>> &columns)
{
  bool ok = true;
  for (const auto &[name, values] : columns) {
    if (!ok) break;
    if (H5Lexists(group, name.c_str(), H5P_DEFAULT) > 0) ok = H5Ldelete(group, name.c_str(), H5P_DEFAULT) >= 0;
    const hsize_t n = values.size();
    const hid_t space = ok ? H5Screate_simple(1, &n, nullptr) : -1;
    const hid_t set =
      space >= 0 ? H5Dcreate2(group, name.c_str(), H5T_NATIVE_DOUBLE, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT)
                 : -1;
    ok = set >= 0 && (n == 0 || H5Dwrite(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) >= 0);
    if (set >= 0) ok = H5Dclose(set) >= 0 && ok;
    if (space >= 0) H5Sclose(space);
  }
  return ok;
}

// Rank 0: the attributes and columns written into /history of the file at `path` (doubles, replacing any of the
// same name); "" or what failed.
std::string WriteEstimate(const std::string &path, const std::vector<std::pair<std::string, double>> &attributes,
                          const std::vector<std::pair<std::string, std::vector<double>>> &columns)
{
  const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  if (file < 0) return "HDF5 cannot open the copy";
  const hid_t group = H5Gopen2(file, "/history", H5P_DEFAULT), scalar = H5Screate(H5S_SCALAR);
  bool ok = group >= 0 && scalar >= 0;
  for (const auto &[name, value] : attributes) {
    if (!ok) break;
    if (H5Aexists(group, name.c_str()) > 0) ok = H5Adelete(group, name.c_str()) >= 0;
    const hid_t attr = ok ? H5Acreate2(group, name.c_str(), H5T_NATIVE_DOUBLE, scalar, H5P_DEFAULT, H5P_DEFAULT) : -1;
    ok = attr >= 0 && H5Awrite(attr, H5T_NATIVE_DOUBLE, &value) >= 0;
    if (attr >= 0) ok = H5Aclose(attr) >= 0 && ok;
  }
  ok = ok && WriteColumns(group, columns);
  if (scalar >= 0) H5Sclose(scalar);
  if (group >= 0) H5Gclose(group);
  ok = H5Fclose(file) >= 0 && ok; // (its flush finds a full disk)
  return ok ? "" : "writing the estimate into the copy failed (a full disk?)";
}

} // namespace

PetscErrorCode AddResultEstimate(MPI_Comm comm, const std::string &path,
                                 const std::vector<std::pair<std::string, double>> &attributes,
                                 const std::vector<std::pair<std::string, std::vector<double>>> &columns,
                                 std::string &why)
{
  PetscMPIInt rank;
  char text[PETSC_MAX_PATH_LEN] = "";

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (rank == 0) {
    const std::string copy = path + ".estimate.partial";
    std::error_code ec, on_size, on_room;
    std::string failed;
    const auto size = std::filesystem::file_size(path, on_size);
    const auto room = std::filesystem::space(std::filesystem::absolute(path, ec).parent_path(), on_room);
    if (!on_size && !on_room && (double)room.available < (double)size + kRoomMargin)
      failed = "no room for its copy (" + std::to_string((int)(room.available / 1000)) + " kB free, the file is " +
               std::to_string((int)(size / 1000)) + " kB)";
    else if (!std::filesystem::copy_file(path, copy, std::filesystem::copy_options::overwrite_existing, ec))
      failed = "cannot copy it (" + ec.message() + ")";
    else
      failed = WriteEstimate(copy, attributes, columns);
    if (failed.empty() && std::rename(copy.c_str(), path.c_str()) != 0) failed = "cannot rename the copy into place";
    if (!failed.empty()) std::remove(copy.c_str());
    PetscCall(PetscStrncpy(text, failed.c_str(), sizeof(text)));
  }
  PetscCallMPI(MPI_Bcast(text, sizeof(text), MPI_CHAR, 0, comm));
  why = text;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode KeepResultCopy(MPI_Comm comm, const std::string &path, const std::string &copy, std::string &why)
{
  PetscMPIInt rank;
  char text[PETSC_MAX_PATH_LEN] = "";

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (rank == 0) {
    std::error_code ec, on_size, on_room;
    std::string failed;
    const auto size = std::filesystem::file_size(path, on_size);
    const auto room = std::filesystem::space(std::filesystem::absolute(copy, ec).parent_path(), on_room);
    if (on_size)
      failed = "cannot read its size (" + on_size.message() + ")";
    else if (!on_room && (double)room.available < 2.0 * (double)size + kRoomMargin) // (the copy and a level beside)
      failed = "no room for a copy beside the next level (" + std::to_string((int)(room.available / 1000)) +
               " kB free, the file is " + std::to_string((int)(size / 1000)) + " kB)";
    else if (!std::filesystem::copy_file(path, copy, std::filesystem::copy_options::overwrite_existing, ec))
      failed = "cannot copy it (" + ec.message() + ")";
    if (!failed.empty()) std::remove(copy.c_str());
    PetscCall(PetscStrncpy(text, failed.c_str(), sizeof(text)));
  }
  PetscCallMPI(MPI_Bcast(text, sizeof(text), MPI_CHAR, 0, comm));
  why = text;
  PetscFunctionReturn(PETSC_SUCCESS);
}

} // namespace tf
