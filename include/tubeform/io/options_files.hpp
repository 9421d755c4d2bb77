// The options files of a run, checked before PETSc reads them: PETSc stops on
// a missing -options_file with a 30-line error and its configure line. Every
// file on the command line, and every file those files name in turn (the
// scene files name options/solver.opts), must be readable.
#pragma once

#include <string>

namespace tf {

// The first problem found, as one line naming the option and the file (with a
// near name from the same folder when there is one), or "" if none. Paths are
// taken from the working directory, as PETSc takes them.
std::string CheckOptionsFiles(int argc, char **argv);

} // namespace tf
