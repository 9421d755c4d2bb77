// Unit tests of the friction law and its linearization (METHOD.md sec. 3):
// the l-row terms of friction::Linearize against finite differences of the
// friction force f_l = -mu f_n phi(x0 + dx) (plus the curvature term), and
// the law's limits (stick spring, sliding at mu f_n, increment independence).
// Tools: first contact with lines and arcs against closed forms.
#include <cmath>

#include "check.hpp"
#include "tubeform/contact/friction.hpp"
#include "tubeform/tool/tool.hpp"

using namespace tf;

int main()
{
  const double mu = 0.3, vcri = 0.01, fn0 = 50, x0 = 0.002, dU_l = -0.004, kappa = 1.0 / 3;
  // The force increment the body receives in the l row, as the row sees it:
  // G(du_l, dfn) = (f_l1 - f_l0) - fn1 kappa dx, with dx = du_l - dU_l, fn1 = fn0 + dfn.
  const auto g = [&](double du_l, double dfn) {
    const double dx = du_l - dU_l, fn1 = fn0 + dfn;
    return -mu * fn1 * friction::Phi(x0 + dx, vcri) + mu * fn0 * friction::Phi(x0, vcri) - fn1 * kappa * dx;
  };
  for (double dxk : {0.0, 0.003, -0.02}) {
    const double dfnk = 7.0, fnk = fn0 + dfnk, du_lk = dxk + dU_l;
    const friction::RowTerms t = friction::Linearize(mu, vcri, fn0, fnk, x0, dxk, dU_l, kappa);
    // Row: (K du)_l + coeff dfn + diag du_l = dF_l + rhs, i.e. the linear model of G is
    // G_lin(du_l, dfn) = rhs - coeff dfn - diag du_l (up to the second-order kappa dfn dx term).
    const double h = 1e-7;
    const double dg_du = (g(du_lk + h, dfnk) - g(du_lk - h, dfnk)) / (2 * h);
    const double dg_dfn = (g(du_lk, dfnk + h) - g(du_lk, dfnk - h)) / (2 * h);
    CHECK_NEAR(-t.diag, dg_du, 1e-6 * (1 + std::abs(dg_du)));
    CHECK_NEAR(-t.row_n_coeff, dg_dfn + kappa * dxk, 1e-6); // G has the (dropped) kappa dfn dx term
    // The linear model matches G at the linearization point.
    const double glin = t.rhs - t.row_n_coeff * dfnk - t.diag * du_lk;
    CHECK_NEAR(glin, g(du_lk, dfnk), 1e-9 * fn0);
  }
  // Limits of the law: sliding far (x >> VCRI) carries mu f_n; tiny slip is a spring of stiffness 3 mu f_n / VCRI.
  CHECK_NEAR(friction::Phi(1.0, vcri), 1.0, 2e-5); // capped at 2 VCRI: tanh(6)
  CHECK(friction::DPhi(1.0, vcri) == 0);            // no change past the cap
  CHECK_NEAR(friction::DPhi(0, vcri), 3 / vcri, 1e-12);
  CHECK_NEAR(friction::Cap(-1.0, vcri), -2 * vcri, 0);
  // Increment independence: accumulating slip in 1 or 100 pieces gives the same force.
  {
    double x1 = 0, x100 = 0;
    x1 = friction::Cap(x1 + 0.05, vcri);
    for (int k = 0; k < 100; ++k) x100 = friction::Cap(x100 + 0.0005, vcri);
    CHECK_NEAR(friction::Phi(x1, vcri), friction::Phi(x100, vcri), 1e-15);
  }

  // Tools: first contact of a point moving onto a line and onto arcs.
  {
    Tool plate = BuildFlatPlate(1.0, -5, 5); // y = 1, body below
    plate.direction = {0, -1};
    // Point at y = 0 moving up by 0.5 while the plate comes down by 1: meets at r = 1/1.5.
    CHECK_NEAR(plate.FirstContact({0.3, 0.0}, {0.0, 0.5}, 1.0), 1.0 / 1.5, 1e-14);
    CHECK(plate.FirstContact({0.3, 0.0}, {0.0, 0.1}, 0.1) > 1); // not reached
    const Tool die = BuildVDie(10.0, 2.0);
    // The apex arc: centre (0, 10 sqrt2 - 2 sqrt2), radius 2; a point straight below moving up meets it at the top.
    const double cy = 10 * std::sqrt(2.0) - 2 * std::sqrt(2.0), top = cy + 2;
    CHECK_NEAR(die.FirstContact({0.0, top - 1.0}, {0.0, 2.0}, 0.0), 0.5, 1e-12);
    // On the flank x + y = 10 sqrt2 the projection has the flank normal and zero gap.
    const Projection pr = die.Project({5 * std::sqrt(2.0), 5 * std::sqrt(2.0)});
    CHECK(pr.segment == 1);
    CHECK_NEAR(pr.gap, 0.0, 1e-12);
    CHECK_NEAR(pr.n[0], -1 / std::sqrt(2.0), 1e-15);
    // The tangent point of the fillet joins arc and flank with one normal.
    const Projection pa = die.Project({2 / std::sqrt(2.0), cy + 2 / std::sqrt(2.0)});
    CHECK_NEAR(pa.gap, 0.0, 1e-12);
    CHECK_NEAR(pa.n[0], -1 / std::sqrt(2.0), 1e-12);
    // Stroke rule: a square with perimeter 2 pi ro and sharp corners (rc = 0).
    const double u = StrokeForCornerRadius(10.0, 0.0), d = 10 * std::sqrt(2.0) - u;
    CHECK_NEAR(4 * std::sqrt(2.0) * d, 2 * M_PI * 10.0, 1e-12);
  }
  return ReportChecks("test_friction");
}
