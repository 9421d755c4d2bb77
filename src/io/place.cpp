// Room for the results and their placing: a write is refused before it
// starts when the file system lacks the room for it (parallel HDF5 does not
// recover from a full disk), room is held back for closing the file, and the
// finished files are renamed into place together.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <vector>

#include "tubeform/io/output.hpp"

namespace tf {

PetscErrorCode CheckRoom(MPI_Comm comm, const std::string &path, const char *option, double bytes, const char *what)
{
  PetscMPIInt rank;
  double free_bytes = -1; // (unknown: the file system does not say)

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (rank == 0) {
    std::error_code ec;
    const auto parent = std::filesystem::path(path).parent_path();
    const auto room = std::filesystem::space(parent.empty() ? "." : parent, ec);
    if (!ec) free_bytes = (double)room.available;
  }
  PetscCallMPI(MPI_Bcast(&free_bytes, 1, MPI_DOUBLE, 0, comm));
  const double need = bytes + kRoomMargin;
  PetscCheck(free_bytes < 0 || free_bytes >= need, comm, PETSC_ERR_FILE_WRITE,
             "%s %s: %.3g MB free on its file system, %s needs about %.3g MB (a full disk?); nothing is renamed "
             "into place (the results so far stay in %s.partial)",
             option, path.c_str(), free_bytes / 1e6, what, need / 1e6, path.c_str());
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode ResultWriter::Reserve()
{
  PetscMPIInt rank;
  int ok = 1;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(mesh_->comm, &rank));
  if (rank == 0) {
    std::ofstream room(ReservePath(), std::ios::binary);
    const std::vector<char> zeros((size_t)kRoomMargin, 0);
    room.write(zeros.data(), (std::streamsize)zeros.size());
    room.close();
    ok = !room.fail();
    if (!ok) std::remove(ReservePath().c_str());
  }
  PetscCallMPI(MPI_Bcast(&ok, 1, MPI_INT, 0, mesh_->comm));
  PetscCheck(ok, mesh_->comm, PETSC_ERR_FILE_WRITE,
             "-output %s: cannot write %s, the room kept for closing the results (a full disk?)", path_.c_str(),
             ReservePath().c_str());
  PetscFunctionReturn(PETSC_SUCCESS);
}

void ResultWriter::FreeReserve()
{
  int rank = 0;
  if (mesh_) (void)MPI_Comm_rank(mesh_->comm, &rank);
  if (rank == 0 && !path_.empty()) std::remove(ReservePath().c_str());
}

PetscErrorCode ResultWriter::Place(const std::string &csv)
{
  PetscMPIInt rank;
  enum { kPlaced, kNotRenamed, kNoCsv, kNoXdmf };
  int status = kPlaced;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(mesh_->comm, &rank));
  // Renames only: each new file replaces its earlier one whole, the results
  // first, the index (which names them) last.
  const auto place = [](const std::string &path) {
    return std::rename((path + ".partial").c_str(), path.c_str()) == 0;
  };
  if (rank == 0) {
    if (!place(path_))
      status = kNotRenamed;
    else if (!csv.empty() && !place(csv))
      status = kNoCsv;
    else if (!place(XdmfPath()))
      status = kNoXdmf, std::remove((XdmfPath() + ".partial").c_str());
  }
  PetscCallMPI(MPI_Bcast(&status, 1, MPI_INT, 0, mesh_->comm));
  PetscCheck(status != kNotRenamed, mesh_->comm, PETSC_ERR_FILE_WRITE,
             "-output %s: cannot rename the finished file into place", path_.c_str());
  PetscCheck(status != kNoCsv, mesh_->comm, PETSC_ERR_FILE_WRITE,
             "-history_csv %s: cannot rename the finished file into place (the results are in %s)", csv.c_str(),
             path_.c_str());
  PetscCheck(status != kNoXdmf, mesh_->comm, PETSC_ERR_FILE_WRITE,
             "-output %s: the results are written, but their ParaView index %s cannot be written", path_.c_str(),
             XdmfPath().c_str());
  PetscFunctionReturn(PETSC_SUCCESS);
}

} // namespace tf
