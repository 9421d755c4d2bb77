// Unit tests of the J2 material point and the hardening laws (no MPI):
//  - the plastic step solves 3G dep + sy(ep+dep) - sy(ep) = 3G a/sbar, so on
//    a proportional, isochoric path (de = (d, -d, 0, 0)) the tangent update
//    must land exactly on the flow curve: sbar = sy(ep) with
//    ep = (2/sqrt 3) eps - sy(ep)/(3G) solved independently by bisection
//    (the exact integral of the law along the path), for Ludwik (n = 0.927,
//    n = 1, n = 0.1), Swift, a table and perfect plasticity;
//  - r1 puts an elastic point exactly on the yield surface;
//  - loading/unloading switches; the elastic tangent of an elastic point.
#include <cmath>
#include <memory>

#include "check.hpp"
#include "tubeform/material/j2.hpp"
#include "tubeform/step/rmin.hpp"

using namespace tf;

namespace {
const double kE = 75000, kNu = 0.34, kG = kE / (2 * (1 + kNu));

// Exact ep on the path for total strain eps (equivalent strain (2/sqrt3) eps).
double ExactEp(const Hardening &h, double eps)
{
  const double eq = 2 / std::sqrt(3.0) * eps;
  if (eq <= h.YieldStress(0) / (3 * kG)) return 0;
  double lo = 0, hi = eq;
  for (int it = 0; it < 200; ++it) {
    const double mid = 0.5 * (lo + hi);
    (mid + h.YieldStress(mid) / (3 * kG) < eq ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

void ProportionalPath(const char *name, std::unique_ptr<Hardening> law, std::unique_ptr<Hardening> ref)
{
  J2Plasticity m(kE, kNu, std::move(law), 2e-3, false);
  PointState s;
  const double d = 2e-4; // strain step; yield near eps = 1e-3
  double eps = 0, worst_ep = 0, worst_s = 0, drift = 0;
  for (int k = 0; k < 500; ++k) {
    Voigt de = {d, -d, 0, 0};
    // Elastic points are brought to the surface by r1 first, as the driver does.
    double r = m.YieldOnset(s, de, 0.0);
    if (!s.plastic && r < 1) {
      Voigt part = {r * d, -r * d, 0, 0};
      m.Update(s, part);
      s.plastic = true;
      CHECK_NEAR(VonMises(s.sigma), ref->YieldStress(0), 1e-9 * ref->YieldStress(0));
      de = {(1 - r) * d, -(1 - r) * d, 0, 0};
    }
    const UpdateInfo u = m.Update(s, de);
    drift = std::max(drift, std::abs(u.drift));
    eps += d;
    const double ep = ExactEp(*ref, eps);
    worst_ep = std::max(worst_ep, std::abs(s.ep - ep) / std::max(ep, 1e-3));
    worst_s = std::max(worst_s, std::abs(VonMises(s.sigma) - ref->YieldStress(s.ep)) / ref->YieldStress(s.ep) *
                                  (s.plastic ? 1 : 0));
  }
  std::printf("%-22s eps = 0.1: ep = %.6f (exact %.6f), max rel. error ep %.1e, sbar vs sy(ep) %.1e, drift %.1e\n",
              name, s.ep, ExactEp(*ref, eps), worst_ep, worst_s, drift);
  // Round-off level: the update is exact on this path.
  CHECK(worst_ep < 1e-9);
  CHECK(worst_s < 1e-9);
}
} // namespace

int main()
{
  ProportionalPath("ludwik aluminum", std::make_unique<LudwikHardening>(165.3, 673.5, 0.927),
                   std::make_unique<LudwikHardening>(165.3, 673.5, 0.927));
  ProportionalPath("ludwik n = 1", std::make_unique<LudwikHardening>(165.3, 673.5, 1.0),
                   std::make_unique<LudwikHardening>(165.3, 673.5, 1.0));
  ProportionalPath("ludwik n = 0.1", std::make_unique<LudwikHardening>(165.3, 673.5, 0.1),
                   std::make_unique<LudwikHardening>(165.3, 673.5, 0.1));
  ProportionalPath("perfectly plastic", std::make_unique<LudwikHardening>(165.3, 0.0, 1.0),
                   std::make_unique<LudwikHardening>(165.3, 0.0, 1.0));
  ProportionalPath("swift", std::make_unique<SwiftHardening>(165.3, 500.0, 0.2),
                   std::make_unique<SwiftHardening>(165.3, 500.0, 0.2));
  ProportionalPath(
    "table", std::make_unique<TableHardening>(std::vector<double>{0, 0.01, 0.05}, std::vector<double>{165, 200, 240}),
    std::make_unique<TableHardening>(std::vector<double>{0, 0.01, 0.05}, std::vector<double>{165, 200, 240}));

  // Swift starts at sy0; the table interpolates and stays flat past its end.
  CHECK_NEAR(SwiftHardening(165.3, 500.0, 0.2).YieldStress(0), 165.3, 1e-9);
  const TableHardening t({0, 0.01, 0.05}, {165, 200, 240});
  CHECK_NEAR(t.YieldStress(0.005), 182.5, 1e-12);
  CHECK_NEAR(t.YieldStress(1.0), 240, 1e-12);
  // The secant slope is finite where H' is not (Ludwik n < 1 at ep = 0).
  const LudwikHardening l(165.3, 673.5, 0.1);
  CHECK(std::isfinite(l.SecantSlope(0, 2e-3)) && l.SecantSlope(0, 2e-3) > 0);

  // r1 on a general (non-proportional) elastic increment with spin: exact.
  {
    J2Plasticity m(kE, kNu, std::make_unique<LudwikHardening>(165.3, 673.5, 0.927), 2e-3, false);
    PointState s;
    s.sigma = {40, -20, 10, 30};
    const Voigt de = {3e-3, 1e-3, 0, 2e-3};
    const double omega = 0.05, r = m.YieldOnset(s, de, omega);
    CHECK(r > 0 && r < 1);
    // The linear path of the increment: dsigma = D de + (W sigma - sigma W) - sigma tr(de).
    const Mat4 d = IsotropicElasticMatrix(kE, kNu);
    Voigt ds{}, spun = s.sigma, at = s.sigma;
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) ds[i] += d[i][j] * de[j];
    JaumannUpdate({0, 0, 0, 0}, 0.0, omega, spun);
    for (int i = 0; i < 4; ++i) at[i] += r * (ds[i] + spun[i] - s.sigma[i] - s.sigma[i] * (de[0] + de[1] + de[2]));
    CHECK_NEAR(VonMises(at), 165.3, 1e-10 * 165.3);
  }
  // Loading/unloading: a plastic point that unloads turns elastic.
  {
    J2Plasticity m(kE, kNu, std::make_unique<LudwikHardening>(165.3, 673.5, 0.927), 2e-3, false);
    PointState s;
    s.sigma = {165.3 / std::sqrt(3.0), -165.3 / std::sqrt(3.0), 0, 0};
    s.plastic = true;
    CHECK(m.Loading(s, {1e-4, -1e-4, 0, 0}));
    CHECK(!m.Loading(s, {-1e-4, 1e-4, 0, 0}));
    s.plastic = false; // on the surface but flagged elastic: loading turns it plastic
    CHECK(m.Loading(s, {1e-4, -1e-4, 0, 0}));
    PointState inside;
    inside.sigma = {10, 0, 0, 0};
    CHECK(!m.Loading(inside, {1e-4, -1e-4, 0, 0}));
  }
  // r2 and r3.
  CHECK_NEAR(MaxPrincipalStrain({1e-3, -1e-3, 0, 0}), 1e-3, 1e-18);
  CHECK_NEAR(MaxPrincipalStrain({0, 0, 0, 2e-3}), 1e-3, 1e-18); // pure shear gamma: principal gamma/2
  CHECK_NEAR(StrainFactor({0, 0, 0, 4e-3}, 1e-3), 0.5, 1e-15);
  CHECK_NEAR(RotationFactor(-0.02, 0.01), 0.5, 1e-15);
  return ReportChecks("test_material");
}
