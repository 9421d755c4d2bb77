// The contact and friction options, read and checked by the contact layer whose parameters they are
// (contact/friction_params.hpp): the run's options hold them (Options::friction) so that they travel to its levels
// and companions, and the scenes with tools hand them to the contact set (scenes/contact_params.hpp).
#pragma once

#include <petscsys.h>

#include "tubeform/contact/friction_params.hpp"
#include "tubeform/core/option_reader.hpp"

namespace tf {

// Collective: -friction_mu, -friction_vcri, -friction_tol, -rmin_dphi and -rmin_dphi_rise into `f`, their own group
// in -help ("tubeform: contact and friction").
PetscErrorCode ReadFrictionOptions(MPI_Comm comm, OptionReader &read, FrictionParams &f);
// Collective: refuses their values out of range, one line naming the option (-friction_tol is refused with the
// friction iterations' counts, by the driver: CheckDriverOptions).
PetscErrorCode CheckFrictionOptions(MPI_Comm comm, const FrictionParams &f);

} // namespace tf
