// Isotropic linear elasticity in plane strain with sigma_zz tracked, and the
// objective (Jaumann) stress update shared by every material law.
#pragma once

#include <array>
#include <iterator>
#include <string>
#include <vector>

#include "tubeform/core/core.hpp"
#include "tubeform/fe/quad.hpp"

namespace tf {

using fe::Mat4;
using fe::Voigt;

// Backstresses a point carries at most (Chaboche's model takes up to three).
constexpr int kMaxBackstresses = 3;

// State carried at each Gauss point from increment to increment.
struct PointState {
  Voigt sigma{};        // Cauchy stress {xx, yy, zz, xy}
  double ep = 0;        // equivalent plastic strain (accumulated: p of kinematic hardening)
  double hslope = 0;    // hardening modulus H' of the last plastic update (0: not yet plastic)
  bool plastic = false; // alpha of docs/theory.md (1): on the yield surface and loading
  // Deviatoric backstresses of kinematic hardening (zero without it), turned
  // with the stress by the spin; the yield surface is centred on their sum.
  std::array<Voigt, kMaxBackstresses> back{};
  // Anisotropic yield: the angle (rad, from x) of the material's radial axis,
  // turned with the stress by the spin.
  double frame = 0;
};

// What one material update did (per unit volume).
struct UpdateInfo {
  double dwp = 0;   // plastic work density of the increment
  double drift = 0; // sbar / sigma_y - 1 after the update (before any correction; round-off after a radial return)
};

// How a plastic point's stress is integrated over an increment (-plastic_update): the tangent update (the rate form
// with the start's flow direction, docs/theory.md (T2)), the radial return (isotropic J2 only; backward Euler: the
// elastic trial projected back onto the yield surface along its own deviator), or auto: the return where the law
// has it and the increments are in equilibrium, the tangent update elsewhere (factory.hpp, UpdateFor).
enum class PlasticUpdate { Tangent, Radial, Auto };
inline constexpr const char *kPlasticUpdateWords[] = {"tangent", "radial", "auto"};

// The flow curve (-material_law), the hardening rule (-hardening) and where the anisotropy's radial axis points
// (-material_axes), each with its words in its enumerators' order.
enum class FlowLaw { Elastic, Ludwik, Swift, Table };
inline constexpr const char *kFlowLawWords[] = {"elastic", "ludwik", "swift", "table"};
enum class HardeningRule { Isotropic, Chaboche };
inline constexpr const char *kHardeningWords[] = {"isotropic", "chaboche"};
enum class MaterialAxes { Tube, Fixed };
inline constexpr const char *kMaterialAxesWords[] = {"tube", "fixed"};
static_assert(std::size(kFlowLawWords) == static_cast<size_t>(FlowLaw::Table) + 1 &&
                std::size(kHardeningWords) == static_cast<size_t>(HardeningRule::Chaboche) + 1 &&
                std::size(kMaterialAxesWords) == static_cast<size_t>(MaterialAxes::Fixed) + 1,
              "a word for each enumerator, in order");

// The numbers a flow-curve table (-material_table, on the command line or in a material file) holds at most: 100
// pairs of ep, sigma, far more than a measured curve needs.
inline constexpr int kMaxTableNumbers = 200;

// Material constants: the paper's aluminum (its Table 1, docs/scenes.md) until a
// material file (options/materials/, material/library.hpp) or options set them.
struct MaterialParams {
  std::string name = "aluminum";
  FlowLaw law = FlowLaw::Ludwik;
  double E = 75000, nu = 0.34, sy = 165.3, K = 673.5, n = 0.927;
  double density = 2.70e-9;  // t/mm^3 (N, mm, s units): only -dynamics implicit uses it
  std::vector<double> table; // ep0, sy0, ep1, sy1, ... for the table law
  // Isotropic, or Chaboche: the flow curve above stays the monotonic one and
  // the backstresses (C1, gamma1, C2, gamma2, ...: Armstrong-Frederick with
  // one pair, gamma 0 linear) take their share of it (material/kinematic.hpp).
  HardeningRule hardening = HardeningRule::Isotropic;
  std::vector<double> kinematic;
  // Hill 1948 in the tube's axes (1 axial, 2 hoop, 3 radial): F, G, H, L, or
  // the Lankford coefficients r0, r45, r90 they follow from (both empty, or
  // every r = 1: von Mises).
  std::vector<double> hill, lankford;
  // Where the material's radial axis points at the start: Tube (from the
  // tube's centre, the origin, to the point) or Fixed (at axes_angle, rad).
  MaterialAxes axes = MaterialAxes::Tube;
  double axes_angle = 0;
};

// A constitutive law in rate form. The objective part of the stress update
// (the rotation of the stress by the spin) is done by the caller with
// RotateStress; Update adds the constitutive increment.
class Material {
public:
  virtual ~Material() = default;
  // C in  (Jaumann rate of Kirchhoff stress) = C : d, for the point's alpha.
  virtual Mat4 Tangent(const PointState &s) const = 0;
  // The derivative of Update's stress by deps at a step deps from s (an equilibrium correction's tangent): the law's
  // algorithmic tangent where it has one (has_step_tangent), else Tangent(s).
  virtual Mat4 StepTangent(const PointState &s, const Voigt &) const { return Tangent(s); }
  virtual bool has_step_tangent() const { return false; }
  // sigma += C : deps - sigma tr(deps) (Kirchhoff -> Cauchy), plastic state advanced.
  virtual UpdateInfo Update(PointState &s, const Voigt &deps) const = 0;
  // Elastic strain energy density of a stress state.
  virtual double ElasticEnergy(const Voigt &sigma) const = 0;
  // r1 of docs/theory.md section 5: the fraction of the trial increment (deps, omega)
  // at which an elastic point reaches the yield surface; infinity if never.
  virtual double YieldOnset(const PointState &, const Voigt &, double) const { return kNever; }
  // alpha for the coming increment given the trial strain increment: a plastic
  // point that unloads (s : deps < 0) turns elastic; an elastic point on the
  // yield surface that loads turns plastic.
  virtual bool Loading(const PointState &, const Voigt &) const { return false; }
  virtual double YieldStress(double) const { return kNever; }
  virtual bool plastic_law() const { return false; }
  // Whether the point's stress is on its yield surface (within kOnSurface).
  virtual bool OnSurface(const PointState &) const { return false; }
  // The point's equivalent stress (about the yield surface's centre) over its yield stress: 1 on the surface,
  // more past it (an elastic release's excess: Body::MeasureRelease); 0 for a law without one.
  virtual double YieldRatio(const PointState &) const { return 0; }
  // How many backstresses the law evolves (0: none to turn with the stress).
  virtual int backstresses() const { return 0; }
  // Whether the law reads the point's material axes (PointState::frame).
  virtual bool anisotropic() const { return false; }
};

class Elastic : public Material {
public:
  Elastic(double e, double nu);
  Mat4 Tangent(const PointState &) const override { return d_; }
  UpdateInfo Update(PointState &s, const Voigt &deps) const override;
  double ElasticEnergy(const Voigt &sigma) const override;
  double shear_modulus() const { return g_; }
  double bulk_modulus() const { return k_; }
  const Mat4 &matrix() const { return d_; }

private:
  double g_, k_;
  Mat4 d_;
};

// Isotropic elastic matrix in Voigt form {xx, yy, zz, gamma_xy}.
Mat4 IsotropicElasticMatrix(double e, double nu);

// Objective update of docs/theory.md (T3): the Jaumann rate of Kirchhoff stress
// is dtau (from the law); the Cauchy stress then changes by
//   dsigma = dtau - sigma tr(deps) + W sigma - sigma W,  W = [[0, w], [-w, 0]].
void JaumannUpdate(const Voigt &dtau, double trace_deps, double omega, Voigt &sigma);

// The spin part alone. Forward (the paper's rate form integrated as is):
// sigma += W sigma - sigma W. Midpoint (Hughes & Winget 1980): sigma = Q sigma Q^T
// with Q = (I - W/2)^-1 (I + W/2), an exact rotation, so invariants are kept;
// `fraction` turns by that part of Q's angle (half before and half after the
// constitutive increment makes the update second order).
enum class ObjectiveScheme { Forward, Midpoint };
void RotateStress(ObjectiveScheme scheme, double omega, Voigt &sigma, double fraction = 1.0);
// The same turn prepared once (its angle's atan, sin and cos) for several
// stresses: the two half turns of a midpoint update are one rotation.
class StressRotation {
public:
  StressRotation(ObjectiveScheme scheme, double omega, double fraction = 1.0);
  void Apply(Voigt &sigma) const;
  // The angle it turns by (rad, counter-clockwise): what a material axis turns by.
  double Angle() const;

private:
  ObjectiveScheme scheme_;
  double omega_ = 0, c_ = 1, s_ = 0, phi_ = 0; // Forward: the spin turned; Midpoint: the angle, its cos and sin
};

// Deviator {sxx, syy, szz, sxy} and the equivalent (von Mises) stress.
Voigt Deviator(const Voigt &s);
double VonMises(const Voigt &s);
// The share f of an increment (a step split at the yield onset).
inline Voigt Scaled(const Voigt &v, double f) { return {f * v[0], f * v[1], f * v[2], f * v[3]}; }
// a : b of two tensors in Voigt stress form (the shear counted twice).
inline double TensorDot(const Voigt &a, const Voigt &b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + 2 * a[3] * b[3];
}
// s : e with e in Voigt strain form (gamma_xy = 2 e_xy).
inline double DevDotStrain(const Voigt &s, const Voigt &e)
{
  return s[0] * e[0] + s[1] * e[1] + s[2] * e[2] + s[3] * e[3];
}

} // namespace tf
