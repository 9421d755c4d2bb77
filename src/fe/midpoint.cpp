#include "tubeform/fe/midpoint.hpp"

namespace tf::fe {

namespace {
// The shoelace area of a cell's corners and its gradient dA/dx_a.
double Area(const double x[2 * kNodes], double grad[kDofs])
{
  double area = 0;
  for (int a = 0; a < kNodes; ++a) {
    const int next = (a + 1) % kNodes, prev = (a + kNodes - 1) % kNodes;
    area += 0.5 * (x[2 * a] * x[2 * next + 1] - x[2 * next] * x[2 * a + 1]);
    grad[2 * a] = 0.5 * (x[2 * next + 1] - x[2 * prev + 1]);
    grad[2 * a + 1] = 0.5 * (x[2 * prev] - x[2 * next]);
  }
  return area;
}

// The Voigt strain of a velocity gradient change dl; with the mean dilatation
// (dmean: its mean volumetric part, else nullptr) the trace replaced by it.
void StrainOf(const double dl[2][2], const double *dmean, double col[kVoigt])
{
  col[0] = dl[0][0], col[1] = dl[1][1], col[2] = 0, col[3] = dl[0][1] + dl[1][0];
  if (!dmean) return;
  const double d = (*dmean - dl[0][0] - dl[1][1]) / 3.0;
  for (int r = 0; r < 3; ++r) col[r] += d;
}
} // namespace

bool LinearizeMidpoint(const double xs[2 * kNodes], const ElemVec &du, const Gradient l[kGauss], MidpointColumns &m)
{
  double xm[2 * kNodes], x1[2 * kNodes], grad0[kDofs], grad1[kDofs], gradm[kDofs];
  for (int k = 0; k < 2 * kNodes; ++k) xm[k] = xs[k] + 0.5 * du[k], x1[k] = xs[k] + du[k];
  if (!ComputeGeometry(xm, m.mid)) return false;
  for (int a = 0; a < kNodes; ++a) {
    // dN_a/dxi at the centre is (xi_a, eta_a) / 4, the corners counter-clockwise from (-1, -1).
    const double dxi = (a == 1 || a == 2 ? 0.25 : -0.25), deta = (a >= 2 ? 0.25 : -0.25);
    for (int r = 0; r < 2; ++r) m.h0[a][r] = dxi * m.mid.inv0[0][r] + deta * m.mid.inv0[1][r];
  }
  for (int g = 0; g < kGauss; ++g) {
    double ln[2][2] = {{0, 0}, {0, 0}};
    for (int a = 0; a < kNodes; ++a)
      for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j) ln[i][j] += du[2 * a + i] * m.mid.dndx[g][a][j];
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2; ++j) {
        m.a[g][i][j] = (i == j) - 0.5 * ln[i][j];
        m.lp[g][i][j] = l[g][2 * i + j] - ln[i][j];
      }
  }
  const double a0 = Area(xs, grad0), a1 = Area(x1, grad1), am = Area(xm, gradm);
  const double mean = (a1 - a0) / am;
  for (int k = 0; k < kDofs; ++k) m.dmean[k] = (grad1[k] - 0.5 * mean * gradm[k]) / am;
  return true;
}

void NodeStrainColumns(const MidpointColumns &m, int g, int a, bool mean_dilatation, double col[kVoigt][2])
{
  const double *h = m.mid.dndx[g][a], *h0 = m.h0[a];
  const auto &ai = m.a[g], &lp = m.lp[g];
  for (int k = 0; k < 2; ++k) {
    // dL_ij = a_ik h_j - lp_ik h0_j / 2 + lp_ij (h0_k - h_k) / 2 for a unit displacement along k.
    double dl[2][2], c[kVoigt];
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2; ++j) dl[i][j] = ai[i][k] * h[j] - 0.5 * lp[i][k] * h0[j] + 0.5 * lp[i][j] * (h0[k] - h[k]);
    StrainOf(dl, mean_dilatation ? &m.dmean[2 * a + k] : nullptr, c);
    for (int r = 0; r < kVoigt; ++r) col[r][k] = c[r];
  }
}

void ModeStrainColumns(const double h[2], bool mean_dilatation, double col[kVoigt][2])
{
  static constexpr double kNoMean = 0; // (the modes' cell mean gradient is zero)
  for (int k = 0; k < 2; ++k) {
    double dl[2][2] = {{0, 0}, {0, 0}}, c[kVoigt];
    dl[k][0] = h[0], dl[k][1] = h[1];
    StrainOf(dl, mean_dilatation ? &kNoMean : nullptr, c);
    for (int r = 0; r < kVoigt; ++r) col[r][k] = c[r];
  }
}

void MidpointElementStiffness(const QuadGeometry &rows, Formulation f, const Mat4 tangent[kGauss],
                              const Voigt sigma[kGauss], const MidpointColumns &m, ElemMat &ke)
{
  const bool bar = f == Formulation::BBar;
  for (auto &row : ke) row.fill(0.0);
  for (int g = 0; g < kGauss; ++g) {
    double bl[kVoigt][kDofs], br[kVoigt][kDofs];
    StrainMatrix(rows, g, f, bl);
    for (int a = 0; a < kNodes; ++a) {
      double col[kVoigt][2];
      NodeStrainColumns(m, g, a, bar, col);
      for (int r = 0; r < kVoigt; ++r) br[r][2 * a] = col[r][0], br[r][2 * a + 1] = col[r][1];
    }
    // ke += w det J  B^T (C - Q) B_mid
    const Mat4 c = JaumannTangent(tangent[g], sigma[g], true);
    if (bar)
      AddBtCB(bl, c, br, rows.wdet[g], ke);
    else
      AddBtCBPlainLeft(bl, kComponent8, c, br, rows.wdet[g], ke);
    // Initial-stress stiffness: (grad N_a . sigma . grad N_b) on both components.
    for (int a = 0; a < kNodes; ++a)
      for (int bn = 0; bn < kNodes; ++bn) {
        const double k = rows.wdet[g] * InitialStress(rows.dndx[g][a], rows.dndx[g][bn], sigma[g]);
        ke[2 * a][2 * bn] += k;
        ke[2 * a + 1][2 * bn + 1] += k;
      }
  }
}

} // namespace tf::fe
