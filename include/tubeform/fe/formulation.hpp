// The element formulation of a body behind one interface (docs/theory.md,
// section 3): q4, bbar or qm6. QM6's condensation of each cell's internal
// modes, cond = -Kii^-1 Kic, is computed by the stiffness and used by the
// kinematics and internal force of the same increment, so this object owns it.
// Pure (no PETSc).
#pragma once

#include <vector>

#include "tubeform/fe/qm6.hpp"
#include "tubeform/fe/quad.hpp"

namespace tf::fe {

class CellFormulation {
public:
  CellFormulation() = default;
  CellFormulation(Formulation f, int num_cells);

  Formulation kind() const { return kind_; }

  // Each on cell e with corners xe and their geometry geo = ComputeGeometry(xe)
  // (not inverted), computed once by the caller.
  // Element tangent (point tangents c, stresses s); for qm6 the cell's
  // condensation is stored. False when qm6's modes cannot be condensed.
  bool Stiffness(int e, const double xe[2 * kNodes], const QuadGeometry &geo, const Mat4 c[kGauss],
                 const Voigt s[kGauss], ElemMat &ke);
  // The equilibrium corrections' tangent at an iterate with midpoint
  // kinematics: the rows of Stiffness, the columns of the mid-increment strain
  // (midpoint.hpp); nothing is stored. False when qm6's modes cannot be condensed.
  bool MidpointStiffness(const QuadGeometry &geo, const Mat4 c[kGauss], const Voigt s[kGauss], const MidpointColumns &m,
                         ElemMat &ke) const;
  // Strain and spin increments at Gauss point g for the nodal increments du
  // (qm6: its modes from the last stiffness of the cell).
  void Kinematics(int e, const double xe[2 * kNodes], const QuadGeometry &geo, int g, const ElemVec &du, Voigt &deps,
                  double &omega) const;
  // Nodal forces of the cell's Gauss-point stresses (qm6: with the
  // condensation its committed state was reached with, SetCommitted).
  void InternalForce(int e, const double xe[2 * kNodes], const QuadGeometry &geo, const Voigt s[kGauss],
                     ElemVec &f) const;

  // qm6, modes in balance (equilibrium iterations): the modes of an increment
  // are unknowns of the cell, started from cond du and corrected until their
  // force vanishes: Modes gives the start, KinematicsWith the strain for given
  // modes, ModeForce the force on them, CorrectModes alpha -= Kii^{-1} f_i.
  bool has_modes() const { return kind_ == Formulation::QM6 || kind_ == Formulation::QM6Bar; }
  bool mean_dilatation() const { return kind_ == Formulation::QM6Bar; }
  InternalVec Modes(int e, const ElemVec &du) const;
  void KinematicsWith(const double xe[2 * kNodes], const QuadGeometry &geo, int g, const ElemVec &du,
                      const InternalVec &alpha, Voigt &deps, double &omega) const
  {
    QM6Kinematics(xe, geo, g, du, alpha, deps, omega, mean_dilatation());
  }
  void ModeForce(const double xe[2 * kNodes], const QuadGeometry &geo, const Voigt s[kGauss], InternalVec &fi) const
  {
    QM6ModeForce(xe, geo, s, fi, mean_dilatation());
  }
  void CorrectModes(int e, const InternalVec &fi, InternalVec &alpha) const;

  // qm6, the force's own condensation (equilibrium iterations): the modes and
  // nodal forces of an increment taken with the condensation of the tangents
  // its own strain increment selects, not the assembled one, so that the
  // forces are a function of the nodal increment (docs/theory.md, 5a).
  // Condense computes cond and Kii^{-1} of tangents c without storing them
  // (false: Kii singular); the *Of functions take them explicitly.
  bool Condense(const double xe[2 * kNodes], const QuadGeometry &geo, const Mat4 c[kGauss], const Voigt s[kGauss],
                Condensation &cond, ModeMatrix &kii_inv) const;
  static InternalVec ModesOf(const Condensation &cond, const ElemVec &du);
  static void CorrectModesOf(const ModeMatrix &kii_inv, const InternalVec &fi, InternalVec &alpha);
  void InternalForceOf(const double xe[2 * kNodes], const QuadGeometry &geo, const Voigt s[kGauss],
                       const Condensation &cond, ElemVec &f) const;
  const Condensation &assembled(int e) const { return condensation_[e]; }
  const ModeMatrix &assembled_kii_inv(int e) const { return kii_inv_[e]; }
  // The condensation of cell e's committed forces (from the increment that reached it).
  void SetCommitted(int e, const Condensation &cond) { committed_[e] = cond; }

  // qm6: the committed state's condensation of every cell (empty for other
  // elements). State a checkpoint keeps: the committed state's internal force uses it.
  std::vector<Condensation> &condensations() { return committed_; }

private:
  Formulation kind_ = Formulation::BBar;
  std::vector<Condensation> condensation_; // qm6: per cell, from the last Stiffness
  std::vector<ModeMatrix> kii_inv_;        // qm6: per cell, Kii^{-1} of the last Stiffness
  std::vector<Condensation> committed_;    // qm6: per cell, of the committed state's forces
};

} // namespace tf::fe
