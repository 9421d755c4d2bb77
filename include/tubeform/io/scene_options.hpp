// The options of the scenes without tools: shear, slide, tension, bending, rotation, column (their loads and
// sizes; the pressure scene's are read with the loads).
#pragma once

#include <petscsys.h>

#include "tubeform/io/option_reader.hpp"
#include "tubeform/io/options.hpp"

namespace tf {

// Between PetscOptionsBegin and PetscOptionsEnd (it needs their PetscOptionsObject).
PetscErrorCode ReadSceneSizes(PetscOptionItems *PetscOptionsObject, OptionReader &read, Options &opt);

} // namespace tf
