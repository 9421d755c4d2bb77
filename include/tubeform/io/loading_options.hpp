// The loading's own options (io/press_params.hpp), read by every scene that loads by a stroke (the tool scenes, the
// column) or releases (the tool scenes, the bending): each reader lists its options in -help inside the loading
// block (between PetscOptionsBegin and PetscOptionsEnd, whose PetscOptionsObject it takes), each checker refuses a
// bad value or a combination its options cannot take, in one line naming the option. The tool scenes' own options
// (the model, the passes, the dies, the first pass's path of strokes and release) are theirs: scenes/tool_options.hpp.
#pragma once

#include <petscsys.h>

#include "tubeform/core/option_reader.hpp"
#include "tubeform/io/options.hpp"

namespace tf {

// -stroke into opt.stroke (stroke_options.cpp).
PetscErrorCode ReadStrokeOptions(PetscOptionItems *PetscOptionsObject, OptionReader &read, StrokeParams &s);
// Collective: refuses the stroke's value (after the tool scenes' checks, which set it from the first pass's
// -stroke_path or -die_path: CheckOptions).
PetscErrorCode CheckStrokeOptions(MPI_Comm comm, Options &opt);
// -springback into opt.release (release_options.cpp).
PetscErrorCode ReadReleaseOptions(PetscOptionItems *PetscOptionsObject, OptionReader &read, ReleaseParams &r);

} // namespace tf
