// A small text file every rank needs (a material file, a die's profile):
// read once on rank 0 and broadcast, so each rank parses the same text and
// reaches the same verdict.
#pragma once

#include <petscsys.h>

#include <string>

namespace tf {

// Collective: the file's contents, verbatim, on every rank; ok false (on every rank) if rank 0 cannot read it.
PetscErrorCode ReadTextOnRoot(MPI_Comm comm, const std::string &path, bool &ok, std::string &text);

} // namespace tf
