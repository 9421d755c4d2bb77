// Unit test of the midpoint (Hughes-Winget) linearization (fe/midpoint.hpp,
// docs/theory.md 5a): the tangent an equilibrium correction takes at an iterate
// du must be the derivative of that iterate's forces. For a linear elastic law
// without prestress the element force of an increment v, with rows on a fixed
// configuration (the kernels' rows: the iterate's, xs + du),
//     f(v) = sum_g w B^T C deps_mid(v),
// deps_mid the strain on the mid configuration xs + v/2 (QM6: its modes in
// balance, f_i = 0), must have the kernels' matrix as its derivative at v = du.
// Reference: central differences of f, from the kinematics the forces use
// (IncrementKinematics, QM6Kinematics), not from the kernels. A distorted cell,
// an increment of about 10 % strain with a rotation; q4, bbar, qm6, qm6bar.
// Tolerance 1e-7 of the largest entry: the differences' own error (step 1e-6:
// truncation 1e-12, round-off 1e-16 / 1e-6 of the forces) measured 1.6e-10 at
// most. The start's columns are off by the order of the strain increment (the
// check fails on them by far), and QM6's mode gradients, which take the
// centre's Jacobian, move with the mid configuration: taken as the nodes' they
// are off by 7.6e-4 (qm6), 5.5e-4 (qm6bar).
#include <algorithm>
#include <cmath>

#include "check.hpp"
#include "tubeform/fe/qm6.hpp"
#include "tubeform/material/elastic.hpp"

using namespace tf;

namespace {

// A distorted cell (test_kernels's) and an increment of about 10 % strain with a rotation.
const double kCell[8] = {0.1, -0.2, 2.3, 0.1, 1.9, 1.7, -0.3, 1.2};
const fe::ElemVec kDu = {0.02, -0.05, 0.21, 0.04, 0.12, 0.25, -0.09, 0.13};
// Relative step of the central differences and the tolerance (above).
constexpr double kStep = 1e-6, kTol = 1e-7;

bool HasModes(fe::Formulation f) { return f == fe::Formulation::QM6 || f == fe::Formulation::QM6Bar; }

// Strain and spin at every Gauss point of the increment v (modes alpha) on the mid configuration.
void MidKinematics(fe::Formulation f, const fe::ElemVec &v, const fe::InternalVec &alpha, Voigt deps[fe::kGauss],
                   double omega[fe::kGauss])
{
  double xm[8];
  for (int k = 0; k < 8; ++k) xm[k] = kCell[k] + 0.5 * v[k];
  fe::QuadGeometry mid;
  CHECK(fe::ComputeGeometry(xm, mid));
  for (int g = 0; g < fe::kGauss; ++g) {
    if (HasModes(f))
      fe::QM6Kinematics(xm, mid, g, v, alpha, deps[g], omega[g], f == fe::Formulation::QM6Bar);
    else
      fe::IncrementKinematics(mid, g, f, v, deps[g], omega[g]);
  }
}

// The rows' strain matrix over the 8 nodal dofs and the 4 modes (zero columns without modes).
void Rows(fe::Formulation f, const fe::QuadGeometry &rows, int g, double b[fe::kVoigt][12])
{
  for (int k = 0; k < 12; ++k) {
    fe::ElemVec v{};
    fe::InternalVec a{};
    (k < 8 ? v[k] : a[k - 8]) = 1;
    Voigt e;
    double w;
    if (HasModes(f)) {
      fe::QM6Kinematics(kCell, rows, g, v, a, e, w, f == fe::Formulation::QM6Bar);
    } else {
      fe::IncrementKinematics(rows, g, f, v, e, w);
      if (k >= 8) e = {};
    }
    for (int r = 0; r < fe::kVoigt; ++r) b[r][k] = e[r];
  }
}

} // namespace

namespace {

// f = sum_g w B^T C deps_mid(v, alpha) over the 12 dofs (rows on `rows`), C the elastic law.
void Force(fe::Formulation f, const fe::QuadGeometry &rows, const Mat4 &c, const fe::ElemVec &v,
           const fe::InternalVec &alpha, double out[12])
{
  Voigt deps[fe::kGauss];
  double omega[fe::kGauss];
  MidKinematics(f, v, alpha, deps, omega);
  std::fill(out, out + 12, 0.0);
  for (int g = 0; g < fe::kGauss; ++g) {
    double b[fe::kVoigt][12];
    Rows(f, rows, g, b);
    for (int k = 0; k < 12; ++k)
      for (int r = 0; r < fe::kVoigt; ++r)
        for (int s = 0; s < fe::kVoigt; ++s) out[k] += rows.wdet[g] * b[r][k] * c[r][s] * deps[g][s];
  }
}

// The modes in balance for v (f_i = 0: f_i is linear in alpha at a given v), by Gaussian elimination.
fe::InternalVec Balanced(fe::Formulation f, const fe::QuadGeometry &rows, const Mat4 &c, const fe::ElemVec &v)
{
  fe::InternalVec alpha{};
  if (!HasModes(f)) return alpha;
  double f0[12], a[4][5];
  Force(f, rows, c, v, alpha, f0);
  for (int j = 0; j < 4; ++j) {
    fe::InternalVec e{};
    e[j] = 1;
    double fj[12];
    Force(f, rows, c, v, e, fj);
    for (int i = 0; i < 4; ++i) a[i][j] = fj[8 + i] - f0[8 + i];
  }
  for (int i = 0; i < 4; ++i) a[i][4] = -f0[8 + i];
  for (int k = 0; k < 4; ++k) {
    int p = k;
    for (int i = k + 1; i < 4; ++i)
      if (std::fabs(a[i][k]) > std::fabs(a[p][k])) p = i;
    std::swap(a[p], a[k]);
    for (int i = 0; i < 4; ++i)
      if (i != k) {
        const double m = a[i][k] / a[k][k];
        for (int j = k; j < 5; ++j) a[i][j] -= m * a[k][j];
      }
  }
  for (int i = 0; i < 4; ++i) alpha[i] = a[i][4] / a[i][i];
  return alpha;
}

// The kernel's tangent at du: columns from the iterate's own mid velocity gradients.
void Kernel(fe::Formulation f, const fe::QuadGeometry &rows, const Mat4 &c, fe::ElemMat &ke)
{
  const fe::InternalVec alpha = Balanced(f, rows, c, kDu);
  Voigt deps[fe::kGauss];
  double omega[fe::kGauss];
  MidKinematics(f, kDu, alpha, deps, omega);
  fe::Gradient l[fe::kGauss];
  for (int g = 0; g < fe::kGauss; ++g)
    l[g] = {deps[g][0] - deps[g][2], 0.5 * deps[g][3] + omega[g], 0.5 * deps[g][3] - omega[g], deps[g][1] - deps[g][2]};
  fe::MidpointColumns m;
  CHECK(fe::LinearizeMidpoint(kCell, kDu, l, m));
  const Mat4 cs[fe::kGauss] = {c, c, c, c};
  const Voigt zero[fe::kGauss] = {};
  if (HasModes(f))
    CHECK(fe::QM6Stiffness(rows, cs, zero, m, ke, f == fe::Formulation::QM6Bar));
  else
    fe::MidpointElementStiffness(rows, f, cs, zero, m, ke);
}

// Largest difference of the kernel's tangent from the central differences of the
// balanced force, over the largest entry; `volumetric`: the same of the tangent's
// product with the difference of the forward (start) columns (how far they are off).
double Check(fe::Formulation f, const char *name)
{
  double x1[8];
  for (int k = 0; k < 8; ++k) x1[k] = kCell[k] + kDu[k];
  fe::QuadGeometry rows;
  CHECK(fe::ComputeGeometry(x1, rows));
  const Mat4 c = Elastic(1.0, 0.3).Tangent(PointState{});
  fe::ElemMat ke;
  Kernel(f, rows, c, ke);
  double scale = 0, err = 0;
  for (int j = 0; j < 8; ++j) {
    fe::ElemVec vp = kDu, vm = kDu;
    vp[j] += kStep, vm[j] -= kStep;
    double fp[12], fm[12];
    Force(f, rows, c, vp, Balanced(f, rows, c, vp), fp);
    Force(f, rows, c, vm, Balanced(f, rows, c, vm), fm);
    for (int i = 0; i < 8; ++i) {
      const double fd = (fp[i] - fm[i]) / (2 * kStep);
      scale = std::max(scale, std::fabs(fd));
      err = std::max(err, std::fabs(fd - ke[i][j]));
    }
  }
  std::printf("%-7s tangent at the iterate vs central differences: %.2e of its largest entry %.3g\n", name, err / scale,
              scale);
  return err / scale;
}

} // namespace

int main()
{
  const std::pair<fe::Formulation, const char *> kinds[] = {{fe::Formulation::Q4, "q4"},
                                                            {fe::Formulation::BBar, "bbar"},
                                                            {fe::Formulation::QM6, "qm6"},
                                                            {fe::Formulation::QM6Bar, "qm6bar"}};
  for (const auto &[f, name] : kinds) CHECK(Check(f, name) <= kTol);
  return ReportChecks("test_midpoint");
}
