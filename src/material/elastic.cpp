#include "tubeform/material/elastic.hpp"

namespace tf {

bool MaterialPreset(const std::string &name, MaterialParams &p)
{
  // Huang (2008), Table 1; flow curve sigma_y0 + K ep^n (METHOD.md decision).
  if (name == "aluminum") p = {name, "ludwik", 75000.0, 0.34, 165.3, 673.5, 0.927};
  else if (name == "copper") p = {name, "ludwik", 112000.0, 0.34, 445.0, 3628.6, 0.987};
  else if (name == "custom") p.name = name;
  else return false;
  return true;
}

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

Elastic::Elastic(double e, double nu) : e_(e), nu_(nu), g_(e / (2 * (1 + nu))), k_(e / (3 * (1 - 2 * nu))), d_(IsotropicElasticMatrix(e, nu)) {}

void JaumannUpdate(const Voigt &dtau, double trace_deps, double omega, Voigt &sigma)
{
  const Voigt s = sigma;
  for (int r = 0; r < 4; ++r) sigma[r] += dtau[r] - s[r] * trace_deps;
  sigma[0] += 2 * omega * s[3];
  sigma[1] -= 2 * omega * s[3];
  sigma[3] += omega * (s[1] - s[0]);
}

bool Elastic::Update(PointState &s, const Voigt &deps, double omega) const
{
  Voigt dtau{};
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) dtau[r] += d_[r][c] * deps[c];
  JaumannUpdate(dtau, deps[0] + deps[1] + deps[2], omega, s.sigma);
  s.plastic = false;
  return false;
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
