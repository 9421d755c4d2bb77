// The stroke's option: read into Options::stroke (in the loading block of -help, where it always was) and checked, one
// line naming the option. (The tool scenes' first pass's path of strokes and corner-radius rule are theirs: they set
// the stroke from them, scenes/options/.)
#include "tubeform/io/loading_options.hpp"

namespace tf {

PetscErrorCode ReadStrokeOptions(PetscOptionItems *PetscOptionsObject, OptionReader &read, StrokeParams &s)
{
  PetscFunctionBeginUser;
  PetscCall(read.Real(PetscOptionsObject, "-stroke",
                      "Final stroke U (mm): tool travel, or the prescribed end shortening of the column", s.u));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode CheckStrokeOptions(MPI_Comm comm, Options &opt)
{
  PetscFunctionBeginUser;
  PetscCheck(opt.stroke.u > 0, comm, PETSC_ERR_USER_INPUT, "-stroke %g: must be positive (mm)", opt.stroke.u);
  PetscFunctionReturn(PETSC_SUCCESS);
}

} // namespace tf
