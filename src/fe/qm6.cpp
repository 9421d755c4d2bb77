#include "tubeform/fe/qm6.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace tf::fe {

namespace {
constexpr int kModes = 2, kShapes = kNodes + kModes, kAll = kDofs + kInternal;

// Gradients of the 4 nodal shape functions and the 2 corrected modes.
struct Gradients {
  double g[kGauss][kShapes][2]; // d(shape s)/dx_j at Gauss point g
  double wdet[kGauss];          // quadrature weight times det J
  double mean[kShapes][2];      // cell mean of d(shape s)/dx_j: bvol for the nodes, 0 for the modes
};

// Taylor's correction: dP/dx = (det J0 / det J_g) J0^{-T} dP/dxi, so that
// sum_g w det J_g dP/dx = det J0 J0^{-T} sum_g dP/dxi = 0 (dP/dxi is odd).
// Gradients of the 6 shapes at Gauss point g of a cell with geometry `geo`.
void GradientsAt(const QuadGeometry &geo, int g, double out[kShapes][2])
{
  for (int a = 0; a < kNodes; ++a)
    for (int r = 0; r < 2; ++r) out[a][r] = geo.dndx[g][a][r];
  const double scale = geo.det0 / geo.wdet[g]; // unit weights: wdet = det J_g
  // dP_1/dxi = (-2 xi, 0), dP_2/dxi = (0, -2 eta).
  for (int r = 0; r < 2; ++r) {
    out[kNodes][r] = scale * (-2 * kXiGauss[g][0]) * geo.inv0[0][r];
    out[kNodes + 1][r] = scale * (-2 * kXiGauss[g][1]) * geo.inv0[1][r];
  }
}

void ComputeGradients(const QuadGeometry &geo, Gradients &gr)
{
  for (int g = 0; g < kGauss; ++g) {
    GradientsAt(geo, g, gr.g[g]);
    gr.wdet[g] = geo.wdet[g];
  }
  for (int s = 0; s < kShapes; ++s)
    for (int r = 0; r < 2; ++r) gr.mean[s][r] = s < kNodes ? geo.bvol[s][r] : 0.0;
}

// The B-bar change of shape s's strain rows xx, yy, zz per unit of its dof c: (mean - local) / 3.
double Dilatation(const Gradients &gr, int g, int s, int c) { return (gr.mean[s][c] - gr.g[g][s][c]) / 3.0; }

// Dof of component c of shape s among the 12: (u_x, u_y) node by node, then alpha[2 c + m].
int Dof(int s, int c) { return s < kNodes ? 2 * s + c : kDofs + kModes * c + (s - kNodes); }
// The component of each of the 12 dofs (its normal strain row without the mean dilatation).
constexpr int kComponent12[kAll] = {0, 1, 0, 1, 0, 1, 0, 1, 0, 0, 1, 1};

// Strain-displacement matrix of the 12 dofs at Gauss point g (zz row zero; with
// the mean dilatation, the rows xx, yy, zz carry the cell's mean volumetric strain).
void StrainMatrix12(const Gradients &gr, int g, double b[kVoigt][kAll], bool mean_dilatation)
{
  for (int r = 0; r < kVoigt; ++r)
    for (int j = 0; j < kAll; ++j) b[r][j] = 0;
  for (int s = 0; s < kShapes; ++s) {
    const double gx = gr.g[g][s][0], gy = gr.g[g][s][1];
    b[0][Dof(s, 0)] = gx;
    b[1][Dof(s, 1)] = gy;
    b[3][Dof(s, 0)] = gy;
    b[3][Dof(s, 1)] = gx;
    if (mean_dilatation)
      for (int c = 0; c < 2; ++c)
        for (int r = 0; r < 3; ++r) b[r][Dof(s, c)] += Dilatation(gr, g, s, c);
  }
}

// Solves A X = B in place (X overwrites B, N columns) by Gaussian elimination
// with partial pivoting; false when a pivot is negligible against max |A_ij|.
template <int N>
bool Solve4(double a[kInternal][kInternal], double x[kInternal][N])
{
  double amax = 0;
  for (int i = 0; i < kInternal; ++i)
    for (int j = 0; j < kInternal; ++j) amax = std::max(amax, std::fabs(a[i][j]));
  for (int k = 0; k < kInternal; ++k) {
    int p = k;
    for (int i = k + 1; i < kInternal; ++i)
      if (std::fabs(a[i][k]) > std::fabs(a[p][k])) p = i;
    if (!(std::fabs(a[p][k]) > kPivotTol * amax)) return false;
    if (p != k) {
      std::swap(a[p], a[k]);
      std::swap(x[p], x[k]);
    }
    for (int i = k + 1; i < kInternal; ++i) {
      const double m = a[i][k] / a[k][k];
      for (int j = k; j < kInternal; ++j) a[i][j] -= m * a[k][j];
      for (int j = 0; j < N; ++j) x[i][j] -= m * x[k][j];
    }
  }
  for (int k = kInternal - 1; k >= 0; --k)
    for (int j = 0; j < N; ++j) {
      double sum = x[k][j];
      for (int i = k + 1; i < kInternal; ++i) sum -= a[k][i] * x[i][j];
      x[k][j] = sum / a[k][k];
    }
  return true;
}

// cond = -Kii^{-1} Kic of the 12-dof k, then K* = Kcc + Kci cond (and Kii^{-1}
// with kii_inv); false when Kii is singular.
bool Condense(const double (&k)[kAll][kAll], ElemMat &ke, Condensation &cond, ModeMatrix *kii_inv)
{
  double kii[kInternal][kInternal], x[kInternal][kDofs];
  for (int i = 0; i < kInternal; ++i) {
    for (int j = 0; j < kInternal; ++j) kii[i][j] = k[kDofs + i][kDofs + j];
    for (int j = 0; j < kDofs; ++j) x[i][j] = k[kDofs + i][j];
  }
  if (kii_inv) {
    double a[kInternal][kInternal], id[kInternal][kInternal] = {};
    for (int i = 0; i < kInternal; ++i) {
      id[i][i] = 1;
      for (int j = 0; j < kInternal; ++j) a[i][j] = kii[i][j];
    }
    if (!Solve4<kInternal>(a, id)) return false;
    for (int i = 0; i < kInternal; ++i)
      for (int j = 0; j < kInternal; ++j) (*kii_inv)[i][j] = id[i][j];
  }
  if (!Solve4<kDofs>(kii, x)) return false;
  for (int i = 0; i < kInternal; ++i)
    for (int j = 0; j < kDofs; ++j) cond[i][j] = -x[i][j];
  for (int i = 0; i < kDofs; ++i)
    for (int j = 0; j < kDofs; ++j) {
      double sum = k[i][j];
      for (int m = 0; m < kInternal; ++m) sum += k[i][kDofs + m] * cond[m][j];
      ke[i][j] = sum;
    }
  return true;
}

} // namespace

bool QM6Stiffness(const double xe[2 * kNodes], const Mat4 tangent[kGauss], const Voigt sigma[kGauss], bool geometric,
                  ElemMat &ke, Condensation &cond, bool mean_dilatation)
{
  QuadGeometry geo;
  return ComputeGeometry(xe, geo) && QM6Stiffness(xe, geo, tangent, sigma, geometric, ke, cond, mean_dilatation);
}

bool QM6Stiffness(const double xe[2 * kNodes], const QuadGeometry &geo, const Mat4 tangent[kGauss],
                  const Voigt sigma[kGauss], bool geometric, ElemMat &ke, Condensation &cond, bool mean_dilatation)
{
  return QM6Stiffness(xe, geo, tangent, sigma, geometric, ke, cond, nullptr, mean_dilatation);
}

bool QM6Stiffness(const double xe[2 * kNodes], const QuadGeometry &geo, const Mat4 tangent[kGauss],
                  const Voigt sigma[kGauss], bool geometric, ElemMat &ke, Condensation &cond, ModeMatrix *kii_inv,
                  bool mean_dilatation)
{
  Gradients gr;
  ComputeGradients(geo, gr);
  double k[kAll][kAll] = {};
  for (int g = 0; g < kGauss; ++g) {
    double b[kVoigt][kAll];
    StrainMatrix12(gr, g, b, mean_dilatation);
    // k += w det J  B12^T (C - Q) B12
    if (mean_dilatation)
      AddBtCB(b, JaumannTangent(tangent[g], sigma[g], geometric), gr.wdet[g], k);
    else
      AddBtCBPlain(b, kComponent12, JaumannTangent(tangent[g], sigma[g], geometric), gr.wdet[g], k);
    if (!geometric) continue;
    // Initial-stress stiffness (grad P_s . sigma . grad P_t) I over nodes and modes alike.
    for (int s = 0; s < kShapes; ++s)
      for (int t = 0; t < kShapes; ++t) {
        const double kst = gr.wdet[g] * InitialStress(gr.g[g][s], gr.g[g][t], sigma[g]);
        for (int comp = 0; comp < 2; ++comp) k[Dof(s, comp)][Dof(t, comp)] += kst;
      }
  }
  return Condense(k, ke, cond, kii_inv);
}

bool QM6Stiffness(const QuadGeometry &rows, const Mat4 tangent[kGauss], const Voigt sigma[kGauss],
                  const MidpointColumns &m, ElemMat &ke, bool mean_dilatation)
{
  Gradients gr, gm;
  ComputeGradients(rows, gr);
  ComputeGradients(m.mid, gm);
  double k[kAll][kAll] = {};
  for (int g = 0; g < kGauss; ++g) {
    double bl[kVoigt][kAll], br[kVoigt][kAll];
    StrainMatrix12(gr, g, bl, mean_dilatation);
    for (int s = 0; s < kShapes; ++s) {
      double col[kVoigt][2];
      if (s < kNodes)
        NodeStrainColumns(m, g, s, mean_dilatation, col);
      else
        ModeStrainColumns(gm.g[g][s], mean_dilatation, col);
      for (int r = 0; r < kVoigt; ++r)
        for (int c = 0; c < 2; ++c) br[r][Dof(s, c)] = col[r][c];
    }
    // k += w det J  B12^T (C - Q) B12_mid
    const Mat4 c = JaumannTangent(tangent[g], sigma[g], true);
    if (mean_dilatation)
      AddBtCB(bl, c, br, gr.wdet[g], k);
    else
      AddBtCBPlainLeft(bl, kComponent12, c, br, gr.wdet[g], k);
    // Initial-stress stiffness (grad P_s . sigma . grad P_t) I over nodes and modes alike.
    for (int s = 0; s < kShapes; ++s)
      for (int t = 0; t < kShapes; ++t) {
        const double kst = gr.wdet[g] * InitialStress(gr.g[g][s], gr.g[g][t], sigma[g]);
        for (int comp = 0; comp < 2; ++comp) k[Dof(s, comp)][Dof(t, comp)] += kst;
      }
  }
  Condensation cond;
  return Condense(k, ke, cond, nullptr);
}

bool QM6Kinematics(const double xe[2 * kNodes], int g, const ElemVec &du, const InternalVec &alpha, Voigt &deps,
                   double &omega, bool mean_dilatation)
{
  QuadGeometry geo;
  if (!ComputeGeometry(xe, geo)) return false;
  QM6Kinematics(xe, geo, g, du, alpha, deps, omega, mean_dilatation);
  return true;
}

void QM6Kinematics(const double xe[2 * kNodes], const QuadGeometry &geo, int g, const ElemVec &du,
                   const InternalVec &alpha, Voigt &deps, double &omega, bool mean_dilatation)
{
  double gr[kShapes][2];
  GradientsAt(geo, g, gr);
  // L_ij = d(du_i)/dx_j summed over the nodal shape functions and the modes.
  double l[2][2] = {{0, 0}, {0, 0}};
  for (int s = 0; s < kShapes; ++s)
    for (int c = 0; c < 2; ++c) {
      const double v = s < kNodes ? du[2 * s + c] : alpha[kModes * c + (s - kNodes)];
      for (int j = 0; j < 2; ++j) l[c][j] += v * gr[s][j];
    }
  deps = {l[0][0], l[1][1], 0.0, l[0][1] + l[1][0]};
  omega = 0.5 * (l[0][1] - l[1][0]);
  if (mean_dilatation) {
    // The cell's mean volumetric strain in place of the point's (the modes' mean is zero).
    double mean = 0;
    for (int a = 0; a < kNodes; ++a) mean += geo.bvol[a][0] * du[2 * a] + geo.bvol[a][1] * du[2 * a + 1];
    const double d = (mean - l[0][0] - l[1][1]) / 3.0;
    for (int r = 0; r < 3; ++r) deps[r] += d;
  }
}

bool QM6InternalForce(const double xe[2 * kNodes], const Voigt sigma[kGauss], const Condensation &cond, ElemVec &f,
                      bool mean_dilatation)
{
  QuadGeometry geo;
  if (!ComputeGeometry(xe, geo)) return false;
  QM6InternalForce(xe, geo, sigma, cond, f, mean_dilatation);
  return true;
}

void QM6InternalForce(const double xe[2 * kNodes], const QuadGeometry &geo, const Voigt sigma[kGauss],
                      const Condensation &cond, ElemVec &f, bool mean_dilatation)
{
  Gradients gr;
  ComputeGradients(geo, gr);
  // f12 = sum_g w det J B12^T sigma_g: per shape, grad P . sigma on each component.
  double f12[kAll] = {};
  for (int g = 0; g < kGauss; ++g) {
    const double sxx = sigma[g][0], syy = sigma[g][1], sxy = sigma[g][3];
    const double trace = mean_dilatation ? sigma[g][0] + sigma[g][1] + sigma[g][2] : 0.0;
    for (int s = 0; s < kShapes; ++s) {
      const double gx = gr.g[g][s][0], gy = gr.g[g][s][1];
      f12[Dof(s, 0)] += gr.wdet[g] * (gx * sxx + gy * sxy);
      f12[Dof(s, 1)] += gr.wdet[g] * (gx * sxy + gy * syy);
      if (mean_dilatation)
        for (int c = 0; c < 2; ++c) f12[Dof(s, c)] += gr.wdet[g] * Dilatation(gr, g, s, c) * trace;
    }
  }
  for (int j = 0; j < kDofs; ++j) {
    double sum = f12[j];
    for (int m = 0; m < kInternal; ++m) sum += cond[m][j] * f12[kDofs + m];
    f[j] = sum;
  }
}

void QM6ModeForce(const double xe[2 * kNodes], const QuadGeometry &geo, const Voigt sigma[kGauss], InternalVec &fi,
                  bool mean_dilatation)
{
  Gradients gr;
  ComputeGradients(geo, gr);
  fi = {};
  for (int g = 0; g < kGauss; ++g) {
    const double sxx = sigma[g][0], syy = sigma[g][1], sxy = sigma[g][3];
    const double trace = mean_dilatation ? sigma[g][0] + sigma[g][1] + sigma[g][2] : 0.0;
    for (int m = 0; m < kModes; ++m) {
      const double gx = gr.g[g][kNodes + m][0], gy = gr.g[g][kNodes + m][1];
      fi[kModes * 0 + m] += gr.wdet[g] * (gx * sxx + gy * sxy);
      fi[kModes * 1 + m] += gr.wdet[g] * (gx * sxy + gy * syy);
      if (mean_dilatation)
        for (int c = 0; c < 2; ++c) fi[kModes * c + m] += gr.wdet[g] * Dilatation(gr, g, kNodes + m, c) * trace;
    }
  }
}

} // namespace tf::fe
