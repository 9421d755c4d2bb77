#include "tubeform/material/kinematic.hpp"

#include <cmath>

namespace tf {

namespace {

double Equivalent(const Voigt &xi) { return std::sqrt(1.5 * TensorDot(xi, xi)); }

} // namespace

double Backstress::Monotonic(double p) const { return gamma > 0 ? c / gamma * (1 - std::exp(-gamma * p)) : c * p; }

std::vector<Backstress> Backstresses(const std::vector<double> &pairs)
{
  std::vector<Backstress> b;
  for (size_t i = 0; i + 1 < pairs.size(); i += 2) b.push_back({pairs[i], pairs[i + 1]});
  return b;
}

double RemainderHardening::YieldStress(double ep) const
{
  double r = total_->YieldStress(ep);
  for (const auto &b : back_) r -= b.Monotonic(ep);
  return r;
}

KinematicJ2::KinematicJ2(double e, double nu, std::unique_ptr<Hardening> h, std::vector<Backstress> back,
                         double dep_ref, bool drift_correction)
    : J2Plasticity(e, nu, std::move(h), dep_ref, drift_correction), back_(std::move(back))
{}

Voigt KinematicJ2::Relative(const PointState &s) const
{
  Voigt xi = Deviator(s.sigma);
  for (size_t i = 0; i < back_.size(); ++i)
    for (int r = 0; r < 4; ++r) xi[r] -= s.back[i][r];
  return xi;
}

double KinematicJ2::KinematicModulus(const PointState &s, const Voigt &xi, double xibar) const
{
  double hk = 0;
  for (size_t i = 0; i < back_.size(); ++i) hk += back_[i].c - 1.5 * back_[i].gamma * TensorDot(xi, s.back[i]) / xibar;
  return hk;
}

bool KinematicJ2::OnSurface(const PointState &s) const
{
  return Equivalent(Relative(s)) >= (1 - kOnSurface) * h_->YieldStress(s.ep);
}

double KinematicJ2::YieldRatio(const PointState &s) const { return Equivalent(Relative(s)) / h_->YieldStress(s.ep); }

Mat4 KinematicJ2::Tangent(const PointState &s) const
{
  Mat4 d = elastic_.matrix();
  if (!s.plastic) return d;
  const Voigt xi = Relative(s);
  const double xibar = Equivalent(xi);
  if (!(xibar > 0)) return d;
  // R' of the last plastic step (the remainder R softens where the backstresses
  // harden faster than the flow curve: negative slopes are slopes too).
  const double iso = s.hslope != 0 ? s.hslope : h_->SecantSlope(s.ep, dep_ref_);
  const double beta = 9 * g_ * g_ / (xibar * xibar * (3 * g_ + iso + KinematicModulus(s, xi, xibar)));
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) d[r][c] -= beta * xi[r] * xi[c];
  return d;
}

UpdateInfo KinematicJ2::Update(PointState &s, const Voigt &deps) const
{
  UpdateInfo info;
  const double trace = deps[0] + deps[1] + deps[2];
  const Voigt xi = Relative(s);
  const double xibar = Equivalent(xi), a = DevDotStrain(xi, deps);
  const Voigt dsig = ElasticStress(deps);
  if (!(s.plastic && a > 0 && xibar > 0)) {
    for (int r = 0; r < 4; ++r) s.sigma[r] += dsig[r] - s.sigma[r] * trace;
    if (s.plastic && a <= 0) s.plastic = false; // elastic unloading
    return info;
  }
  // The tangent update of j2.cpp about the shifted surface; each backstress
  // follows its rule integrated exactly for the step's fixed direction xi / xibar.
  // The consistency over the whole step: the backstresses' projection on the
  // direction xi / xibar moves by (C_i / gamma_i - 3/2 xi : alpha_i / xibar)(1 - exp(-gamma_i dp)).
  KinematicShare kin;
  kin.n = (int)back_.size();
  for (int i = 0; i < kin.n; ++i) {
    const Backstress &b = back_[i];
    const double along = 1.5 * TensorDot(xi, s.back[i]) / xibar;
    kin.gamma[i] = b.gamma;
    kin.amp[i] = b.gamma > 0 ? b.c / b.gamma - along : b.c;
  }
  const double dep = PlasticStep(s.ep, a, xibar, s.hslope, &kin);
  const double r_old = h_->YieldStress(s.ep), r_new = h_->YieldStress(s.ep + dep);
  for (int r = 0; r < 4; ++r) s.sigma[r] += dsig[r] - 3 * g_ * dep / xibar * xi[r] - s.sigma[r] * trace;
  Voigt mid{};
  for (size_t i = 0; i < back_.size(); ++i) {
    const Backstress &b = back_[i];
    const double decay = std::exp(-b.gamma * dep), grow = b.gamma > 0 ? b.c / b.gamma * (1 - decay) : b.c * dep;
    for (int r = 0; r < 4; ++r) {
      const double old = s.back[i][r];
      s.back[i][r] = old * decay + grow * xi[r] / xibar;
      mid[r] += 0.5 * (old + s.back[i][r]);
    }
  }
  if (dep > 0) s.hslope = (r_new - r_old) / dep; // (may be negative: see Tangent)
  s.ep += dep;
  // sigma : dep_tensor = (xibar + 3/2 alpha : xi / xibar) dp: the isotropic part and the work stored in the
  // backstresses.
  info.dwp = (0.5 * (r_old + r_new) + 1.5 * TensorDot(mid, xi) / xibar) * dep;
  const Voigt xi_new = Relative(s);
  const double xibar_new = Equivalent(xi_new);
  info.drift = xibar_new / r_new - 1;
  if (drift_correction_ && xibar_new > 0) {
    // Scale xi back onto the shifted surface, the backstresses and pressure kept.
    const double f = r_new / xibar_new;
    for (int r = 0; r < 4; ++r) s.sigma[r] += (f - 1) * xi_new[r];
  }
  return info;
}

double KinematicJ2::YieldOnset(const PointState &s, const Voigt &deps, double omega) const
{
  if (s.plastic) return kNever;
  const double sy = h_->YieldStress(s.ep);
  const Voigt x0 = Relative(s);
  if (Equivalent(x0) >= (1 - kOnSurface) * sy) return kNever;
  // Linear path of xi: the stress's elastic path less the backstresses' turn by the spin.
  Voigt d1 = Deviator(ElasticPath(s, deps, omega));
  for (size_t i = 0; i < back_.size(); ++i) {
    Voigt turned = s.back[i];
    RotateStress(ObjectiveScheme::Forward, omega, turned);
    for (int r = 0; r < 4; ++r) d1[r] -= turned[r] - s.back[i][r];
  }
  return OnsetRoot(1.5 * TensorDot(d1, d1), 3 * TensorDot(x0, d1), 1.5 * TensorDot(x0, x0) - sy * sy);
}

bool KinematicJ2::Loading(const PointState &s, const Voigt &deps) const
{
  const double a = DevDotStrain(Relative(s), deps);
  if (s.plastic) return a > 0;
  return a > 0 && OnSurface(s);
}

} // namespace tf
