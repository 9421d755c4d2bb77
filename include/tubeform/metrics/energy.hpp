// The energy accounts of a run and its two self-checks (docs/theory.md,
// "Self-checks"), per unit length of the modelled part (N mm/mm), accumulated
// increment by increment. Each side of a check comes from other quantities:
//   (a) work put in = internal work + friction dissipation + inertia work,
//       the input taken from the reported load and stroke where they are
//       work-conjugate (a tool: half the punch load times the stroke for the
//       quarter tube), else from the loads and supports at the nodes; the
//       friction dissipation from the contact slips, the internal work from
//       stresses and strain increments, the inertia work (= kinetic energy +
//       the energy backward Euler damps) from the accelerations, all by the
//       same trapezoidal rule;
//   (b) internal work = plastic dissipation + stored elastic energy,
//       the plastic part from the flow stress and plastic strain increments,
//       the elastic part from the current stresses.
// Each relative to the largest its reference (the work put in, the internal
// work) has been so far: a springback that gives an elastic press's work back
// leaves them near 0, where the difference relative to them would mean nothing.
#pragma once

#include <algorithm>
#include <cmath>

#include "tubeform/core/core.hpp"

namespace tf {

struct EnergyAccount {
  double w_ext = 0;      // work put into the model (check (a)'s input)
  double w_tool = 0;     // the part of w_ext measured from the reported load and stroke
  double w_int = 0;      // stress work, sum sigma_mid : deps dV
  double w_plastic = 0;  // plastic dissipation, sum sigma_y,mid dep dV
  double w_friction = 0; // friction dissipation, -sum f_l,mid dslip
  double w_inertia = 0;  // work of the inertia forces (trapezoidal) = kinetic + damped energy
  double ext_peak = 0;   // the largest |w_ext| so far
  double int_peak = 0;   // the largest |w_int| so far

  // The peaks, once the increment's works are added.
  void TakePeaks() { ext_peak = std::max(ext_peak, std::abs(w_ext)), int_peak = std::max(int_peak, std::abs(w_int)); }
  // (a) (w_ext - w_int - w_friction - w_inertia) / the largest |w_ext| so far
  double BalanceError() const { return (w_ext - w_int - w_friction - w_inertia) / std::max(ext_peak, kTiny); }
  // (b) (w_int - w_plastic - w_elastic) / the largest |w_int| so far
  double InternalError(double w_elastic) const { return (w_int - w_plastic - w_elastic) / std::max(int_peak, kTiny); }
};

} // namespace tf
