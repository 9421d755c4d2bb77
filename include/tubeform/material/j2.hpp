// J2 (Prandtl-Reuss) elasto-plasticity in plane strain with sigma_zz tracked,
// isotropic hardening, rate form (docs/theory.md, section 1; paper eq. 1):
//   C_ep = C_e - alpha 9 G^2 / (sbar^2 (3G + H')) s (x) s,
//   dep  = 3G (s : de) / (sbar (3G + H')).
#pragma once

#include <memory>

#include "tubeform/material/elastic.hpp"
#include "tubeform/material/hardening.hpp"

namespace tf {

// A point within this relative distance of the yield surface counts as on it:
// events resolved to round-off (or by a re-solved step) are not new events.
constexpr double kOnSurface = 1e-6;
// The plastic step (T2) is solved by regula falsi to this relative width of
// its bracket (round-off), within this many iterations (Illinois converges in
// a few dozen; the cap only guards against a non-monotone table).
constexpr double kPlasticStepTol = 1e-14;
constexpr int kPlasticStepIterations = 200;
// The radial return flows where its trial raises the equivalent stress past the surface by more than this share
// of sigma_y: a point on the surface loading neutrally (no strain, or along the surface) stays elastic whatever
// round-off (another rank's summation order) adds to its trial, at most this far past the surface.
constexpr double kFlowTie = 1e-8;
// H'(ep) for the algorithmic tangent by central differences over this plastic strain: its truncation (h^2 sigma_y''')
// and its round-off (1e-16 sigma_y / h) both far below the 1e-3 that would slow a Newton iteration.
constexpr double kSlopeStep = 1e-6;

// The backstresses' part of a plastic step's consistency (kinematic.hpp): how
// far their projection on the step's flow direction moves over a plastic
// strain step x, each integrated exactly for that direction.
struct KinematicShare {
  int n = 0;
  double amp[kMaxBackstresses] = {}, gamma[kMaxBackstresses] = {}; // gamma 0: amp is C (linear)
  double Value(double x) const;                                    // sum amp (1 - exp(-gamma x)), or amp x
  double Slope() const;                                            // its derivative at x = 0
};

class J2Plasticity : public Material {
public:
  // dep_ref: plastic strain step over which H' is taken (as a secant) before a
  // point has yielded once; drift_correction scales the deviator back onto the
  // yield surface after each plastic update; update: the tangent update (T2) or
  // the radial return (docs/theory.md, section 1; the derived laws take the tangent one).
  J2Plasticity(double e, double nu, std::unique_ptr<Hardening> h, double dep_ref, bool drift_correction,
               PlasticUpdate update = PlasticUpdate::Tangent);

  Mat4 Tangent(const PointState &s) const override;
  // The radial return's algorithmic tangent (Simo and Taylor 1985; docs/theory.md, section 1).
  Mat4 StepTangent(const PointState &s, const Voigt &deps) const override;
  bool has_step_tangent() const override { return update_ == PlasticUpdate::Radial; }
  UpdateInfo Update(PointState &s, const Voigt &deps) const override;
  double ElasticEnergy(const Voigt &sigma) const override { return elastic_.ElasticEnergy(sigma); }
  double YieldOnset(const PointState &s, const Voigt &deps, double omega) const override;
  bool Loading(const PointState &s, const Voigt &deps) const override;
  double YieldStress(double ep) const override { return h_->YieldStress(ep); }
  bool plastic_law() const override { return true; }
  bool OnSurface(const PointState &s) const override
  {
    return VonMises(s.sigma) >= (1 - kOnSurface) * h_->YieldStress(s.ep);
  }
  double YieldRatio(const PointState &s) const override { return VonMises(s.sigma) / h_->YieldStress(s.ep); }

  // Solves 3G dep + sigma_y(ep + dep) - sigma_y(ep) [+ kin->Value(dep)] = 3G a / sbar
  // for dep >= 0: the plastic strain step whose secant modulus is the H' of the
  // update. `hslope`: the last plastic step's modulus (0: none), the first guess.
  double PlasticStep(double ep, double a, double sbar, double hslope = 0, const KinematicShare *kin = nullptr) const;
  // The same equation in general form: m dep + sigma_y(ep + dep) - sigma_y(ep) = target, dep in [0, hi = target / m].
  double SecantStep(double ep, double target, double m, double hi, double hslope) const;

protected:
  // C_e : deps (Voigt strain in, stress out).
  Voigt ElasticStress(const Voigt &deps) const;
  // The elastic trial of an increment: sigma + C_e : deps - sigma tr(deps) (the spin is the caller's).
  Voigt Trial(const PointState &s, const Voigt &deps) const;
  // The radial return's step from s over deps: the elastic trial and, where it flows, the plastic strain step and
  // the deviator's shrink f = 1 - 3G dep / sbar_tr (RadialReturn and StepTangent).
  struct ReturnStep {
    Voigt trial;
    double sbar_tr, sy_old, dep = 0, f = 1;
    bool flows;
  };
  ReturnStep Return(const PointState &s, const Voigt &deps) const;
  // The radial return (backward Euler) of the trial onto the yield surface where it passes it, else elastic.
  UpdateInfo RadialReturn(PointState &s, const Voigt &deps) const;
  // Whether a trial of equivalent stress sbar_tr flows: past the surface, and (from a start past it) higher (kFlowTie).
  bool TrialFlows(const PointState &s, double sbar_tr, double sy) const;
  // The elastic stress change of a step (the law, the spin's turn and the Kirchhoff term), linear in its length.
  Voigt ElasticPath(const PointState &s, const Voigt &deps, double omega) const;
  // The root r in (0, inf) of qa r^2 + qb r + qc = 0 with qc < 0 (the onset on a path), kNever if qa <= 0.
  static double OnsetRoot(double qa, double qb, double qc);

  Elastic elastic_;
  std::unique_ptr<Hardening> h_;
  double g_, dep_ref_;
  bool drift_correction_;
  PlasticUpdate update_;
  // dsigma_y/dep at ep (a one-sided difference at ep = 0).
  double SlopeAt(double ep) const;
  double Modulus(const PointState &s) const { return s.hslope > 0 ? s.hslope : h_->SecantSlope(s.ep, dep_ref_); }
};

} // namespace tf
