// Unit tests of the friction law and its linearization (docs/theory.md, section 6):
// the l-row terms of friction::Linearize against finite differences of the
// friction force f_l = -mu f_n phi(x0 + dx) (plus the curvature terms, the
// normal force increment being the n-row reaction less kappa f_l dx); the
// n-row term's sign against the geometry of a force carried along concave
// and convex arcs; r6 (slide to stick) landing exactly where the mobilization
// has fallen by dphi_max; the law's limits (stick spring, sliding at mu f_n,
// increment independence).
// Tools: first contact with lines and arcs against closed forms.
#include <cmath>

#include "check.hpp"
#include "tubeform/contact/friction.hpp"
#include "tubeform/tool/shape.hpp"
#include "tubeform/tool/tool.hpp"

using namespace tf;

int main()
{
  const double mu = 0.3, vcri = 0.01, fn0 = 50, x0 = 0.002, dU_l = -0.004, kappa = 1.0 / 3;
  // w: the tool's own turn in the step (a die turning along its path), which turns the frame with kappa dx.
  for (double w : {0.0, 0.002}) {
    // The force increment the body receives in the l row, as the row sees it:
    // G(du_l, dfn) = (f_l1 - f_l0) - fn1 (kappa dx + w), with dx = du_l - dU_l, fn1 = fn0 + dfn.
    const auto g = [&](double du_l, double dfn) {
      const double dx = du_l - dU_l, fn1 = fn0 + dfn;
      return -mu * fn1 * friction::Phi(x0 + dx, vcri) + mu * fn0 * friction::Phi(x0, vcri) - fn1 * (kappa * dx + w);
    };
    for (double dxk : {0.0, 0.003, -0.02}) {
      const double dfnk = 7.0, fnk = fn0 + dfnk, du_lk = dxk + dU_l;
      // The row sees the reaction R_n; the normal force changes by R_n - f_lk (kappa dx + w)
      // (f_lk: the iterate's friction force, fixed within the solve).
      const double f_lk = -mu * fnk * friction::Phi(x0 + dxk, vcri);
      const auto g_of_r = [&](double du_l, double r_n) { return g(du_l, r_n - f_lk * (kappa * (du_l - dU_l) + w)); };
      const double rk = dfnk + f_lk * (kappa * dxk + w); // the reaction that gives the normal force change dfnk
      const friction::RowTerms t = friction::Linearize(mu, vcri, fn0, fnk, x0, dxk, dU_l, kappa, w);
      // Row: (K du)_l + coeff R_n + diag du_l = dF_l + rhs, i.e. the linear model of G is
      // G_lin(du_l, R_n) = rhs - coeff R_n - diag du_l (up to the second-order dfn (kappa dx + w) term).
      const double h = 1e-7;
      const double dg_du = (g_of_r(du_lk + h, rk) - g_of_r(du_lk - h, rk)) / (2 * h);
      const double dg_dr = (g_of_r(du_lk, rk + h) - g_of_r(du_lk, rk - h)) / (2 * h);
      // The dropped second-order term dfn (kappa dx + w) contributes (kappa dxk + w) (kappa f_lk) to d/du and
      // kappa dxk + w to d/dR.
      CHECK_NEAR(-t.diag, dg_du - (kappa * dxk + w) * kappa * f_lk, 1e-6 * (1 + std::abs(dg_du)));
      CHECK_NEAR(-t.row_n_coeff, dg_dr + kappa * dxk + w, 1e-6);
      // The linear model matches G at the linearization point.
      const double glin = t.rhs - t.row_n_coeff * rk - t.diag * du_lk;
      CHECK_NEAR(glin, g_of_r(du_lk, rk), 1e-9 * fn0);
    }
  }
  // The n-row term's sign from geometry: a contact force f_n n + f_l l carried
  // along an arc of radius rho by a slip s, with f_n and f_l changing linearly
  // in s, the tool turning by w as well. Its change along the start normal is the reaction R_n; NormalIncrement
  // must return the change of f_n to O(s^2, w^2) (without the term: an error f_l (kappa s + w)).
  for (const double w : {0.0, 1e-4})
    for (const bool concave : {true, false}) {
      const double rho = 3.0, th0 = 0.7, fn_0 = 40, fl_0 = -6, a = 900, b = -150, s = 1e-4;
      const double k = (concave ? 1.0 : -1.0) / rho;
      const auto frame = [&](double slip, double turn, double n[2], double l[2]) {
        // Concave: n = -e_r, l = e_theta (slip turns theta forward); convex: n = e_r, l = -e_theta; the tool's
        // turn turns both counter-clockwise.
        const double th = th0 + (concave ? 1 : -1) * slip / rho + turn, er[2] = {std::cos(th), std::sin(th)};
        const double et[2] = {-std::sin(th), std::cos(th)}, sn = concave ? -1 : 1;
        n[0] = sn * er[0], n[1] = sn * er[1], l[0] = -sn * et[0], l[1] = -sn * et[1]; // l = n turned by -90 degrees
      };
      double n0[2], l0[2], n1[2], l1[2];
      frame(0, 0, n0, l0);
      frame(s, w, n1, l1);
      const double fn_s = fn_0 + a * s, fl_s = fl_0 + b * s;
      const double r_n = (fn_s * n1[0] + fl_s * l1[0] - fn_0 * n0[0] - fl_0 * l0[0]) * n0[0] +
                         (fn_s * n1[1] + fl_s * l1[1] - fn_0 * n0[1] - fl_0 * l0[1]) * n0[1];
      // The second-order remainder: the change of f_l times the turn (b s (|k| s + |w|)) and the turn's own
      // curvature on both forces ((|f_n| + |f_l|) (|k| s + |w|)^2 / 2), doubled.
      const double turn = std::abs(k) * s + std::abs(w);
      const double second = 2 * (std::abs(b) * s * turn + (std::abs(fn_0) + std::abs(fl_0)) * turn * turn);
      // The l row's share, as friction::Linearize takes it (its model G above): dF.l = df_l - f_n (kappa s + w).
      const double r_l = (fn_s * n1[0] + fl_s * l1[0] - fn_0 * n0[0] - fl_0 * l0[0]) * l0[0] +
                         (fn_s * n1[1] + fl_s * l1[1] - fn_0 * n0[1] - fl_0 * l0[1]) * l0[1];
      // (its remainder: the change of f_n times the turn, a s (|k| s + |w|), with the same curvature part)
      const double second_l = 2 * (std::abs(a) * s * turn + (std::abs(fn_0) + std::abs(fl_0)) * turn * turn);
      CHECK_NEAR(r_l, b * s - fn_0 * (k * s + w), second_l);
      if (w != 0) CHECK(std::abs(r_l - (b * s - fn_0 * k * s)) > 100 * std::abs(r_l - (b * s - fn_0 * (k * s + w))));
      const double dfn = friction::NormalIncrement(r_n, k, fl_0, s, w);
      CHECK_NEAR(dfn, a * s, second);
      CHECK(std::abs(r_n - a * s) > 100 * std::abs(dfn - a * s));
      // The tool's turn is not the slip's: leaving it out errs by f_l w.
      if (w != 0) CHECK(std::abs(friction::NormalIncrement(r_n, k, fl_0, s) - a * s) > 100 * std::abs(dfn - a * s));
    }
  // r6, slide to stick: from sliding (phi ~ 1) a reversal of 4 VCRI is cut where
  // phi has fallen by dphi_max; stick to slide and small falls are not limited.
  for (const double dphi : {0.5, 0.25, 1.0}) {
    const double xs = 2 * vcri, dx = -4 * vcri, r = friction::StickFactor(xs, dx, vcri, dphi);
    CHECK(r > 0 && r < 1);
    CHECK_NEAR(friction::Phi(xs, vcri) - friction::Phi(xs + r * dx, vcri), dphi, 1e-12);
    CHECK_NEAR(friction::StickFactor(-xs, -dx, vcri, dphi), r, 1e-15); // the mirror image
  }
  CHECK(friction::StickFactor(0.0, 4 * vcri, vcri, 0.5) > 1e299);      // stick to slide: no limit
  CHECK(friction::StickFactor(2 * vcri, 5 * vcri, vcri, 0.5) > 1e299); // sliding on: no limit
  CHECK(friction::StickFactor(2 * vcri, -0.1 * vcri, vcri, 0.5) > 1);  // a fall below dphi_max: no limit
  // Stick to slide (-rmin_dphi_rise): r lands where |phi| has risen by exactly dphi, either direction;
  // no limit for a smaller rise, a fall, a reversal (StickFactor's), or dphi >= 1.
  for (double dphi : {0.1, 0.25, 0.5}) {
    const double x0 = 0.1 * vcri, dx = 3 * vcri, r = friction::SlideFactor(x0, dx, vcri, dphi);
    CHECK(r > 0 && r < 1);
    CHECK_NEAR(friction::Phi(x0 + r * dx, vcri) - friction::Phi(x0, vcri), dphi, 1e-12);
    CHECK_NEAR(friction::SlideFactor(-x0, -dx, vcri, dphi), r, 1e-15); // the mirror image
  }
  CHECK(friction::SlideFactor(0.0, 4 * vcri, vcri, 1.0) > 1e299);         // dphi 1: no bound
  CHECK(friction::SlideFactor(0.0, 0.01 * vcri, vcri, 0.25) > 1e299);     // a small rise
  CHECK(friction::SlideFactor(2 * vcri, -0.5 * vcri, vcri, 0.1) > 1e299); // a fall
  CHECK(friction::SlideFactor(0.5 * vcri, -3 * vcri, vcri, 0.1) > 1e299); // a reversal
  // Limits of the law: sliding far (x >> VCRI) carries mu f_n; tiny slip is a spring of stiffness 3 mu f_n / VCRI.
  CHECK_NEAR(friction::Phi(1.0, vcri), 1.0, 2e-5); // capped at 2 VCRI: tanh(6)
  CHECK(friction::DPhi(1.0, vcri) == 0);           // no change past the cap
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
    plate.motion = StrokeMotion({0, -1});
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
  // The V-die closed by a parting face y = u_close through a convex edge fillet
  // (docs/dies.md). References from the construction: the chain apex arc ->
  // flank -> edge fillet -> face is continuous with one normal at every joint
  // (C1), a point at distance delta from any piece projects back onto it with
  // gap delta, and first contact on the face and on the fillet is found where
  // straight-line motion meets them.
  {
    const double ro = 17.5, ra = 3, uc = 2, re = 1.5, s2 = std::sqrt(2.0);
    const Tool die = BuildVDie(ro, ra, uc, re);
    CHECK(die.segments.size() == 4);
    const auto end_point = [](const Segment &s, bool first) -> Vec2 {
      if (s.kind == Segment::Line) return first ? s.a : s.b;
      const double t = first ? s.t0 : s.t1;
      return {s.c[0] + s.radius * std::cos(t), s.c[1] + s.radius * std::sin(t)};
    };
    // Joints: apex arc (t0 end) - flank a; flank b - fillet (t0 end); fillet (t1 end) - face a.
    const Vec2 joints[3][2] = {{end_point(die.segments[0], true), die.segments[1].a},
                               {die.segments[1].b, end_point(die.segments[2], true)},
                               {end_point(die.segments[2], false), die.segments[3].a}};
    for (const auto &j : joints) {
      CHECK_NEAR(j[0][0], j[1][0], 1e-12);
      CHECK_NEAR(j[0][1], j[1][1], 1e-12);
      const Projection pj = die.Project(j[0]);
      CHECK_NEAR(pj.gap, 0.0, 1e-12);
    }
    // The fillet's normals at its ends are the flank's and the face's.
    const Segment &edge = die.segments[2];
    CHECK_NEAR(std::cos(edge.t0), -1 / s2, 1e-12);
    CHECK_NEAR(std::sin(edge.t1), -1.0, 1e-12);
    // The flank meets the face line (corner before rounding) at x = ro sqrt2 - uc.
    CHECK_NEAR(die.segments[1].n_line[0] * (ro * s2 - uc) + die.segments[1].n_line[1] * uc, -ro, 1e-12);
    // Points at distance delta (body side) from every piece project back with gap delta.
    const double delta = 0.05;
    for (size_t k = 0; k < die.segments.size(); ++k) {
      const Segment &s = die.segments[k];
      for (double f : {0.1, 0.5, 0.9}) {
        Vec2 q, n;
        if (s.kind == Segment::Line) {
          q = {s.a[0] + f * (s.b[0] - s.a[0]), s.a[1] + f * (s.b[1] - s.a[1])};
          n = s.n_line;
        } else {
          const double t = s.t0 + f * (s.t1 - s.t0), sg = s.concave ? -1.0 : 1.0;
          n = {sg * std::cos(t), sg * std::sin(t)};
          q = {s.c[0] + s.radius * std::cos(t), s.c[1] + s.radius * std::sin(t)};
        }
        const Projection pq = die.Project({q[0] + delta * n[0], q[1] + delta * n[1]});
        CHECK(pq.segment == (int)k);
        CHECK_NEAR(pq.gap, delta, 1e-12);
        CHECK_NEAR(pq.n[0], n[0], 1e-12);
        CHECK_NEAR(pq.n[1], n[1], 1e-12);
      }
    }
    // First contact: a point below the face rising by 1 while the die comes
    // down by 1 meets the face y = uc - U when its height y0 + r = uc - r.
    const double xf = 0.5 * (die.segments[3].a[0] + die.segments[3].b[0]);
    CHECK_NEAR(die.FirstContact({xf, 0.5}, {0.0, 1.0}, 1.0), (uc - 0.5) / 2, 1e-12);
    // A point 0.5 left of the fillet's centre (static die) rising by 4 meets the
    // circle at y = c_y - sqrt(re^2 - 0.25).
    CHECK_NEAR(die.FirstContact({edge.c[0] - 0.5, 0.0}, {0.0, 4.0}, 0.0), (edge.c[1] - std::sqrt(re * re - 0.25)) / 4,
               1e-12);
  }
  return ReportChecks("test_friction");
}
