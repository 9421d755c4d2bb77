#include "tubeform/material/j2.hpp"

#include <algorithm>
#include <cmath>

namespace tf {

J2Plasticity::J2Plasticity(double e, double nu, std::unique_ptr<Hardening> h, double dep_ref, bool drift_correction,
                           PlasticUpdate update)
    : elastic_(e, nu), h_(std::move(h)), g_(e / (2 * (1 + nu))), dep_ref_(dep_ref), drift_correction_(drift_correction),
      update_(update)
{}

Mat4 J2Plasticity::Tangent(const PointState &s) const
{
  Mat4 d = elastic_.matrix();
  if (!s.plastic) return d;
  const Voigt dev = Deviator(s.sigma);
  const double sbar = VonMises(s.sigma);
  if (!(sbar > 0)) return d;
  // Paper eq. 1: D_ep = D_e - 9 G^2 / (sbar^2 (3G + H')) s s^T (Voigt s acts on gamma_xy as s_xy).
  const double beta = 9 * g_ * g_ / (sbar * sbar * (3 * g_ + Modulus(s)));
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) d[r][c] -= beta * dev[r] * dev[c];
  return d;
}

Mat4 J2Plasticity::StepTangent(const PointState &s, const Voigt &deps) const
{
  if (update_ != PlasticUpdate::Radial || !s.plastic) return Tangent(s);
  const ReturnStep rs = Return(s, deps);
  if (!rs.flows) return Tangent(s);
  // d sigma = C_e d eps - 2G (1 - f) I_dev d eps - 2G theta n (x) n d eps, with f = 1 - 3G dep / sbar_tr the
  // deviator's shrink and theta = 3G / (3G + H') - (1 - f): the return's own derivative, H' at its end.
  const double f = rs.f, theta = 3 * g_ / (3 * g_ + SlopeAt(s.ep + rs.dep)) - (1 - f);
  Mat4 d = elastic_.matrix();
  const double bulk = elastic_.bulk_modulus();
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) d[r][c] = (r < 3 && c < 3 ? bulk * (1 - f) : 0) + f * d[r][c];
  const Voigt dev = Deviator(rs.trial);
  const double beta = 3 * g_ * theta / (rs.sbar_tr * rs.sbar_tr);
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) d[r][c] -= beta * dev[r] * dev[c];
  return d;
}

double J2Plasticity::SlopeAt(double ep) const
{
  const double h = std::min(kSlopeStep, 0.5 * ep);
  return h > 0 ? h_->SecantSlope(ep - h, 2 * h) : h_->SecantSlope(ep, kSlopeStep);
}

namespace {

// The root of g, increasing, with g(lo) < 0 < g(hi): the bracket is first
// narrowed at `guess` (the step the last plastic modulus predicts: the root
// itself when H' is constant), then regula falsi (Illinois) to round-off.
template <class G>
double Root(const G &g, double lo, double hi, double glo, double ghi, double guess)
{
  if (guess > 0) {
    const double gx = guess < hi ? g(guess) : 1.0;
    if (gx == 0) return guess;
    if (gx < 0)
      lo = guess, glo = gx;
    else if (guess < hi)
      hi = guess, ghi = gx;
  }
  int side = 0;
  for (int it = 0; it < kPlasticStepIterations && hi - lo > kPlasticStepTol * hi; ++it) {
    const double x = (lo * ghi - hi * glo) / (ghi - glo), gx = g(x);
    if (gx == 0) return x;
    if (gx < 0) {
      lo = x, glo = gx;
      if (side == -1) ghi *= 0.5;
      side = -1;
    } else {
      hi = x, ghi = gx;
      if (side == 1) glo *= 0.5;
      side = 1;
    }
  }
  return 0.5 * (lo + hi);
}

} // namespace

double KinematicShare::Value(double x) const
{
  double v = 0;
  for (int i = 0; i < n; ++i) v += gamma[i] > 0 ? amp[i] * -std::expm1(-gamma[i] * x) : amp[i] * x;
  return v;
}

double KinematicShare::Slope() const
{
  double v = 0;
  for (int i = 0; i < n; ++i) v += gamma[i] > 0 ? amp[i] * gamma[i] : amp[i];
  return v;
}

double J2Plasticity::PlasticStep(double ep, double a, double sbar, double hslope, const KinematicShare *kin) const
{
  // g(dep) = 3G dep + sigma_y(ep + dep) - sigma_y(ep) [+ the backstresses' share] - 3G a / sbar
  // is increasing, g(0) < 0 <= g(a / sbar): bracketed.
  const double target = 3 * g_ * a / sbar, s0 = h_->YieldStress(ep), hi = a / sbar;
  if (kin) {
    const auto g = [&](double x) { return 3 * g_ * x + h_->YieldStress(ep + x) - s0 + kin->Value(x) - target; };
    const double glo = g(0), ghi = g(hi);
    if (ghi <= 0) return hi;
    return Root(g, 0, hi, glo, ghi, hslope > 0 ? target / (3 * g_ + hslope + kin->Slope()) : 0);
  }
  const auto g = [&](double x) { return 3 * g_ * x + h_->YieldStress(ep + x) - s0 - target; };
  const double glo = g(0), ghi = g(hi);
  if (ghi <= 0) return hi;
  return Root(g, 0, hi, glo, ghi, hslope > 0 ? target / (3 * g_ + hslope) : 0);
}

double J2Plasticity::SecantStep(double ep, double target, double m, double hi, double hslope) const
{
  const double s0 = h_->YieldStress(ep);
  const auto g = [&](double x) { return m * x + h_->YieldStress(ep + x) - s0 - target; };
  const double glo = g(0), ghi = g(hi);
  if (ghi <= 0) return hi;
  return Root(g, 0, hi, glo, ghi, hslope > 0 ? target / (m + hslope) : 0);
}

Voigt J2Plasticity::Trial(const PointState &s, const Voigt &deps) const
{
  const double trace = deps[0] + deps[1] + deps[2];
  const Voigt dsig = ElasticStress(deps);
  Voigt trial;
  for (int r = 0; r < 4; ++r) trial[r] = s.sigma[r] + (dsig[r] - s.sigma[r] * trace);
  return trial;
}

bool J2Plasticity::TrialFlows(const PointState &s, double sbar_tr, double sy) const
{
  return sbar_tr > std::max(VonMises(s.sigma), sy) + kFlowTie * sy;
}

J2Plasticity::ReturnStep J2Plasticity::Return(const PointState &s, const Voigt &deps) const
{
  ReturnStep rs;
  rs.trial = Trial(s, deps);
  rs.sbar_tr = VonMises(rs.trial), rs.sy_old = h_->YieldStress(s.ep);
  rs.flows = TrialFlows(s, rs.sbar_tr, rs.sy_old);
  if (!rs.flows) return rs;
  // 3G dep + sigma_y(ep + dep) = sbar_tr: the deviator shrinks along itself to
  // sbar_tr - 3G dep = sigma_y(ep + dep), the pressure kept.
  const double over = rs.sbar_tr - rs.sy_old;
  rs.dep = SecantStep(s.ep, over, 3 * g_, over / (3 * g_), s.hslope);
  rs.f = 1 - 3 * g_ * rs.dep / rs.sbar_tr;
  return rs;
}

UpdateInfo J2Plasticity::RadialReturn(PointState &s, const Voigt &deps) const
{
  // Whatever the point's flag: the update is a function of the increment from
  // the start state (an elastic point's trial passes the surface only where
  // its onset lies inside the step).
  UpdateInfo info;
  const ReturnStep rs = Return(s, deps);
  const Voigt &trial = rs.trial;
  const double sy_old = rs.sy_old, dep = rs.dep;
  s.plastic = rs.flows;
  s.sigma = trial;
  if (!s.plastic) return info;
  const double sy_new = h_->YieldStress(s.ep + dep);
  const double p = (trial[0] + trial[1] + trial[2]) / 3;
  for (int r = 0; r < 3; ++r) s.sigma[r] = p + rs.f * (trial[r] - p);
  s.sigma[3] = rs.f * trial[3];
  if (dep > 0) s.hslope = (sy_new - sy_old) / dep;
  s.ep += dep;
  info.dwp = 0.5 * (sy_old + sy_new) * dep;
  info.drift = VonMises(s.sigma) / sy_new - 1; // round-off
  return info;
}

UpdateInfo J2Plasticity::Update(PointState &s, const Voigt &deps) const
{
  if (update_ == PlasticUpdate::Radial) return RadialReturn(s, deps);
  UpdateInfo info;
  const double trace = deps[0] + deps[1] + deps[2];
  const Voigt dev = Deviator(s.sigma);
  const double sbar = VonMises(s.sigma), a = DevDotStrain(dev, deps);
  const Voigt dsig = ElasticStress(deps);
  if (s.plastic && a > 0 && sbar > 0) {
    // Tangent update with H' the secant over this step's own plastic strain:
    // dsigma = C_e de - 3G (dep / sbar) s, exact on a proportional path.
    const double dep = PlasticStep(s.ep, a, sbar, s.hslope);
    const double sy_old = h_->YieldStress(s.ep), sy_new = h_->YieldStress(s.ep + dep);
    for (int r = 0; r < 4; ++r) s.sigma[r] += dsig[r] - 3 * g_ * dep / sbar * dev[r] - s.sigma[r] * trace;
    if (dep > 0) s.hslope = (sy_new - sy_old) / dep;
    s.ep += dep;
    info.dwp = 0.5 * (sy_old + sy_new) * dep;
    const double sbar_new = VonMises(s.sigma);
    info.drift = sbar_new / sy_new - 1;
    if (drift_correction_ && sbar_new > 0) {
      // Scale the deviator back onto the yield surface, pressure kept.
      const double p = (s.sigma[0] + s.sigma[1] + s.sigma[2]) / 3, f = sy_new / sbar_new;
      for (int r = 0; r < 3; ++r) s.sigma[r] = p + f * (s.sigma[r] - p);
      s.sigma[3] *= f;
    }
  } else {
    for (int r = 0; r < 4; ++r) s.sigma[r] += dsig[r] - s.sigma[r] * trace;
    if (s.plastic && a <= 0) s.plastic = false; // elastic unloading
  }
  return info;
}

double J2Plasticity::YieldOnset(const PointState &s, const Voigt &deps, double omega) const
{
  if (s.plastic) return kNever;
  // On the surface (within kOnSurface) or past it: not an r1 event; a loading
  // point there is switched to plastic by Loading, or marked at the commit.
  const double sy = h_->YieldStress(s.ep);
  if (VonMises(s.sigma) >= (1 - kOnSurface) * sy) return kNever;
  // Linear stress path sigma + r dsigma; 3/2 |dev(sigma + r dsigma)|^2 = sigma_y^2 is a quadratic in r.
  const Voigt s0 = Deviator(s.sigma), d1 = Deviator(ElasticPath(s, deps, omega));
  return OnsetRoot(1.5 * TensorDot(d1, d1), 3 * TensorDot(s0, d1), 1.5 * TensorDot(s0, s0) - sy * sy);
}

Voigt J2Plasticity::ElasticStress(const Voigt &deps) const
{
  Voigt ds{};
  const Mat4 &de = elastic_.matrix();
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) ds[r] += de[r][c] * deps[c];
  return ds;
}

Voigt J2Plasticity::ElasticPath(const PointState &s, const Voigt &deps, double omega) const
{
  Voigt ds = ElasticStress(deps);
  Voigt rotated = s.sigma;
  RotateStress(ObjectiveScheme::Forward, omega, rotated);
  const double trace = deps[0] + deps[1] + deps[2];
  for (int r = 0; r < 4; ++r) ds[r] += rotated[r] - s.sigma[r] - s.sigma[r] * trace;
  return ds;
}

double J2Plasticity::OnsetRoot(double qa, double qb, double qc)
{
  if (qa <= 0) return kNever;
  const double root = std::sqrt(qb * qb - 4 * qa * qc); // real since qc < 0 < qa
  // The positive root, in the form free of cancellation for either sign of qb.
  return qb >= 0 ? -2 * qc / (qb + root) : (-qb + root) / (2 * qa);
}

bool J2Plasticity::Loading(const PointState &s, const Voigt &deps) const
{
  // Radial return: a point on the surface flows when its trial passes it, as
  // RadialReturn decides (inside the surface: the elastic fraction's business).
  if (update_ == PlasticUpdate::Radial)
    return (s.plastic || OnSurface(s)) && TrialFlows(s, VonMises(Trial(s, deps)), h_->YieldStress(s.ep));
  const double a = DevDotStrain(Deviator(s.sigma), deps);
  if (s.plastic) return a > 0;
  return a > 0 && VonMises(s.sigma) >= (1 - kOnSurface) * h_->YieldStress(s.ep);
}

} // namespace tf
