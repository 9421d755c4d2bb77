// The incremental driver's own options (Options::driver, io/driver_params.hpp): read and checked here, in the
// driver, and handed to ReadOptions from above (main) as the scenes' readers are (SceneReaders).
#pragma once

#include "tubeform/io/options.hpp"

namespace tf {

class OptionReader;
// Inside the driver's group of -help: the increments and r_min's bounds, the stops, the iterations, inertia, the
// kinematics and the factorization, into opt.driver.
PetscErrorCode ReadDriverOptions(PetscOptionItems *PetscOptionsObject, OptionReader &read, Options &opt);
// Collective: refuses the driver's values out of range, one line naming the option.
PetscErrorCode CheckDriverOptions(MPI_Comm comm, const Options &opt);
// Both, with the title of their group in -help, for ReadOptions.
OptionGroup DriverOptions();

} // namespace tf
