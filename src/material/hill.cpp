#include "tubeform/material/hill.hpp"

#include <cmath>

namespace tf {

namespace {

// Stress (or any tensor in Voigt tensor form) in axes turned by `angle`
// (counter-clockwise): {rr, hh, zz, rh} for the radial axis at `angle`.
Voigt ToAxes(const Voigt &t, double angle)
{
  const double c = std::cos(angle), s = std::sin(angle);
  return {c * c * t[0] + s * s * t[1] + 2 * c * s * t[3], s * s * t[0] + c * c * t[1] - 2 * c * s * t[3], t[2],
          -c * s * t[0] + c * s * t[1] + (c * c - s * s) * t[3]};
}

Voigt FromAxes(const Voigt &t, double angle) { return ToAxes(t, -angle); }

} // namespace

std::array<double, 4> HillFromR(double r0, double r90)
{
  const double g = 1 / (1 + r0), h = r0 / (1 + r0), f = r0 / (r90 * (1 + r0));
  return {f, g, h, 1.5};
}

HillPlasticity::HillPlasticity(double e, double nu, std::unique_ptr<Hardening> h, const std::array<double, 4> &fghl,
                               double dep_ref, bool drift_correction)
    : J2Plasticity(e, nu, std::move(h), dep_ref, drift_correction), f_(fghl[0]), g_h_(fghl[1]), h_h_(fghl[2]),
      l_(fghl[3])
{}

double HillPlasticity::Bilinear(const Voigt &a, const Voigt &b, double frame) const
{
  // In the axes: 1 = axial (zz), 2 = hoop, 3 = radial.
  const Voigt x = ToAxes(a, frame), y = ToAxes(b, frame);
  const double a1 = x[2], a2 = x[1], a3 = x[0], b1 = y[2], b2 = y[1], b3 = y[0];
  return f_ * (a2 - a3) * (b2 - b3) + g_h_ * (a3 - a1) * (b3 - b1) + h_h_ * (a1 - a2) * (b1 - b2) +
         2 * l_ * x[3] * y[3];
}

double HillPlasticity::Quadratic(const Voigt &sigma, double frame) const { return Bilinear(sigma, sigma, frame); }

double HillPlasticity::Equivalent(const Voigt &sigma, double frame) const
{
  return std::sqrt(std::max(Quadratic(sigma, frame), 0.0));
}

Voigt HillPlasticity::Normal(const Voigt &sigma, double frame, double &eq) const
{
  const Voigt x = ToAxes(sigma, frame);
  const double s1 = x[2], s2 = x[1], s3 = x[0];
  eq = Equivalent(sigma, frame);
  if (!(eq > 0)) return {};
  // d sigma_eq / d sigma_ii = (1/2 d(sigma_eq^2)/d sigma_ii) / sigma_eq; the shear's tensor component L s23 / sigma_eq.
  const double d1 = -g_h_ * (s3 - s1) + h_h_ * (s1 - s2), d2 = f_ * (s2 - s3) - h_h_ * (s1 - s2),
               d3 = -f_ * (s2 - s3) + g_h_ * (s3 - s1);
  return FromAxes({d3 / eq, d2 / eq, d1 / eq, l_ * x[3] / eq}, frame);
}

bool HillPlasticity::OnSurface(const PointState &s) const
{
  return Equivalent(s.sigma, s.frame) >= (1 - kOnSurface) * h_->YieldStress(s.ep);
}

Mat4 HillPlasticity::Tangent(const PointState &s) const
{
  Mat4 d = elastic_.matrix();
  if (!s.plastic) return d;
  double eq;
  const Voigt n = Normal(s.sigma, s.frame, eq);
  if (!(eq > 0)) return d;
  // C_e : n = 2G n for a deviatoric n: D_ep = D_e - (2G)^2 n n / (2G n : n + H').
  const double two_g = 2 * g_, beta = two_g * two_g / (two_g * TensorDot(n, n) + Modulus(s));
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) d[r][c] -= beta * n[r] * n[c];
  return d;
}

UpdateInfo HillPlasticity::Update(PointState &s, const Voigt &deps) const
{
  UpdateInfo info;
  const double trace = deps[0] + deps[1] + deps[2];
  double eq;
  const Voigt n = Normal(s.sigma, s.frame, eq);
  const double a = DevDotStrain(n, deps);
  const Voigt dsig = ElasticStress(deps);
  if (!(s.plastic && a > 0 && eq > 0)) {
    for (int r = 0; r < 4; ++r) s.sigma[r] += dsig[r] - s.sigma[r] * trace;
    if (s.plastic && a <= 0) s.plastic = false; // elastic unloading
    return info;
  }
  // (T2) with 3G -> 2G n : n and 3G a / sbar -> 2G n : de: the secant over the step's own plastic strain.
  const double two_g = 2 * g_, nn = TensorDot(n, n);
  const double dep = SecantStep(s.ep, two_g * a, two_g * nn, a / nn, s.hslope);
  const double sy_old = h_->YieldStress(s.ep), sy_new = h_->YieldStress(s.ep + dep);
  for (int r = 0; r < 4; ++r) s.sigma[r] += dsig[r] - two_g * dep * n[r] - s.sigma[r] * trace;
  if (dep > 0) s.hslope = (sy_new - sy_old) / dep;
  s.ep += dep;
  info.dwp = 0.5 * (sy_old + sy_new) * dep;
  const double eq_new = Equivalent(s.sigma, s.frame);
  info.drift = eq_new / sy_new - 1;
  if (drift_correction_ && eq_new > 0) {
    // sigma_eq is of degree one in the deviator: scale it back onto the surface, pressure kept.
    const double p = (s.sigma[0] + s.sigma[1] + s.sigma[2]) / 3, f = sy_new / eq_new;
    for (int r = 0; r < 3; ++r) s.sigma[r] = p + f * (s.sigma[r] - p);
    s.sigma[3] *= f;
  }
  return info;
}

double HillPlasticity::YieldOnset(const PointState &s, const Voigt &deps, double omega) const
{
  if (s.plastic) return kNever;
  const double sy = h_->YieldStress(s.ep);
  if (Equivalent(s.sigma, s.frame) >= (1 - kOnSurface) * sy) return kNever;
  // The elastic stress path in the material's axes, which turn with the spin
  // as the stress does: only the law's increment and the Kirchhoff term change
  // the stress there. Quadratic in r: Q(s0 + r ds) = sy^2.
  (void)omega;
  const Voigt ds = ElasticPath(s, deps, 0.0);
  return OnsetRoot(Quadratic(ds, s.frame), 2 * Bilinear(s.sigma, ds, s.frame), Quadratic(s.sigma, s.frame) - sy * sy);
}

bool HillPlasticity::Loading(const PointState &s, const Voigt &deps) const
{
  double eq;
  const double a = DevDotStrain(Normal(s.sigma, s.frame, eq), deps);
  if (s.plastic) return a > 0;
  return a > 0 && OnSurface(s);
}

} // namespace tf
