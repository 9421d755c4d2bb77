#include "tubeform/fe/formulation.hpp"

namespace tf::fe {

CellFormulation::CellFormulation(Formulation f, int num_cells) : kind_(f)
{
  if (has_modes()) {
    condensation_.assign(num_cells, Condensation{});
    kii_inv_.assign(num_cells, ModeMatrix{});
    committed_.assign(num_cells, Condensation{});
  }
}

bool CellFormulation::Stiffness(int e, const double xe[2 * kNodes], const QuadGeometry &geo, const Mat4 c[kGauss],
                                const Voigt s[kGauss], ElemMat &ke)
{
  if (has_modes()) return QM6Stiffness(xe, geo, c, s, true, ke, condensation_[e], &kii_inv_[e], mean_dilatation());
  ElementStiffness(geo, kind_, c, s, true, ke);
  return true;
}

bool CellFormulation::MidpointStiffness(const QuadGeometry &geo, const Mat4 c[kGauss], const Voigt s[kGauss],
                                        const MidpointColumns &m, ElemMat &ke) const
{
  if (has_modes()) return QM6Stiffness(geo, c, s, m, ke, mean_dilatation());
  MidpointElementStiffness(geo, kind_, c, s, m, ke);
  return true;
}

void CellFormulation::Kinematics(int e, const double xe[2 * kNodes], const QuadGeometry &geo, int g, const ElemVec &du,
                                 Voigt &deps, double &omega) const
{
  if (!has_modes()) {
    IncrementKinematics(geo, g, kind_, du, deps, omega);
    return;
  }
  // Internal modes of the increment from the condensation of its assembly.
  QM6Kinematics(xe, geo, g, du, Modes(e, du), deps, omega, mean_dilatation());
}

void CellFormulation::InternalForce(int e, const double xe[2 * kNodes], const QuadGeometry &geo, const Voigt s[kGauss],
                                    ElemVec &f) const
{
  if (has_modes())
    QM6InternalForce(xe, geo, s, committed_[e], f, mean_dilatation());
  else
    fe::InternalForce(geo, kind_, s, f);
}

InternalVec CellFormulation::Modes(int e, const ElemVec &du) const { return ModesOf(condensation_[e], du); }

void CellFormulation::CorrectModes(int e, const InternalVec &fi, InternalVec &alpha) const
{
  CorrectModesOf(kii_inv_[e], fi, alpha);
}

bool CellFormulation::Condense(const double xe[2 * kNodes], const QuadGeometry &geo, const Mat4 c[kGauss],
                               const Voigt s[kGauss], Condensation &cond, ModeMatrix &kii_inv) const
{
  ElemMat ke;
  return QM6Stiffness(xe, geo, c, s, true, ke, cond, &kii_inv, mean_dilatation());
}

InternalVec CellFormulation::ModesOf(const Condensation &cond, const ElemVec &du)
{
  InternalVec alpha{};
  for (int k = 0; k < kInternal; ++k)
    for (int j = 0; j < kDofs; ++j) alpha[k] += cond[k][j] * du[j];
  return alpha;
}

void CellFormulation::CorrectModesOf(const ModeMatrix &kii_inv, const InternalVec &fi, InternalVec &alpha)
{
  for (int i = 0; i < kInternal; ++i)
    for (int j = 0; j < kInternal; ++j) alpha[i] -= kii_inv[i][j] * fi[j];
}

void CellFormulation::InternalForceOf(const double xe[2 * kNodes], const QuadGeometry &geo, const Voigt s[kGauss],
                                      const Condensation &cond, ElemVec &f) const
{
  QM6InternalForce(xe, geo, s, cond, f, mean_dilatation());
}

} // namespace tf::fe
