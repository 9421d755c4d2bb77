// The tool scenes' options (squaring, flattening): the dies, their path and passes, the model of the tube.
#pragma once

#include <petscsys.h>

#include "tubeform/io/option_reader.hpp"
#include "tubeform/io/options.hpp"

namespace tf {

// Between PetscOptionsBegin and PetscOptionsEnd (it needs their PetscOptionsObject).
PetscErrorCode ReadToolOptions(PetscOptionItems *PetscOptionsObject, OptionReader &read, Options &opt);

} // namespace tf
