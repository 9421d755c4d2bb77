// The energy accounts of a run (per unit length of the modelled part, N mm/mm),
// accumulated increment by increment (METHOD.md section 6).
#pragma once

#include <algorithm>
#include <cmath>

#include "tubeform/core/core.hpp"

namespace tf {

struct EnergyAccount {
  double w_ext = 0;      // the tools' and loads' work: body external work + friction dissipation
  double w_int = 0;      // stress work, sum sigma_mid : deps dV
  double w_plastic = 0;  // plastic dissipation, sum sigma_y,mid dep dV
  double w_friction = 0; // friction dissipation, -sum f_l,mid dslip
  double w_inertia = 0;  // work of the inertia forces (trapezoidal)

  // (w_ext - w_int - w_friction - w_inertia) / |w_ext|
  double Error() const { return (w_ext - w_int - w_friction - w_inertia) / std::max(std::abs(w_ext), kTiny); }
};

} // namespace tf
