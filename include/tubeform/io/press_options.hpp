// The press's own options (io/press_params.hpp), one group each, read and checked in its own file: each reader lists
// its options in -help inside the loading block (between PetscOptionsBegin and PetscOptionsEnd, whose
// PetscOptionsObject it takes), each checker refuses a bad value or a combination its options cannot take, in one line
// naming the option (the combinations another tool's option leads are that tool's checks: options_check.cpp).
#pragma once

#include <petscsys.h>

#include "tubeform/io/option_reader.hpp"
#include "tubeform/io/options.hpp"

namespace tf {

// -stroke, -stroke_corner_radius, -stroke_path into opt.stroke (stroke_options.cpp).
PetscErrorCode ReadStrokeOptions(PetscOptionItems *PetscOptionsObject, OptionReader &read, StrokeParams &s);
// Collective: refuses the stroke's values and the dies the corner-radius rule is not for; a -stroke_path sets the
// final stroke (after the upper die's checks: a -die_path sets it too, CheckOptions).
PetscErrorCode CheckStrokeOptions(MPI_Comm comm, Options &opt);
// -unload, -springback into opt.release (release_options.cpp).
PetscErrorCode ReadReleaseOptions(PetscOptionItems *PetscOptionsObject, OptionReader &read, ReleaseParams &r);
// Collective: refuses a release the model cannot take (after the dies' and passes' checks, CheckOptions).
PetscErrorCode CheckReleaseOptions(MPI_Comm comm, const Options &opt);
// -model, -die_offset, -full_hold into opt.model (model_options.cpp).
PetscErrorCode ReadModelOptions(PetscOptionItems *PetscOptionsObject, OptionReader &read, ModelParams &m);
// Collective: refuses a model the dies cannot take (the quarter without mirrored dies, a die off the axis without the
// full model), the die's offset out of range and a support the model or the forces cannot take (after the passes'
// turns, CheckOptions).
PetscErrorCode CheckModelOptions(MPI_Comm comm, const Options &opt);

} // namespace tf
