// Unit tests of the incompatible-modes quadrilateral QM6: symmetry and the
// rigid-body null space of the condensed tangent, the patch test on a
// distorted cell, and a slender cantilever against Timoshenko beam theory
// (where full-integration Q4 shear-locks); the same with the mean dilatation
// (-element qm6bar), whose volumetric strain must be the cell's area change
// at every Gauss point. No MPI needed.
#include <algorithm>
#include <cstdio>
#include <vector>

#include "check.hpp"
#include "tubeform/fe/qm6.hpp"
#include "tubeform/material/elastic.hpp"

using namespace tf;

// A distorted cell (the one of test_kernels).
static const double kCell[8] = {0.1, -0.2, 2.3, 0.1, 1.9, 1.7, -0.3, 1.2};

// In-place dense Cholesky A = L L^T (lower triangle, row-major n x n); false
// when a pivot falls below tol.
static bool Cholesky(std::vector<double> &a, int n, double tol)
{
  for (int j = 0; j < n; ++j) {
    double d = a[j * n + j];
    for (int k = 0; k < j; ++k) d -= a[j * n + k] * a[j * n + k];
    if (!(d > tol)) return false;
    a[j * n + j] = std::sqrt(d);
    for (int i = j + 1; i < n; ++i) {
      double s = a[i * n + j];
      for (int k = 0; k < j; ++k) s -= a[i * n + k] * a[j * n + k];
      a[i * n + j] = s / a[j * n + j];
    }
  }
  return true;
}

// Solves L L^T x = b in place with the factor of Cholesky().
static void CholeskySolve(const std::vector<double> &l, int n, std::vector<double> &b)
{
  for (int i = 0; i < n; ++i) {
    for (int k = 0; k < i; ++k) b[i] -= l[i * n + k] * b[k];
    b[i] /= l[i * n + i];
  }
  for (int i = n - 1; i >= 0; --i) {
    for (int k = i + 1; k < n; ++k) b[i] -= l[k * n + i] * b[k];
    b[i] /= l[i * n + i];
  }
}

static double MaxAbs(const fe::ElemMat &k)
{
  double m = 0;
  for (const auto &row : k)
    for (double v : row) m = std::max(m, std::fabs(v));
  return m;
}

static void StiffnessTests(bool bar)
{
  Mat4 c[4];
  Voigt s[4];
  for (auto &m : c) m = IsotropicElasticMatrix(200.0, 0.3);
  // With a prestress (varying over the cell) K* stays symmetric and rigid translations are force free.
  for (int g = 0; g < 4; ++g) s[g] = {10.0 + g, -4.0, 2.0, 3.0 - 2 * g};
  fe::ElemMat k;
  fe::Condensation cond;
  CHECK(fe::QM6Stiffness(kCell, c, s, true, k, cond, bar));
  double kmax = MaxAbs(k);
  for (int i = 0; i < 8; ++i)
    for (int j = 0; j < 8; ++j) CHECK_NEAR(k[i][j], k[j][i], 1e-12 * kmax);
  for (int comp = 0; comp < 2; ++comp) {
    for (int i = 0; i < 8; ++i) {
      double r = 0;
      for (int a = 0; a < 4; ++a) r += k[i][2 * a + comp];
      CHECK_NEAR(r, 0.0, 1e-12 * kmax);
    }
    for (int m = 0; m < 4; ++m) {
      double r = 0;
      for (int a = 0; a < 4; ++a) r += cond[m][2 * a + comp];
      CHECK_NEAR(r, 0.0, 1e-12);
    }
  }

  // Unstressed: exactly 3 zero-energy modes. K r = 0 for the 2 translations
  // and the rotation, and K + kmax P (P the projector on them) is positive definite.
  for (auto &v : s) v = {0, 0, 0, 0};
  CHECK(fe::QM6Stiffness(kCell, c, s, true, k, cond, bar));
  kmax = MaxAbs(k);
  double rigid[3][8];
  for (int a = 0; a < 4; ++a) {
    rigid[0][2 * a] = 1, rigid[0][2 * a + 1] = 0;
    rigid[1][2 * a] = 0, rigid[1][2 * a + 1] = 1;
    rigid[2][2 * a] = -kCell[2 * a + 1], rigid[2][2 * a + 1] = kCell[2 * a];
  }
  for (auto &r : rigid)
    for (int i = 0; i < 8; ++i) {
      double f = 0;
      for (int j = 0; j < 8; ++j) f += k[i][j] * r[j];
      CHECK_NEAR(f, 0.0, 1e-12 * kmax);
    }
  // Gram-Schmidt so that P = sum r r^T is the orthogonal projector.
  for (int m = 0; m < 3; ++m) {
    for (int p = 0; p < m; ++p) {
      double d = 0;
      for (int j = 0; j < 8; ++j) d += rigid[m][j] * rigid[p][j];
      for (int j = 0; j < 8; ++j) rigid[m][j] -= d * rigid[p][j];
    }
    double nn = 0;
    for (int j = 0; j < 8; ++j) nn += rigid[m][j] * rigid[m][j];
    for (int j = 0; j < 8; ++j) rigid[m][j] /= std::sqrt(nn);
  }
  std::vector<double> a(64);
  for (int i = 0; i < 8; ++i)
    for (int j = 0; j < 8; ++j) {
      a[i * 8 + j] = k[i][j];
      for (const auto &r : rigid) a[i * 8 + j] += kmax * r[i] * r[j];
    }
  CHECK(Cholesky(a, 8, 1e-8 * kmax));

  // Consistency of the three kernels: with sigma_g = C deps_g from alpha = cond du,
  // the condensed internal force is K* du (f_i vanishes by construction of cond).
  const fe::ElemVec du = {0.3, -0.1, 0.7, 0.2, -0.4, 0.9, 0.05, -0.6};
  fe::InternalVec alpha{};
  for (int m = 0; m < 4; ++m)
    for (int j = 0; j < 8; ++j) alpha[m] += cond[m][j] * du[j];
  for (int g = 0; g < 4; ++g) {
    Voigt de;
    double w;
    CHECK(fe::QM6Kinematics(kCell, g, du, alpha, de, w, bar));
    s[g] = {0, 0, 0, 0};
    for (int r = 0; r < 4; ++r)
      for (int q = 0; q < 4; ++q) s[g][r] += c[g][r][q] * de[q];
  }
  fe::ElemVec f;
  CHECK(fe::QM6InternalForce(kCell, s, cond, f, bar));
  for (int i = 0; i < 8; ++i) {
    double kd = 0;
    for (int j = 0; j < 8; ++j) kd += k[i][j] * du[j];
    CHECK_NEAR(f[i], kd, 1e-12 * kmax);
  }

  // A clockwise cell is rejected.
  const double cw[8] = {0, 0, 0, 1, 1, 1, 1, 0};
  CHECK(!fe::QM6Stiffness(cw, c, s, false, k, cond));
  CHECK(!fe::QM6Kinematics(cw, 0, du, alpha, s[0], kmax));
  CHECK(!fe::QM6InternalForce(cw, s, cond, f));
}

static void PatchTests(bool bar)
{
  // du = G x on the distorted cell: the modes stay idle (alpha = cond du = 0)
  // and every Gauss point sees the exact strain sym(G) and spin skew(G).
  Mat4 c[4];
  Voigt s[4];
  for (auto &m : c) m = IsotropicElasticMatrix(75000, 0.34);
  for (auto &v : s) v = {120.0, -40.0, 25.0, 30.0}; // uniform prestress
  const double gm[2][2] = {{0.01, 0.004}, {-0.003, -0.002}};
  fe::ElemVec du;
  double dmax = 0;
  for (int a = 0; a < 4; ++a)
    for (int i = 0; i < 2; ++i) {
      du[2 * a + i] = gm[i][0] * kCell[2 * a] + gm[i][1] * kCell[2 * a + 1];
      dmax = std::max(dmax, std::fabs(du[2 * a + i]));
    }
  for (bool geometric : {false, true}) {
    fe::ElemMat k;
    fe::Condensation cond;
    CHECK(fe::QM6Stiffness(kCell, c, s, geometric, k, cond, bar));
    fe::InternalVec alpha{};
    for (int m = 0; m < 4; ++m) {
      for (int j = 0; j < 8; ++j) alpha[m] += cond[m][j] * du[j];
      CHECK_NEAR(alpha[m], 0.0, 1e-13 * dmax);
    }
    for (int g = 0; g < 4; ++g) {
      Voigt de;
      double w;
      CHECK(fe::QM6Kinematics(kCell, g, du, alpha, de, w, bar));
      CHECK_NEAR(de[0], gm[0][0], 1e-14);
      CHECK_NEAR(de[1], gm[1][1], 1e-14);
      CHECK_NEAR(de[2], 0.0, bar ? 1e-14 : 0.0); // qm6bar: (mean - local) / 3, zero to round-off
      CHECK_NEAR(de[3], gm[0][1] + gm[1][0], 1e-14);
      CHECK_NEAR(w, 0.5 * (gm[0][1] - gm[1][0]), 1e-14);
    }
    // A uniform stress loads no mode: the condensed force is the Q4 one, which
    // is what makes an assembled patch of distorted QM6 cells exact.
    fe::ElemVec fq, fm;
    fe::QuadGeometry geo;
    fe::ComputeGeometry(kCell, geo);
    fe::InternalForce(geo, fe::Formulation::Q4, s, fq);
    CHECK(fe::QM6InternalForce(kCell, s, cond, fm, bar));
    for (int j = 0; j < 8; ++j) CHECK_NEAR(fm[j], fq[j], 1e-12 * 120.0 * geo.area);
  }
}

// Shoelace area of a quad.
static double Area(const double x[8])
{
  double a = 0;
  for (int i = 0; i < 4; ++i) {
    const int j = (i + 1) % 4;
    a += x[2 * i] * x[2 * j + 1] - x[2 * j] * x[2 * i + 1];
  }
  return 0.5 * a;
}

// The mean dilatation's defining property, against an independent measure: at
// every Gauss point the volumetric strain is the cell's relative area change,
// dA / A = (A(x + e du) - A(x - e du)) / (2 e A) (exact: the area is quadratic in
// the coordinates), the modes included (their cell integral vanishes). Without
// it (qm6) the Gauss points differ from that mean, so the check is not empty.
static void MeanDilatationTests()
{
  Mat4 c[4];
  Voigt s[4];
  for (auto &m : c) m = IsotropicElasticMatrix(200.0, 0.3);
  for (auto &v : s) v = {0, 0, 0, 0};
  const fe::ElemVec du = {0.3, -0.1, 0.7, 0.2, -0.4, 0.9, 0.05, -0.6};
  const double e = 1e-3;
  double plus[8], minus[8];
  for (int j = 0; j < 8; ++j) plus[j] = kCell[j] + e * du[j], minus[j] = kCell[j] - e * du[j];
  const double mean = (Area(plus) - Area(minus)) / (2 * e * Area(kCell));
  for (bool bar : {false, true}) {
    fe::ElemMat k;
    fe::Condensation cond;
    CHECK(fe::QM6Stiffness(kCell, c, s, false, k, cond, bar));
    fe::InternalVec alpha{};
    for (int m = 0; m < 4; ++m)
      for (int j = 0; j < 8; ++j) alpha[m] += cond[m][j] * du[j];
    double spread = 0;
    for (int g = 0; g < 4; ++g) {
      Voigt de;
      double w;
      CHECK(fe::QM6Kinematics(kCell, g, du, alpha, de, w, bar));
      spread = std::max(spread, std::fabs(de[0] + de[1] + de[2] - mean));
    }
    std::printf("%s: largest |tr deps_g - dA/A| over the Gauss points %.3g (dA/A = %.6g)\n", bar ? "qm6bar" : "qm6",
                spread, mean);
    if (bar)
      CHECK(spread < 1e-12 * std::fabs(mean));
    else
      CHECK(spread > 1e-2 * std::fabs(mean));
  }
}

// Tip deflection of a plane-strain cantilever L x h meshed nx x 1, clamped at
// x = 0 (both nodes fixed), tip shear P shared by the two tip nodes.
static double CantileverTip(bool qm6, double e, double nu, double len, double h, int nx, double p)
{
  const int nn = 2 * (nx + 1), n = 2 * nn;
  auto node = [nx](int i, int j) { return j * (nx + 1) + i; };
  Mat4 c[4];
  Voigt s[4];
  for (auto &m : c) m = IsotropicElasticMatrix(e, nu);
  for (auto &v : s) v = {0, 0, 0, 0};
  std::vector<double> k(n * n, 0.0), rhs(n, 0.0);
  for (int i = 0; i < nx; ++i) {
    const int ids[4] = {node(i, 0), node(i + 1, 0), node(i + 1, 1), node(i, 1)};
    double xe[8];
    for (int a = 0; a < 4; ++a) xe[2 * a] = len * (ids[a] % (nx + 1)) / nx, xe[2 * a + 1] = h * (ids[a] / (nx + 1));
    fe::ElemMat ke;
    if (qm6) {
      fe::Condensation cond;
      CHECK(fe::QM6Stiffness(xe, c, s, false, ke, cond));
    } else {
      fe::QuadGeometry geo;
      CHECK(fe::ComputeGeometry(xe, geo));
      fe::ElementStiffness(geo, fe::Formulation::Q4, c, s, false, ke);
    }
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b)
        for (int r = 0; r < 2; ++r)
          for (int q = 0; q < 2; ++q) k[(2 * ids[a] + r) * n + 2 * ids[b] + q] += ke[2 * a + r][2 * b + q];
  }
  rhs[2 * node(nx, 0) + 1] = rhs[2 * node(nx, 1) + 1] = 0.5 * p;
  // Clamp: identity rows and columns on the dofs of the x = 0 nodes.
  for (int j = 0; j < 2; ++j)
    for (int r = 0; r < 2; ++r) {
      const int d = 2 * node(0, j) + r;
      for (int m = 0; m < n; ++m) k[d * n + m] = k[m * n + d] = 0;
      k[d * n + d] = 1;
    }
  CHECK(Cholesky(k, n, 0.0));
  CholeskySolve(k, n, rhs);
  return 0.5 * (rhs[2 * node(nx, 0) + 1] + rhs[2 * node(nx, 1) + 1]);
}

static void CantileverTests()
{
  // L/h = 10, 10 x 1 elements. Timoshenko: P L^3 / (3 E' I) + P L / (kappa G A),
  // plane strain E' = E / (1 - nu^2), I = h^3 / 12, A = h, kappa = 5/6.
  const double e = 1000, len = 10, h = 1, p = 1;
  for (double nu : {0.3, 0.4999}) {
    const double ep = e / (1 - nu * nu), g = e / (2 * (1 + nu));
    const double beam = p * len * len * len / (3 * ep * h * h * h / 12) + p * len / (5.0 / 6.0 * g * h);
    const double qm6 = CantileverTip(true, e, nu, len, h, 10, p), q4 = CantileverTip(false, e, nu, len, h, 10, p);
    std::printf("cantilever L/h = 10, nu = %g: beam %.6g, QM6 %.6g (ratio %.4f), Q4 %.6g (ratio %.4f)\n", nu, beam, qm6,
                qm6 / beam, q4, q4 / beam);
    CHECK_NEAR(qm6 / beam, 1.0, nu < 0.45 ? 0.02 : 0.03);
    CHECK(q4 / beam < 0.8); // shear locking of full-integration Q4
  }
}

int main()
{
  for (bool bar : {false, true}) {
    StiffnessTests(bar);
    PatchTests(bar);
  }
  MeanDilatationTests();
  CantileverTests();
  return ReportChecks("test_qm6");
}
