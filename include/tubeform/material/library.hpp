// Named materials: one options file per material in a library folder
// (options/materials/NAME.opts, docs/options.md "Materials"), read for
// -material NAME or -material path/to/file.opts. The file's values are the
// material's; -material_e, -material_sy, ... given on the command line or in a
// scene's options file override them one by one.
#pragma once

#include <petscsys.h>

#include <string>
#include <vector>

#include "tubeform/material/elastic.hpp"

namespace tf {

// The library folder: `dir` when given (-material_library), else the one this
// build was configured with (the source tree's options/materials).
std::string MaterialLibraryDir(const std::string &dir);

// The library's material names (its *.opts files, sorted), "" where it cannot be read.
std::vector<std::string> LibraryMaterials(const std::string &dir);

// The -material that keeps the built-in values for the user to set (LoadMaterial).
inline constexpr const char *kCustomMaterial = "custom";

// Fills `p` for -material `name`: "custom" keeps the built-in values for the
// user to override; a name with a '/' or ending in .opts is a file; any other
// name is a file of the library. Collective on comm; a one-line error naming
// the file and what is wrong (unknown name with the library's list, a missing
// or unreadable file, an option the file may not set, a missing constant).
PetscErrorCode LoadMaterial(MPI_Comm comm, const std::string &name, const std::string &dir, MaterialParams &p);

} // namespace tf
