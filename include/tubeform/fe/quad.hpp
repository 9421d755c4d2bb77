// Pure kernels of the 4-node quadrilateral (no PETSc): shape functions,
// gradients in the current configuration, the (B-bar) strain-displacement
// matrix and the updated-Lagrangian tangent of docs/theory.md, section 4.
//
// Voigt order {xx, yy, zz, xy}; strains carry gamma_xy. Element dofs are
// ordered (u_x, u_y) node by node, nodes counter-clockwise.
#pragma once

#include <array>
#include <cmath>

namespace tf::fe {

enum class Formulation {
  Q4,   // full 2x2 integration (locks for near-incompressible flow)
  BBar, // mean-dilatation B-bar (Hughes 1980): volumetric strain averaged over the cell
  QM6,  // incompatible modes (Wilson; Taylor et al. 1976), free of shear locking: see qm6.hpp
  // QM6 with the mean dilatation of B-bar: no shear locking in bending, a constant
  // pressure per cell in plastic (isochoric) flow; see qm6.hpp
  QM6Bar,
};

constexpr int kNodes = 4, kGauss = 4, kDofs = 8, kVoigt = 4;

using Mat4 = std::array<std::array<double, kVoigt>, kVoigt>;
using Voigt = std::array<double, kVoigt>;
using ElemMat = std::array<std::array<double, kDofs>, kDofs>;
using ElemVec = std::array<double, kDofs>;

// Gradients of the shape functions at the 2x2 Gauss points of a cell with
// corners xe (x0, y0, x1, y1, ...), with the weights w_g det J_g.
struct QuadGeometry {
  double dndx[kGauss][kNodes][2]; // dN_a/dx_j at Gauss point g
  double wdet[kGauss];            // quadrature weight times det J
  double bvol[kNodes][2];         // cell mean of dN_a/dx_j (B-bar volumetric row)
  double area;
  double det0;       // det J at the cell centre (xi = eta = 0)
  double inv0[2][2]; // J^{-1} at the centre, dxi_s/dx_r (QM6's corrected modes)
};

// The 2x2 Gauss points' natural coordinates (+-1/sqrt 3), in the order of the point states.
inline const double kGaussXi = 1.0 / std::sqrt(3.0);
inline const double kXiGauss[kGauss][2] = {
  {-kGaussXi, -kGaussXi}, {kGaussXi, -kGaussXi}, {kGaussXi, kGaussXi}, {-kGaussXi, kGaussXi}};
// The component of each dof (u_x, u_y node by node): its normal strain row.
constexpr int kComponent8[kDofs] = {0, 1, 0, 1, 0, 1, 0, 1};

// The shape functions and their natural gradients at (xi, eta).
void ShapeFunctions(double xi, double eta, double n[kNodes], double dn[kNodes][2]);
// The coordinates of a cell's Gauss points (in the order of the point states).
void GaussPoints(const double xe[2 * kNodes], double xg[kGauss][2]);

// Row-sum lumped mass of a cell: m_a = rho * integral of N_a over the cell
// (2x2 Gauss), per unit thickness. Exact for the bilinear shape functions.
void LumpedMass(const double xe[2 * kNodes], double rho, double m[kNodes]);

// Fills `geo`; returns false when det J <= 0 at a Gauss point (inverted cell).
bool ComputeGeometry(const double xe[2 * kNodes], QuadGeometry &geo);

// Strain-displacement matrix at Gauss point g (4 Voigt rows x 8 dofs).
void StrainMatrix(const QuadGeometry &geo, int g, Formulation f, double b[kVoigt][kDofs]);

// Stress-correction matrix Q of docs/theory.md (T4) (from -2 sigma.D : dD), 4x4 form.
Mat4 StressCorrection(const Voigt &sigma);

// The material part of the updated-Lagrangian tangent at a Gauss point:
// C - Q(sigma) with `geometric`, else C.
Mat4 JaumannTangent(const Mat4 &tangent, const Voigt &sigma, bool geometric);

// The initial-stress product grad_a . sigma . grad_b of two shape gradients.
inline double InitialStress(const double ga[2], const double gb[2], const Voigt &s)
{
  return ga[0] * (s[0] * gb[0] + s[3] * gb[1]) + ga[1] * (s[3] * gb[0] + s[1] * gb[1]);
}

// cb = C Br.
template <int N>
void TimesB(const Mat4 &c, const double (&br)[kVoigt][N], double (&cb)[kVoigt][N])
{
  for (int r = 0; r < kVoigt; ++r)
    for (int j = 0; j < N; ++j) {
      double sum = 0;
      for (int s = 0; s < kVoigt; ++s) sum += c[r][s] * br[s][j];
      cb[r][j] = sum;
    }
}

// k += w Bl^T C Br: rows and columns of different strain matrices (an unsymmetric tangent).
template <int N, class K>
void AddBtCB(const double (&bl)[kVoigt][N], const Mat4 &c, const double (&br)[kVoigt][N], double w, K &k)
{
  double cb[kVoigt][N];
  TimesB(c, br, cb);
  for (int i = 0; i < N; ++i)
    for (int j = 0; j < N; ++j) {
      double sum = 0;
      for (int r = 0; r < kVoigt; ++r) sum += bl[r][i] * cb[r][j];
      k[i][j] += w * sum;
    }
}

// k += w B^T C B for a strain matrix of N columns (8 for Q4/B-bar, 12 for
// QM6 with its incompatible modes); K is any N x N indexable matrix.
template <int N, class K>
void AddBtCB(const double (&b)[kVoigt][N], const Mat4 &c, double w, K &k)
{
  AddBtCB(b, c, b, w, k);
}

// AddBtCB (Bl, C, Br) for a plain Bl (as AddBtCBPlain's) and any Br.
template <int N, class K>
void AddBtCBPlainLeft(const double (&bl)[kVoigt][N], const int (&comp)[N], const Mat4 &c, const double (&br)[kVoigt][N],
                      double w, K &k)
{
  double cb[kVoigt][N];
  TimesB(c, br, cb);
  for (int i = 0; i < N; ++i) {
    const int ri = comp[i];
    for (int j = 0; j < N; ++j) k[i][j] += w * (bl[ri][i] * cb[ri][j] + bl[3][i] * cb[3][j]);
  }
}

// AddBtCB for a plain strain matrix (no mean dilatation): column j strains
// the row comp[j] (xx for an x dof, yy for a y dof) and the shear row xy,
// nothing else. AddBtCB's sums without their zero terms, in its order: the
// same values, at less than half the work of QM6's 12 columns.
template <int N, class K>
void AddBtCBPlain(const double (&b)[kVoigt][N], const int (&comp)[N], const Mat4 &c, double w, K &k)
{
  double cb[kVoigt][N];
  for (int r = 0; r < kVoigt; ++r)
    for (int j = 0; j < N; ++j) cb[r][j] = c[r][comp[j]] * b[comp[j]][j] + c[r][3] * b[3][j];
  for (int i = 0; i < N; ++i) {
    const int ri = comp[i];
    for (int j = 0; j < N; ++j) k[i][j] += w * (b[ri][i] * cb[ri][j] + b[3][i] * cb[3][j]);
  }
}

// Element tangent  K = sum_g w det J [ Bbar^T (C_g - Q(sigma_g)) Bbar + G^T S_g G ],
// with C_g the tangent relating the Jaumann rate of Kirchhoff stress to d, and
// the initial-stress part G^T S G = (grad N_a . sigma . grad N_b) I.
// `geometric` = false drops the Q and initial-stress terms (small-strain tangent).
void ElementStiffness(const QuadGeometry &geo, Formulation f, const Mat4 tangent[kGauss], const Voigt sigma[kGauss],
                      bool geometric, ElemMat &ke);

// Increment kinematics at Gauss point g from the nodal increments du:
// strain increment (Voigt, B-bar if chosen) and the spin increment
// omega = (L_xy - L_yx) / 2 with L_ij = d(du_i)/dx_j.
void IncrementKinematics(const QuadGeometry &geo, int g, Formulation f, const ElemVec &du, Voigt &deps, double &omega);

// Internal force  f = sum_g w det J Bbar^T sigma_g.
void InternalForce(const QuadGeometry &geo, Formulation f, const Voigt sigma[kGauss], ElemVec &fe);

} // namespace tf::fe
