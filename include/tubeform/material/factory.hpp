// The constitutive law of a run from its material parameters.
#pragma once

#include <memory>

#include "tubeform/material/elastic.hpp"

namespace tf {

// law "elastic": linear elastic; "ludwik", "swift", "table": J2 plasticity
// with that flow curve. `dep_ref` is the plastic strain step over which H' is
// taken as a secant before a point has yielded once (the strain-limit step,
// -rmin_deps); `drift_correction` scales plastic stresses back onto the yield
// surface after each update.
std::unique_ptr<Material> MakeMaterial(const MaterialParams &m, double dep_ref, bool drift_correction);

} // namespace tf
