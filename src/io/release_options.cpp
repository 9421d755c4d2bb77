// The release's option: read into Options::release (in the loading block of -help, where it always was): the
// springback's law. (How a tool scene's pass lets the tube go, -unload, is the pass's: scenes/options/.)
#include "tubeform/io/loading_options.hpp"

namespace tf {

PetscErrorCode ReadReleaseOptions(PetscOptionItems *PetscOptionsObject, OptionReader &read, ReleaseParams &r)
{
  PetscFunctionBeginUser;
  PetscCall(ChooseWord(PetscOptionsObject, read, "-springback",
                       "The springback's law: material (the material's own, backstresses and all, as in loading), "
                       "elastic (the paper's: every point elastic; how far that carries points past the yield surface "
                       "is measured and reported), or auto: elastic for -unload reverse (its reversed contact forces "
                       "are dead loads, which can drive a thin wall into a collapse by the material's law), material "
                       "for -unload withdraw and the bending scene",
                       kSpringbackWords, r.springback));
  PetscFunctionReturn(PETSC_SUCCESS);
}

} // namespace tf
