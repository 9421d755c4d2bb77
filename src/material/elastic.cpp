#include "tubeform/material/elastic.hpp"

#include <cmath>

namespace tf {

Mat4 IsotropicElasticMatrix(double e, double nu)
{
  const double lam = e * nu / ((1 + nu) * (1 - 2 * nu)), mu = e / (2 * (1 + nu));
  Mat4 d{};
  for (int r = 0; r < 3; ++r) {
    for (int s = 0; s < 3; ++s) d[r][s] = lam;
    d[r][r] += 2 * mu;
  }
  d[3][3] = mu;
  return d;
}

Elastic::Elastic(double e, double nu)
    : g_(e / (2 * (1 + nu))), k_(e / (3 * (1 - 2 * nu))), d_(IsotropicElasticMatrix(e, nu))
{}

void JaumannUpdate(const Voigt &dtau, double trace_deps, double omega, Voigt &sigma)
{
  const Voigt s = sigma;
  for (int r = 0; r < 4; ++r) sigma[r] += dtau[r] - s[r] * trace_deps;
  sigma[0] += 2 * omega * s[3];
  sigma[1] -= 2 * omega * s[3];
  sigma[3] += omega * (s[1] - s[0]);
}

UpdateInfo Elastic::Update(PointState &s, const Voigt &deps) const
{
  Voigt dtau{};
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) dtau[r] += d_[r][c] * deps[c];
  JaumannUpdate(dtau, deps[0] + deps[1] + deps[2], 0.0, s.sigma);
  return {};
}

StressRotation::StressRotation(ObjectiveScheme scheme, double omega, double fraction) : scheme_(scheme)
{
  if (scheme == ObjectiveScheme::Forward) {
    omega_ = fraction * omega;
    return;
  }
  // Q = (I - W/2)^-1 (I + W/2) = [[c, s], [-s, c]], a rotation by phi = 2 atan(omega/2);
  // a fraction of it turns by fraction * phi.
  phi_ = 2 * std::atan(0.5 * omega) * fraction;
  c_ = std::cos(phi_), s_ = std::sin(phi_);
}

// W = [[0, omega], [-omega, 0]] is the spin of a counter-clockwise turn by -omega
// (v = dtheta (-y, x) has W_xy = -dtheta): Q = [[c, s], [-s, c]] turns by -phi.
double StressRotation::Angle() const { return scheme_ == ObjectiveScheme::Forward ? -omega_ : -phi_; }

void StressRotation::Apply(Voigt &sigma) const
{
  if (scheme_ == ObjectiveScheme::Forward) {
    JaumannUpdate({0, 0, 0, 0}, 0.0, omega_, sigma);
    return;
  }
  // sigma <- Q sigma Q^T.
  const double c = c_, s = s_, xx = sigma[0], yy = sigma[1], xy = sigma[3];
  sigma[0] = c * c * xx + 2 * c * s * xy + s * s * yy;
  sigma[1] = s * s * xx - 2 * c * s * xy + c * c * yy;
  sigma[3] = -c * s * xx + (c * c - s * s) * xy + c * s * yy;
}

void RotateStress(ObjectiveScheme scheme, double omega, Voigt &sigma, double fraction)
{
  StressRotation(scheme, omega, fraction).Apply(sigma);
}

Voigt Deviator(const Voigt &s)
{
  const double p = (s[0] + s[1] + s[2]) / 3.0;
  return {s[0] - p, s[1] - p, s[2] - p, s[3]};
}

double VonMises(const Voigt &s)
{
  const Voigt d = Deviator(s);
  return std::sqrt(1.5 * (d[0] * d[0] + d[1] * d[1] + d[2] * d[2] + 2 * d[3] * d[3]));
}

double Elastic::ElasticEnergy(const Voigt &sg) const
{
  // W = p^2 / (2K) + s:s / (4G), with s the deviator (3D, sigma_zz included).
  const double p = (sg[0] + sg[1] + sg[2]) / 3.0;
  const double sx = sg[0] - p, sy = sg[1] - p, sz = sg[2] - p;
  const double j2 = sx * sx + sy * sy + sz * sz + 2 * sg[3] * sg[3];
  return p * p / (2 * k_) + j2 / (4 * g_);
}

} // namespace tf
