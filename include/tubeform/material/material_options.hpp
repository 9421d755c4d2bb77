// The material's own options (docs/options.md, "Materials"): read into a MaterialParams in their block of -help,
// "tubeform: material", and checked, one line naming the option, whichever way the constants came (the -material_*
// options, a material file, the library: material/library.hpp).
#pragma once

#include <petscsys.h>

#include "tubeform/core/option_reader.hpp"
#include "tubeform/material/elastic.hpp"

namespace tf {

// Collective: -material (LoadMaterial) and the -material_*, -hardening options that override its values, in their
// own block of -help (material_options.cpp).
PetscErrorCode ReadMaterialOptions(MPI_Comm comm, OptionReader &read, MaterialParams &material);
// Collective: refuses material constants out of range or not in MPa (material_check.cpp).
PetscErrorCode CheckMaterial(MPI_Comm comm, const MaterialParams &m);

} // namespace tf
