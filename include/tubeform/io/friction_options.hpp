// The contact and friction options (Options::friction, io/friction_params.hpp), read and checked in io: the contact
// layer whose parameters they are lies below io and its option reader, as the material's does.
#pragma once

#include <petscsys.h>

#include "tubeform/io/option_reader.hpp"
#include "tubeform/io/options.hpp"

namespace tf {

// Collective: -friction_mu, -friction_vcri, -friction_tol, -rmin_dphi and -rmin_dphi_rise into opt.friction, their
// own group in -help ("tubeform: contact and friction").
PetscErrorCode ReadFrictionOptions(MPI_Comm comm, OptionReader &read, Options &opt);
// Collective: refuses their values out of range, one line naming the option (-friction_tol is refused with the
// friction iterations' counts, by the driver: CheckDriverOptions).
PetscErrorCode CheckFrictionOptions(MPI_Comm comm, const FrictionParams &f);

} // namespace tf
