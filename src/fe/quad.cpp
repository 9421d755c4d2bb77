#include "tubeform/fe/quad.hpp"

#include <cmath>

namespace tf::fe {

namespace {
constexpr double kXiNode[kNodes][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
} // namespace

void ShapeFunctions(double xi, double eta, double n[kNodes], double dn[kNodes][2])
{
  for (int a = 0; a < kNodes; ++a) {
    const double xa = kXiNode[a][0], ya = kXiNode[a][1];
    n[a] = 0.25 * (1 + xa * xi) * (1 + ya * eta);
    dn[a][0] = 0.25 * xa * (1 + ya * eta);
    dn[a][1] = 0.25 * ya * (1 + xa * xi);
  }
}

void GaussPoints(const double xe[2 * kNodes], double xg[kGauss][2])
{
  for (int g = 0; g < kGauss; ++g) {
    double n[kNodes], dn[kNodes][2];
    ShapeFunctions(kXiGauss[g][0], kXiGauss[g][1], n, dn);
    xg[g][0] = xg[g][1] = 0;
    for (int a = 0; a < kNodes; ++a) xg[g][0] += n[a] * xe[2 * a], xg[g][1] += n[a] * xe[2 * a + 1];
  }
}

namespace {
// The shape functions and their natural derivatives at the 2x2 Gauss points
// (index g) and at the centre (index kGauss), evaluated once: every cell's
// geometry needs them, many times an increment.
struct ShapeTable {
  double n[kGauss + 1][kNodes], dn[kGauss + 1][kNodes][2];
  ShapeTable()
  {
    for (int g = 0; g < kGauss; ++g) ShapeFunctions(kXiGauss[g][0], kXiGauss[g][1], n[g], dn[g]);
    ShapeFunctions(0, 0, n[kGauss], dn[kGauss]);
  }
};
const ShapeTable &Shapes()
{
  static const ShapeTable table;
  return table;
}
} // namespace

void LumpedMass(const double xe[2 * kNodes], double rho, double m[kNodes])
{
  for (int a = 0; a < kNodes; ++a) m[a] = 0;
  const ShapeTable &shapes = Shapes();
  for (int g = 0; g < kGauss; ++g) {
    const auto &n = shapes.n[g];
    const auto &dn = shapes.dn[g];
    double j[2][2] = {{0, 0}, {0, 0}};
    for (int a = 0; a < kNodes; ++a)
      for (int r = 0; r < 2; ++r)
        for (int s = 0; s < 2; ++s) j[r][s] += xe[2 * a + r] * dn[a][s];
    const double det = j[0][0] * j[1][1] - j[0][1] * j[1][0];
    for (int a = 0; a < kNodes; ++a) m[a] += rho * n[a] * det; // unit weights
  }
}

bool ComputeGeometry(const double xe[2 * kNodes], QuadGeometry &geo)
{
  const ShapeTable &shapes = Shapes();
  geo.area = 0;
  for (int a = 0; a < kNodes; ++a) geo.bvol[a][0] = geo.bvol[a][1] = 0;
  for (int g = 0; g < kGauss; ++g) {
    const auto &dn = shapes.dn[g];
    double j[2][2] = {{0, 0}, {0, 0}};
    for (int a = 0; a < kNodes; ++a)
      for (int r = 0; r < 2; ++r)
        for (int s = 0; s < 2; ++s) j[r][s] += xe[2 * a + r] * dn[a][s]; // J_rs = dx_r/dxi_s
    const double det = j[0][0] * j[1][1] - j[0][1] * j[1][0];
    if (!(det > 0)) return false;
    const double inv[2][2] = {{j[1][1] / det, -j[0][1] / det}, {-j[1][0] / det, j[0][0] / det}}; // dxi_s/dx_r
    for (int a = 0; a < kNodes; ++a)
      for (int r = 0; r < 2; ++r) geo.dndx[g][a][r] = dn[a][0] * inv[0][r] + dn[a][1] * inv[1][r];
    geo.wdet[g] = det; // unit weights for the 2x2 rule
    geo.area += det;
    for (int a = 0; a < kNodes; ++a)
      for (int r = 0; r < 2; ++r) geo.bvol[a][r] += det * geo.dndx[g][a][r];
  }
  for (int a = 0; a < kNodes; ++a)
    for (int r = 0; r < 2; ++r) geo.bvol[a][r] /= geo.area;
  // The centre's Jacobian (QM6's modes): det J = a0 + a1 xi + a2 eta on a
  // bilinear cell, so det J0 is the mean of the (positive) Gauss values.
  {
    const auto &dn = shapes.dn[kGauss];
    double j0[2][2] = {{0, 0}, {0, 0}};
    for (int a = 0; a < kNodes; ++a)
      for (int r = 0; r < 2; ++r)
        for (int s = 0; s < 2; ++s) j0[r][s] += xe[2 * a + r] * dn[a][s];
    const double det0 = j0[0][0] * j0[1][1] - j0[0][1] * j0[1][0];
    geo.det0 = det0;
    geo.inv0[0][0] = j0[1][1] / det0, geo.inv0[0][1] = -j0[0][1] / det0;
    geo.inv0[1][0] = -j0[1][0] / det0, geo.inv0[1][1] = j0[0][0] / det0;
  }
  return true;
}

void StrainMatrix(const QuadGeometry &geo, int g, Formulation f, double b[kVoigt][kDofs])
{
  for (int a = 0; a < kNodes; ++a) {
    const double bx = geo.dndx[g][a][0], by = geo.dndx[g][a][1];
    b[0][2 * a] = bx, b[0][2 * a + 1] = 0;
    b[1][2 * a] = 0, b[1][2 * a + 1] = by;
    b[2][2 * a] = 0, b[2][2 * a + 1] = 0;
    b[3][2 * a] = by, b[3][2 * a + 1] = bx;
    if (f == Formulation::BBar) {
      // eps_bar = dev(eps) + (1/3) mean(tr eps) 1: add (bvol - b)/3 to xx, yy, zz.
      const double dx = (geo.bvol[a][0] - bx) / 3.0, dy = (geo.bvol[a][1] - by) / 3.0;
      for (int r = 0; r < 3; ++r) {
        b[r][2 * a] += dx;
        b[r][2 * a + 1] += dy;
      }
    }
  }
}

Mat4 StressCorrection(const Voigt &s)
{
  // delta d : (sigma d + d sigma) in Voigt form (docs/theory.md (T4)), zz row included.
  Mat4 q{};
  q[0][0] = 2 * s[0];
  q[0][3] = s[3];
  q[1][1] = 2 * s[1];
  q[1][3] = s[3];
  q[2][2] = 2 * s[2];
  q[3][0] = s[3];
  q[3][1] = s[3];
  q[3][3] = 0.5 * (s[0] + s[1]);
  return q;
}

Mat4 JaumannTangent(const Mat4 &tangent, const Voigt &sigma, bool geometric)
{
  Mat4 c = tangent;
  if (!geometric) return c;
  const Mat4 q = StressCorrection(sigma);
  for (int r = 0; r < kVoigt; ++r)
    for (int s = 0; s < kVoigt; ++s) c[r][s] -= q[r][s];
  return c;
}

void ElementStiffness(const QuadGeometry &geo, Formulation f, const Mat4 tangent[kGauss], const Voigt sigma[kGauss],
                      bool geometric, ElemMat &ke)
{
  for (auto &row : ke) row.fill(0.0);
  for (int g = 0; g < kGauss; ++g) {
    double b[kVoigt][kDofs];
    StrainMatrix(geo, g, f, b);
    // ke += w det J  B^T (C - Q) B
    if (f == Formulation::BBar)
      AddBtCB(b, JaumannTangent(tangent[g], sigma[g], geometric), geo.wdet[g], ke);
    else
      AddBtCBPlain(b, kComponent8, JaumannTangent(tangent[g], sigma[g], geometric), geo.wdet[g], ke);
    if (!geometric) continue;
    // Initial-stress stiffness: (grad N_a . sigma . grad N_b) on both components.
    for (int a = 0; a < kNodes; ++a)
      for (int bn = 0; bn < kNodes; ++bn) {
        const double k = geo.wdet[g] * InitialStress(geo.dndx[g][a], geo.dndx[g][bn], sigma[g]);
        ke[2 * a][2 * bn] += k;
        ke[2 * a + 1][2 * bn + 1] += k;
      }
  }
}

void IncrementKinematics(const QuadGeometry &geo, int g, Formulation f, const ElemVec &du, Voigt &deps, double &omega)
{
  double b[kVoigt][kDofs];
  StrainMatrix(geo, g, f, b);
  for (int r = 0; r < kVoigt; ++r) {
    deps[r] = 0;
    for (int j = 0; j < kDofs; ++j) deps[r] += b[r][j] * du[j];
  }
  double lxy = 0, lyx = 0;
  for (int a = 0; a < kNodes; ++a) {
    lxy += du[2 * a] * geo.dndx[g][a][1];
    lyx += du[2 * a + 1] * geo.dndx[g][a][0];
  }
  omega = 0.5 * (lxy - lyx);
}

void InternalForce(const QuadGeometry &geo, Formulation f, const Voigt sigma[kGauss], ElemVec &fe)
{
  fe.fill(0.0);
  for (int g = 0; g < kGauss; ++g) {
    double b[kVoigt][kDofs];
    StrainMatrix(geo, g, f, b);
    for (int j = 0; j < kDofs; ++j) {
      double sum = 0;
      for (int r = 0; r < kVoigt; ++r) sum += b[r][j] * sigma[g][r];
      fe[j] += geo.wdet[g] * sum;
    }
  }
}

} // namespace tf::fe
