// The r_min controller of METHOD.md section 4 (Yamada et al. 1968; paper eq. 16):
// every increment is a linear solution for a trial step, scaled by
//   r_min = min(1, r1, ..., r6)
// so that nothing that would make it non-linear happens inside it. Each factor
// is a named function here; contact adds r4-r6 with the tools.
#pragma once

#include <petscsys.h>

#include "tubeform/fe/quad.hpp"
#include "tubeform/io/history.hpp"

namespace tf {

// The smallest factor offered so far, what it was and where (input numbering of
// the element or node).
struct StepLimit {
  double r = 1e300;
  Limiter who = Limiter::Trial;
  PetscInt where = -1;
  void Offer(double factor, Limiter what, PetscInt at)
  {
    if (factor < r) r = factor, who = what, where = at;
  }
};

// Collective: the global minimum over ranks (ties go to the lower rank).
PetscErrorCode ReduceStepLimit(MPI_Comm comm, StepLimit &limit);

// Largest absolute principal value of a Voigt strain {xx, yy, zz, gamma_xy}.
double MaxPrincipalStrain(const fe::Voigt &e);

// r2: the factor that brings the largest principal strain increment to deps_max.
inline double StrainFactor(const fe::Voigt &deps, double deps_max)
{
  const double e = MaxPrincipalStrain(deps);
  return e > 0 ? deps_max / e : 1e300;
}

// r3: the factor that brings the rotation increment |omega| to domega_max.
inline double RotationFactor(double omega, double domega_max) { return omega != 0 ? domega_max / std::abs(omega) : 1e300; }

} // namespace tf
