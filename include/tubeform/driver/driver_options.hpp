// The incremental driver's own options (Options::driver and Options::accuracy, io/driver_params.hpp): read and checked
// here, in the driver, and handed to ReadOptions from above (main) as the scenes' readers are (SceneReaders).
#pragma once

#include <vector>

#include "tubeform/io/options.hpp"

namespace tf {

class OptionReader;
// Inside the driver's group of -help: the increments and r_min's bounds, the stops, the iterations, inertia, the
// kinematics and the factorization, into opt.driver.
PetscErrorCode ReadDriverOptions(PetscOptionItems *PetscOptionsObject, OptionReader &read, Options &opt);
// Collective: refuses the driver's values out of range, one line naming the option.
PetscErrorCode CheckDriverOptions(MPI_Comm comm, const Options &opt);
// Inside the accuracy group of -help: the error estimate, the accuracy demanded or expected and the levels' bounds,
// into opt.accuracy.
PetscErrorCode ReadAccuracyOptions(PetscOptionItems *PetscOptionsObject, OptionReader &read, Options &opt);
// Collective: refuses their values out of range, one line naming the option.
PetscErrorCode CheckAccuracyOptions(MPI_Comm comm, const Options &opt);
// The driver's two groups (each its reader and checker, with its title in -help), for ReadOptions.
std::vector<OptionGroup> DriverOptions();

} // namespace tf
