// Hill's 1948 quadratic yield function in plane strain, in the tube's axes
// (1 axial = z, 2 hoop, 3 radial: the point's PointState::frame is the radial
// axis's angle), with the rate form of j2.hpp (isotropic hardening):
//   sigma_eq^2 = F (s22 - s33)^2 + G (s33 - s11)^2 + H (s11 - s22)^2 + 2 L s23^2
// (s13 = s12 = 0 in the cross-section). F = G = H = 1/2, L = 3/2 is von Mises.
// n = d sigma_eq / d sigma is deviatoric, sigma : n = sigma_eq, and with
// dep_tensor = dp n the tangent update is (1), (T1), (T2) with s / sbar ->
// n (3/2 s / sbar for von Mises) and 3G -> 2G n : n.
#pragma once

#include <array>
#include <memory>

#include "tubeform/material/j2.hpp"

namespace tf {

// F, G, H, L from the Lankford coefficients of tension along the tube (r0,
// strain ratio hoop / radial) and across it (r90), normalized so that
// sigma_eq is the stress of tension along the axis (G + H = 1); L, which no
// in-plane r-value determines, takes von Mises's 3/2. (r45 sets N, the
// axial-hoop shear, which does not act in the cross-section.)
std::array<double, 4> HillFromR(double r0, double r90);

class HillPlasticity : public J2Plasticity {
public:
  HillPlasticity(double e, double nu, std::unique_ptr<Hardening> h, const std::array<double, 4> &fghl, double dep_ref,
                 bool drift_correction);

  Mat4 Tangent(const PointState &s) const override;
  UpdateInfo Update(PointState &s, const Voigt &deps) const override;
  double YieldOnset(const PointState &s, const Voigt &deps, double omega) const override;
  bool Loading(const PointState &s, const Voigt &deps) const override;
  bool OnSurface(const PointState &s) const override;
  double YieldRatio(const PointState &s) const override { return Equivalent(s.sigma, s.frame) / h_->YieldStress(s.ep); }
  bool anisotropic() const override { return true; }

  // sigma_eq^2 of a stress in global Voigt form at material axes `frame`, and n (global, tensor components).
  double Quadratic(const Voigt &sigma, double frame) const;
  double Equivalent(const Voigt &sigma, double frame) const; // sigma_eq
  Voigt Normal(const Voigt &sigma, double frame, double &eq) const;

private:
  double f_, g_h_, h_h_, l_; // F, G, H, L (g_ is J2's shear modulus)
  // The bilinear form of Quadratic: B(a, a) = Quadratic(a).
  double Bilinear(const Voigt &a, const Voigt &b, double frame) const;
};

} // namespace tf
