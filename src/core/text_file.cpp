#include "tubeform/core/text_file.hpp"

#include <fstream>

#include "tubeform/core/core.hpp"

namespace tf {

PetscErrorCode ReadTextOnRoot(MPI_Comm comm, const std::string &path, bool &ok, std::string &text)
{
  PetscMPIInt rank;
  long size = -1;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  text.clear();
  if (rank == 0) {
    std::ifstream in(path, std::ios::binary);
    char c;
    while (in.get(c)) text.push_back(c);
    if (in.eof()) size = (long)text.size(); // read to its end (an empty file too)
  }
  PetscCallMPI(MPI_Bcast(&size, 1, MPI_LONG, 0, comm));
  ok = size >= 0;
  text.resize(ok ? size : 0);
  if (size > 0) PetscCallMPI(MPI_Bcast(&text[0], (PetscMPIInt)size, MPI_CHAR, 0, comm));
  PetscFunctionReturn(PETSC_SUCCESS);
}

} // namespace tf
