// The r factors of the r_min controller (docs/theory.md section 5; Yamada et al.
// 1968; paper eq. 16): every increment is a linear solution for a trial step,
// scaled by r_min = min(1, r1, ..., r6) so that nothing that would make it
// non-linear happens inside it. The Gauss-point factors (r1-r3) are computed
// by the body, the contact factors (r4-r6) by the contact set; this header
// names them and keeps the running minimum.
#pragma once

#include <petscsys.h>

#include "tubeform/core/core.hpp"
#include "tubeform/fe/quad.hpp"

namespace tf {

// What set the size of an increment (the r_min factor that won, or the end of
// the load path). Stored in the history as its integer code.
enum class Limiter : int {
  Trial = 0,
  Final = 1,
  Yield = 2,
  Strain = 3,
  Rotation = 4,
  Contact = 5,
  Separation = 6,
  Stick = 7,
  Slide = 8
};
constexpr int kNumLimiters = 9;
const char *LimiterName(int code);

// The stall watch (-rmin_stall_increments): a window of increments that
// together advance the load parameter by less than this is a stall (the
// finished paper runs advance by at least 4.9e-5 over any 1000 increments,
// the stalled ones by 3.2e-7 and 1.6e-7: docs/theory.md, "Stalls").
constexpr double kStallAdvance = 1e-6;

// The smallest factor offered so far, what it was and where (input numbering of
// the element or node).
struct StepLimit {
  double r = kNever;
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
  return e > 0 ? deps_max / e : kNever;
}

// r3: the factor that brings the rotation increment |omega| to domega_max.
inline double RotationFactor(double omega, double domega_max)
{
  return omega != 0 ? domega_max / std::abs(omega) : kNever;
}

} // namespace tf
