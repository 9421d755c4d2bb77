// Combined isotropic-kinematic J2 plasticity (Armstrong & Frederick 1966;
// Chaboche 1986, up to three backstresses) in the rate form of j2.hpp. The
// yield surface sqrt(3/2 xi : xi) = R(p) is centred on the sum of the
// deviatoric backstresses, xi = s - sum(alpha_i), and each backstress evolves
// with the accumulated plastic strain p as
//   d alpha_i = C_i (xi / xibar) dp - gamma_i alpha_i dp
// (Armstrong-Frederick; gamma_i = 0 is Prager's linear rule). Consistency
// gives the same tangent as isotropic hardening with s -> xi and
//   H' -> R'(p) + sum_i (C_i - 3/2 gamma_i (xi : alpha_i) / xibar),
// the kinematic part non-negative while |alpha_i| stays below its saturation.
// On a proportional monotonic path each backstress grows as
// (C_i / gamma_i)(1 - exp(-gamma_i p)) along xi, so R(p) = sigma_y(p) minus
// their sum keeps the flow curve sigma_y(p) of the material as the monotonic
// curve: the backstresses only change what happens on reversal (Bauschinger).
#pragma once

#include <memory>
#include <vector>

#include "tubeform/material/j2.hpp"

namespace tf {

struct Backstress {
  double c = 0;     // initial kinematic modulus C (MPa)
  double gamma = 0; // recall gamma (0: linear)
  // Its equivalent value on a monotonic proportional path at plastic strain p.
  double Monotonic(double p) const;
};

// The pairs C1, gamma1, C2, gamma2, ... of -material_kinematic.
std::vector<Backstress> Backstresses(const std::vector<double> &pairs);

// R(p) = sigma_y(p) - sum of the backstresses' monotonic values: the
// isotropic part that keeps sigma_y(p) the monotonic flow curve.
class RemainderHardening : public Hardening {
public:
  RemainderHardening(std::unique_ptr<Hardening> total, std::vector<Backstress> back)
      : total_(std::move(total)), back_(std::move(back))
  {}
  double YieldStress(double ep) const override;

private:
  std::unique_ptr<Hardening> total_;
  std::vector<Backstress> back_;
};

class KinematicJ2 : public J2Plasticity {
public:
  // `h` is the isotropic part R(p) (a RemainderHardening for -hardening chaboche).
  KinematicJ2(double e, double nu, std::unique_ptr<Hardening> h, std::vector<Backstress> back, double dep_ref,
              bool drift_correction);

  Mat4 Tangent(const PointState &s) const override;
  UpdateInfo Update(PointState &s, const Voigt &deps) const override;
  double YieldOnset(const PointState &s, const Voigt &deps, double omega) const override;
  bool Loading(const PointState &s, const Voigt &deps) const override;
  bool OnSurface(const PointState &s) const override;
  double YieldRatio(const PointState &s) const override;
  int backstresses() const override { return (int)back_.size(); }

private:
  std::vector<Backstress> back_;
  // xi = dev(sigma) - sum(alpha_i).
  Voigt Relative(const PointState &s) const;
  // sum_i (C_i - 3/2 gamma_i (xi : alpha_i) / xibar): the backstresses' share of H'.
  double KinematicModulus(const PointState &s, const Voigt &xi, double xibar) const;
};

} // namespace tf
