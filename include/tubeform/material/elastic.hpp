// Isotropic linear elasticity in plane strain with sigma_zz tracked, and the
// objective (Jaumann) stress update shared by every material law.
#pragma once

#include <string>

#include "tubeform/fe/quad.hpp"

namespace tf {

using fe::Mat4;
using fe::Voigt;

// State carried at each Gauss point from increment to increment.
struct PointState {
  Voigt sigma{};     // Cauchy stress {xx, yy, zz, xy}
  double ep = 0;     // equivalent plastic strain
  bool plastic = false;
};

// Material constants (METHOD.md Table 1 for the presets).
struct MaterialParams {
  std::string name = "aluminum";
  std::string law = "ludwik";
  double E = 75000, nu = 0.34, sy = 165.3, K = 673.5, n = 0.927;
};

// Fills `p` with a named preset; false when the name is unknown.
bool MaterialPreset(const std::string &name, MaterialParams &p);

class Material {
public:
  virtual ~Material() = default;
  // C in  (Jaumann rate of Kirchhoff stress) = C : d.
  virtual Mat4 Tangent(const PointState &s) const = 0;
  // Advances the state by the strain increment deps and spin omega; returns
  // whether the point is plastic after the update.
  virtual bool Update(PointState &s, const Voigt &deps, double omega) const = 0;
  // Elastic strain energy density of a stress state.
  virtual double ElasticEnergy(const Voigt &sigma) const = 0;
};

class Elastic : public Material {
public:
  Elastic(double e, double nu);
  Mat4 Tangent(const PointState &) const override { return d_; }
  bool Update(PointState &s, const Voigt &deps, double omega) const override;
  double ElasticEnergy(const Voigt &sigma) const override;
  double shear_modulus() const { return g_; }
  double bulk_modulus() const { return k_; }

private:
  double e_, nu_, g_, k_;
  Mat4 d_;
};

// Isotropic elastic matrix in Voigt form {xx, yy, zz, gamma_xy}.
Mat4 IsotropicElasticMatrix(double e, double nu);

// Objective update of METHOD.md sec. 2: the Jaumann rate of Kirchhoff stress
// is dtau (from the law); the Cauchy stress then changes by
//   dsigma = dtau - sigma tr(deps) + W sigma - sigma W,  W = [[0, w], [-w, 0]].
void JaumannUpdate(const Voigt &dtau, double trace_deps, double omega, Voigt &sigma);

} // namespace tf
