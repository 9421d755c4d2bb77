#include "tubeform/fe/formulation.hpp"

namespace tf::fe {

CellFormulation::CellFormulation(Formulation f, int num_cells) : kind_(f)
{
  if (has_modes()) {
    condensation_.assign(num_cells, Condensation{});
    kii_inv_.assign(num_cells, ModeMatrix{});
  }
}

bool CellFormulation::Stiffness(int e, const double xe[2 * kNodes], const QuadGeometry &geo, const Mat4 c[kGauss],
                                const Voigt s[kGauss], ElemMat &ke)
{
  if (has_modes()) return QM6Stiffness(xe, geo, c, s, true, ke, condensation_[e], &kii_inv_[e], mean_dilatation());
  ElementStiffness(geo, kind_, c, s, true, ke);
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
    QM6InternalForce(xe, geo, s, condensation_[e], f, mean_dilatation());
  else
    fe::InternalForce(geo, kind_, s, f);
}

InternalVec CellFormulation::Modes(int e, const ElemVec &du) const
{
  InternalVec alpha{};
  for (int k = 0; k < kInternal; ++k)
    for (int j = 0; j < kDofs; ++j) alpha[k] += condensation_[e][k][j] * du[j];
  return alpha;
}

void CellFormulation::CorrectModes(int e, const InternalVec &fi, InternalVec &alpha) const
{
  for (int i = 0; i < kInternal; ++i)
    for (int j = 0; j < kInternal; ++j) alpha[i] -= kii_inv_[e][i][j] * fi[j];
}

} // namespace tf::fe
