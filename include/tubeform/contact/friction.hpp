// The regularized Coulomb law of docs/theory.md section 6 (paper eqs. 9-14), as a
// pure kernel. The friction force on the body, along the contact frame's l, is
//   f_l = -mu f_n phi(x),  phi(x) = tanh(x / (VCRI / 3)),
// where x is the node's slip relative to the tool, accumulated increment by
// increment (x += du_l - dU.l) and kept within +-2 VCRI. For one increment
// from x = 0 this is the paper's law with x = du_rel; accumulating x makes the
// result independent of the increment size: a block sliding steadily carries
// mu f_n however small r_min makes the increments (decision, docs/theory.md).
#pragma once

#include <algorithm>
#include <cmath>

#include "tubeform/core/core.hpp"

namespace tf::friction {

inline double Cap(double x, double vcri) { return std::max(-2 * vcri, std::min(2 * vcri, x)); }
// The mobilization of the (capped) slip state, and its derivative: zero past
// the cap, where more slip no longer changes the state.
inline double Phi(double x, double vcri) { return std::tanh(3.0 * Cap(x, vcri) / vcri); }
inline double DPhi(double x, double vcri)
{
  if (std::abs(x) >= 2 * vcri) return 0.0;
  const double t = Phi(x, vcri);
  return 3.0 * (1 - t * t) / vcri;
}

// Sliding on an arc turns the node's frame (paper eq. 13): with slip s along l
// and kappa = +1/rho on concave arcs, -1/rho on convex ones, 0 on lines,
//   dn = -kappa s l,  dl = kappa s n,
// so the contact force F = f_n n + f_l l changes in the frame of the step's
// start by
//   dF.n = df_n + kappa f_l s,   dF.l = df_l - kappa f_n s   (eq. 15).
// A tool that turns by w in the step (counter-clockwise) turns the frame by w
// more: kappa s becomes kappa s + w in both.
// The system's n row gives dF.n as the reaction R_n; the normal force itself
// changes by
inline double NormalIncrement(double reaction_n, double kappa, double f_l, double s, double w = 0)
{
  return reaction_n - kappa * f_l * s - f_l * w;
}

// Terms of the linearized l-row of a contact node for friction iterate k
// (paper eq. 14-15). With t = phi(x0 + dx_k), t' = phi'(x0 + dx_k),
// dx = du_l - dU_l, and df_n = R_n - kappa f_lk dx (NormalIncrement, with the
// iterate's friction force f_lk = -mu f_nk t):
//   (K du)_l + mu t df_n + (mu f_nk t' + f_nk kappa) du_l
//       = dF_l + mu f_n0 (phi(x0) - t) + mu f_nk t' (dx_k + dU_l) + f_nk kappa dU_l.
// R_n = (K du)_n - dF_n is row n of the system, so row_l += (mu t) row_n (the
// unsymmetric correction row) and the curvature part of df_n,
// mu t kappa mu f_nk t dx, joins the diagonal and load. The tool's turn w in
// the step (kappa dx + w for kappa dx) moves (f_nk + mu t mu f_nk t) w to the
// load's side with the opposite sign.
struct RowTerms {
  double row_n_coeff = 0; // multiplier of row n (and its load) added to row l
  double diag = 0;        // added to K_ll
  double rhs = 0;         // added to the l load
};

// The fraction r of the slip increment dx (from state x0) at which the
// mobilization reaches `target` (|target| < 1), exact on the law.
inline double FractionReaching(double x0, double dx, double vcri, double target)
{
  return (vcri / 3.0 * std::atanh(target) - Cap(x0, vcri)) / dx;
}

// r6 of docs/theory.md section 5, slide to stick: the fraction r of the slip increment
// dx (from state x0) at which the mobilization phi = tanh(3x/VCRI) has fallen
// by dphi_max from phi(x0), towards stick or through it into a reversal;
// exact on the law (x0 + r dx lands where phi = phi(x0) - sign(phi(x0)) dphi_max).
// Infinite (no limit) while phi grows in its direction or falls by less.
inline double StickFactor(double x0, double dx, double vcri, double dphi_max)
{
  const double phi0 = Phi(x0, vcri), phi1 = Phi(x0 + dx, vcri);
  const double fall = phi0 > 0 ? phi0 - phi1 : phi0 < 0 ? phi1 - phi0 : 0.0;
  if (!(fall > dphi_max)) return kNever;
  const double target = phi0 > 0 ? phi0 - dphi_max : phi0 + dphi_max; // |target| < 1: the fall exceeds dphi_max
  return FractionReaching(x0, dx, vcri, target);
}

// The same event the other way, stick to slide: the fraction r of dx at which
// the mobilization has risen by dphi_max in magnitude (in the direction it
// moves; a reversal through zero is StickFactor's). Infinite while it rises
// by less, or with dphi_max >= 1 (a rise never exceeds 1: no bound).
inline double SlideFactor(double x0, double dx, double vcri, double dphi_max)
{
  const double phi0 = Phi(x0, vcri), phi1 = Phi(x0 + dx, vcri);
  if (phi0 * phi1 < 0 || !(std::abs(phi1) - std::abs(phi0) > dphi_max)) return kNever;
  const double target = phi1 > 0 ? std::abs(phi0) + dphi_max : -(std::abs(phi0) + dphi_max);
  return FractionReaching(x0, dx, vcri, target);
}

// The friction force on the body along l for normal force fn and slip state x.
inline double Force(double mu, double vcri, double fn, double x) { return -mu * fn * Phi(x, vcri); }

// The stiffness of the stick spring, mu f_nk phi', is taken with the positive
// part of f_nk: a tensile iterate (a node about to separate, its step cut by
// r5) would otherwise give a negative tangential stiffness and can make the
// iterations diverge. Only the iteration matrix changes, not the converged
// solution: the same factor multiplies du_l and its right-hand-side partner.
inline RowTerms Linearize(double mu, double vcri, double fn0, double fnk, double x0, double dxk, double dU_l,
                          double kappa, double w = 0)
{
  RowTerms t;
  const double tk = Phi(x0 + dxk, vcri), dtk = DPhi(x0 + dxk, vcri) * (fnk > 0 ? 1.0 : 0.0);
  t.row_n_coeff = mu * tk;
  const double turn = mu * tk * kappa * mu * fnk * tk; // n-row curvature term through the coupling row
  t.diag = mu * fnk * dtk + fnk * kappa + turn;
  t.rhs = mu * fn0 * (Phi(x0, vcri) - tk) + mu * fnk * dtk * (dxk + dU_l) + (fnk * kappa + turn) * dU_l -
          (fnk + mu * tk * mu * fnk * tk) * w;
  return t;
}

} // namespace tf::friction
