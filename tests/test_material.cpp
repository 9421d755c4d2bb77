// Unit tests of the J2 material point and the hardening laws (no MPI), against
// references written out here, not taken from the classes under test:
//  - the flow curves by their formulas: Ludwik sy0 + K ep^n, Swift K (ep0 + ep)^n
//    with ep0 = (sy0/K)^(1/n), the table's straight pieces;
//  - plane-strain elasticity in closed form: uniaxial strain gives
//    (lambda + 2G, lambda, lambda) eps, uniaxial stress (sigma_yy = 0,
//    eps_yy = -nu/(1 - nu) eps) gives E' = E/(1 - nu^2) and sigma_zz = nu sigma_xx,
//    shear G gamma;
//  - the plastic step solves 3G dep + sy(ep+dep) - sy(ep) = 3G a/sbar, so on a
//    proportional, isochoric path (de = (d, -d, 0, 0)) the tangent update must
//    land exactly on the flow curve: ep from ep + sy(ep)/(3G) = (2/sqrt 3) eps
//    (bisection here), and sigma_xx = -sigma_yy = 2G (eps - (sqrt 3/2) ep),
//    sigma_zz = sigma_xy = 0 (the exact integral of the law along the path), for
//    Ludwik (n = 0.927, 1, 0.1), Swift, a table and perfect plasticity;
//  - linear hardening (H' = K): the elastic-plastic tangent on that path is
//    2G H'/(3G + H') (paper eq. 1 worked by hand for s = (s, -s, 0, 0));
//  - the radial return (-plastic_update radial) on the same proportional paths
//    (the same closed forms: there the trial's deviator is the start's
//    direction), and after large non-proportional steps on the yield surface
//    exactly (sbar = sy(ep) to round-off, where the tangent update drifts), its
//    loading state what its update does, a round-off strain on the surface elastic;
//    its algorithmic tangent the derivative of its stress by central differences;
//  - r1 puts an elastic point exactly on the yield surface;
//  - loading/unloading switches; r2 and r3.
#include <cmath>
#include <functional>
#include <memory>

#include "check.hpp"
#include "tubeform/material/factory.hpp"
#include "tubeform/material/j2.hpp"
#include "tubeform/step/rmin.hpp"

using namespace tf;

namespace {
const double kE = 75000, kNu = 0.34, kG = kE / (2 * (1 + kNu));
const double kLambda = kE * kNu / ((1 + kNu) * (1 - 2 * kNu));
// Relative tolerance of every comparison below: the updates are exact on these
// paths and the references closed forms, so only round-off separates them
// (measured at most 6e-14, on any OpenBLAS kernel: no BLAS is involved).
const double kRoundOff = 1e-12;
using FlowCurve = std::function<double(double)>;

// The flow curves, written out (the reference; the classes are under test).
FlowCurve Ludwik(double sy0, double k, double n)
{
  return [=](double ep) { return sy0 + k * std::pow(ep, n); };
}
FlowCurve Swift(double sy0, double k, double n)
{
  const double ep0 = std::pow(sy0 / k, 1 / n);
  return [=](double ep) { return k * std::pow(ep0 + ep, n); };
}
// Through (0, 165), (0.01, 200), (0.05, 240), flat beyond.
double Table(double ep)
{
  if (ep < 0.01) return 165 + 3500 * ep;
  if (ep < 0.05) return 200 + 1000 * (ep - 0.01);
  return 240;
}

// Exact ep on the path for total strain eps (equivalent strain (2/sqrt3) eps).
double ExactEp(const FlowCurve &sy, double eps)
{
  const double eq = 2 / std::sqrt(3.0) * eps;
  if (eq <= sy(0) / (3 * kG)) return 0;
  double lo = 0, hi = eq;
  for (int it = 0; it < 200; ++it) {
    const double mid = 0.5 * (lo + hi);
    (mid + sy(mid) / (3 * kG) < eq ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

void ProportionalPath(const char *name, std::unique_ptr<Hardening> law, const FlowCurve &sy,
                      PlasticUpdate update = PlasticUpdate::Tangent)
{
  J2Plasticity m(kE, kNu, std::move(law), 2e-3, false, update);
  PointState s;
  const double d = 2e-4; // strain step; yield near eps = 1e-3
  double eps = 0, worst_ep = 0, worst_s = 0, worst_sigma = 0, drift = 0;
  for (int k = 0; k < 500; ++k) {
    Voigt de = {d, -d, 0, 0};
    // Elastic points are brought to the surface by r1 first, as the driver does.
    double r = m.YieldOnset(s, de, 0.0);
    if (!s.plastic && r < 1) {
      Voigt part = {r * d, -r * d, 0, 0};
      m.Update(s, part);
      s.plastic = true;
      CHECK_NEAR(VonMises(s.sigma), sy(0), kRoundOff * sy(0));
      de = {(1 - r) * d, -(1 - r) * d, 0, 0};
    }
    const UpdateInfo u = m.Update(s, de);
    drift = std::max(drift, std::abs(u.drift));
    eps += d;
    const double ep = ExactEp(sy, eps), sxx = 2 * kG * (eps - std::sqrt(3.0) / 2 * ep);
    worst_ep = std::max(worst_ep, std::abs(s.ep - ep) / std::max(ep, 1e-3));
    worst_s = std::max(worst_s, std::abs(VonMises(s.sigma) - sy(s.ep)) / sy(s.ep) * (s.plastic ? 1 : 0));
    const double dev =
      std::max({std::abs(s.sigma[0] - sxx), std::abs(s.sigma[1] + sxx), std::abs(s.sigma[2]), std::abs(s.sigma[3])});
    worst_sigma = std::max(worst_sigma, dev / sy(0));
  }
  std::printf("%-22s %-7s eps = 0.1: ep = %.6f (exact %.6f), max rel. error ep %.1e, sbar vs sy(ep) %.1e, stress %.1e, "
              "drift %.1e\n",
              name, kPlasticUpdateWords[(int)update], s.ep, ExactEp(sy, eps), worst_ep, worst_s, worst_sigma, drift);
  CHECK(worst_ep < kRoundOff);
  CHECK(worst_s < kRoundOff);
  CHECK(worst_sigma < kRoundOff);
}

// The radial return after large non-proportional steps from a plastic point:
// sbar = sy(ep) to round-off (the tangent update drifts by a few per cent), the
// pressure that of the elastic trial, and Loading says whether Update flows.
void RadialNonProportional()
{
  const FlowCurve sy = Ludwik(165.3, 673.5, 0.927);
  double worst = 0, tangent_drift = 0;
  int disagree = 0;
  for (int k = 0; k < 24; ++k) {
    PointState s[2];
    const J2Plasticity m[2] = {
      {kE, kNu, std::make_unique<LudwikHardening>(165.3, 673.5, 0.927), 2e-3, false},
      {kE, kNu, std::make_unique<LudwikHardening>(165.3, 673.5, 0.927), 2e-3, false, PlasticUpdate::Radial}};
    // On the surface in plane-strain tension (ep 0.01), then a step of 2.5 yield strains at angle k * 15 degrees in
    // the (xx - yy, gamma_xy) plane with some volume change.
    const double sx = sy(0.01) / std::sqrt(3.0), c = std::cos(k * M_PI / 12), sn = std::sin(k * M_PI / 12);
    const Voigt de = {3e-3 * c + 1e-4, -3e-3 * c + 2e-4, 0, 6e-3 * sn};
    for (int u = 0; u < 2; ++u) {
      s[u].sigma = {sx + 20, -sx + 20, 20, 0};
      s[u].ep = 0.01;
      s[u].plastic = true;
    }
    const bool loads = m[1].Loading(s[1], de);
    const Voigt before = s[1].sigma;
    const UpdateInfo ut = m[0].Update(s[0], de), ur = m[1].Update(s[1], de);
    tangent_drift = std::max(tangent_drift, std::abs(ut.drift));
    disagree += loads != (s[1].ep > 0.01);
    if (s[1].ep > 0.01) {
      worst = std::max(worst, std::abs(VonMises(s[1].sigma) / sy(s[1].ep) - 1));
      CHECK(std::abs(ur.drift) < kRoundOff);
      // The pressure is the trial's: p + K tr(de) - p tr(de) (C_e's volumetric part).
      const double tr = de[0] + de[1] + de[2], p0 = (before[0] + before[1] + before[2]) / 3;
      const double p = (s[1].sigma[0] + s[1].sigma[1] + s[1].sigma[2]) / 3;
      CHECK_NEAR(p, p0 + (kLambda + 2 * kG / 3) * tr - p0 * tr, kRoundOff * 165.3);
    }
  }
  std::printf("non-proportional steps of 2.5 yield strains: radial |sbar/sy - 1| %.1e, tangent drift %.1e\n", worst,
              tangent_drift);
  CHECK(worst < kRoundOff);
  CHECK(tangent_drift > 1e-3); // (the case is one the tangent update gets wrong)
  CHECK(disagree == 0);
  // An unloading step stays elastic, and Loading says so.
  {
    const J2Plasticity m(kE, kNu, std::make_unique<LudwikHardening>(165.3, 673.5, 0.927), 2e-3, false,
                         PlasticUpdate::Radial);
    PointState s;
    s.sigma = {165.3 / std::sqrt(3.0), -165.3 / std::sqrt(3.0), 0, 0};
    s.plastic = true;
    CHECK(!m.Loading(s, {-1e-4, 1e-4, 0, 0}));
    CHECK(m.Loading(s, {1e-4, -1e-4, 0, 0}));
    m.Update(s, {-1e-4, 1e-4, 0, 0});
    CHECK(!s.plastic && s.ep == 0);
  }
  // A point on the surface given a strain of round-off's size (what another rank's summation order adds to a
  // neutral step: its trial 6e-13 sigma_y past the surface) stays elastic, Loading agreeing; one of 1e-9 (6e-7 past
  // it) flows (kFlowTie, 1e-8, between them).
  for (const double d : {1e-15, 1e-9}) {
    const J2Plasticity m(kE, kNu, std::make_unique<LudwikHardening>(165.3, 673.5, 0.927), 2e-3, false,
                         PlasticUpdate::Radial);
    PointState s;
    s.sigma = {165.3 / std::sqrt(3.0), -165.3 / std::sqrt(3.0), 0, 0};
    s.plastic = true;
    const bool loads = m.Loading(s, {d, -d, 0, 0}), flows = d > 1e-12;
    m.Update(s, {d, -d, 0, 0});
    CHECK(loads == flows && (s.ep > 0) == flows && s.plastic == flows);
  }
}

// The radial return's algorithmic tangent (StepTangent) against the central difference of its own stress update, on
// the non-proportional steps above, in the three isochoric directions (the Kirchhoff term sigma tr(de) does not move
// along them). Step 1e-7 of the 3e-3 steps: truncation (h / de)^2 ~ 1e-9 and round-off 1e-16 sigma / h ~ 1e-7 MPa
// against 2G |dir| = 56,000 MPa per unit strain, so 1e-6 of 2G leaves four orders either way; a tangent missing the
// return's shrink of the deviator (1 - f up to 0.6 here) is off by tenths of 2G.
void RadialStepTangent()
{
  const FlowCurve sy = Ludwik(165.3, 673.5, 0.927);
  const J2Plasticity m(kE, kNu, std::make_unique<LudwikHardening>(165.3, 673.5, 0.927), 2e-3, false,
                       PlasticUpdate::Radial);
  const Voigt dirs[3] = {{1, -1, 0, 0}, {1, 0, -1, 0}, {0, 0, 0, 2}};
  const double h = 1e-7;
  double worst = 0;
  int flowed = 0;
  for (int k = 0; k < 24; ++k) {
    const double sx = sy(0.01) / std::sqrt(3.0), c = std::cos(k * M_PI / 12), sn = std::sin(k * M_PI / 12);
    const Voigt de = {3e-3 * c + 1e-4, -3e-3 * c + 2e-4, 0, 6e-3 * sn};
    PointState s0;
    s0.sigma = {sx + 20, -sx + 20, 20, 0};
    s0.ep = 0.01;
    s0.plastic = true;
    if (!m.Loading(s0, de)) continue;
    ++flowed;
    const Mat4 t = m.StepTangent(s0, de);
    for (const Voigt &d : dirs) {
      PointState up = s0, down = s0;
      Voigt dp, dm;
      for (int r = 0; r < 4; ++r) dp[r] = de[r] + h * d[r], dm[r] = de[r] - h * d[r];
      m.Update(up, dp);
      m.Update(down, dm);
      for (int r = 0; r < 4; ++r) {
        double td = 0;
        for (int q = 0; q < 4; ++q) td += t[r][q] * d[q];
        worst = std::max(worst, std::abs(td - (up.sigma[r] - down.sigma[r]) / (2 * h)) / (2 * kG));
      }
    }
  }
  std::printf("radial return's algorithmic tangent on %d flowing steps: largest miss %.1e of 2G\n", flowed, worst);
  CHECK(flowed >= 12);
  CHECK(worst < 1e-6);
}

// Plane-strain elasticity from zero stress (the Kirchhoff term sigma tr(de) vanishes).
void ElasticClosedForm()
{
  const Elastic m(kE, kNu);
  const double d = 1e-4, tol = kRoundOff * kE * d;
  PointState s;
  m.Update(s, {d, 0, 0, 0}); // uniaxial strain
  CHECK_NEAR(s.sigma[0], (kLambda + 2 * kG) * d, tol);
  CHECK_NEAR(s.sigma[1], kLambda * d, tol);
  CHECK_NEAR(s.sigma[2], kLambda * d, tol);
  CHECK_NEAR(s.sigma[3], 0, tol);
  s = PointState();
  m.Update(s, {d, -kNu / (1 - kNu) * d, 0, 0}); // uniaxial stress in plane strain
  CHECK_NEAR(s.sigma[0], kE / (1 - kNu * kNu) * d, tol);
  CHECK_NEAR(s.sigma[1], 0, tol);
  CHECK_NEAR(s.sigma[2], kNu * s.sigma[0], tol);
  s = PointState();
  m.Update(s, {0, 0, 0, d}); // engineering shear strain gamma
  CHECK_NEAR(s.sigma[3], kG * d, tol);
  CHECK_NEAR(s.sigma[0], 0, tol);
  // Energy density sigma : eps / 2 of that shear.
  CHECK_NEAR(m.ElasticEnergy(s.sigma), 0.5 * kG * d * d, kRoundOff * kG * d * d);
}

// Linear hardening: after a plastic step on the isochoric path, the tangent's
// xx response to de = (d, -d, 0, 0) is 2G H'/(3G + H') d (H' = K exactly).
void LinearHardeningTangent()
{
  const double sy0 = 165.3, k = 673.5, d = 1e-4;
  J2Plasticity m(kE, kNu, std::make_unique<LudwikHardening>(sy0, k, 1.0), 2e-3, false);
  PointState s;
  s.sigma = {sy0 / std::sqrt(3.0), -sy0 / std::sqrt(3.0), 0, 0};
  s.plastic = true;
  m.Update(s, {d, -d, 0, 0});
  const Mat4 c = m.Tangent(s);
  const double dsxx = c[0][0] * d - c[0][1] * d, expect = 2 * kG * k / (3 * kG + k) * d;
  CHECK_NEAR(dsxx, expect, kRoundOff * std::abs(expect));
  CHECK_NEAR(c[2][0] * d - c[2][1] * d, 0, kRoundOff * std::abs(expect)); // sigma_zz: s_zz = 0 on this path
}
// -plastic_update auto (UpdateFor): the isotropic J2 law's radial return where the increments are in equilibrium,
// on the surface to round-off after a non-proportional step of 2.5 yield strains where the tangent update leaves it
// by more than 1e-3 (the first case of RadialNonProportional); the tangent update for the paper's forward increments
// and for the laws that have no return; a named update as named.
void AutoUpdate()
{
  CHECK(UpdateFor(PlasticUpdate::Auto, LawKind::IsotropicJ2, true) == PlasticUpdate::Radial);
  CHECK(UpdateFor(PlasticUpdate::Auto, LawKind::IsotropicJ2, false) == PlasticUpdate::Tangent);
  for (const LawKind law : {LawKind::Elastic, LawKind::KinematicJ2, LawKind::Hill})
    CHECK(UpdateFor(PlasticUpdate::Auto, law, true) == PlasticUpdate::Tangent);
  for (const PlasticUpdate named : {PlasticUpdate::Tangent, PlasticUpdate::Radial})
    CHECK(UpdateFor(named, LawKind::IsotropicJ2, false) == named);
  MaterialParams aluminum;
  const double sx = 165.3 / std::sqrt(3.0);
  double drift[2] = {0, 0};
  const bool equilibrium[2] = {true, false};
  for (int u = 0; u < 2; ++u) {
    const std::unique_ptr<Material> m =
      MakeMaterial(aluminum, 2e-3, false, UpdateFor(PlasticUpdate::Auto, LawOf(aluminum), equilibrium[u]));
    PointState s;
    s.sigma = {sx + 20, -sx + 20, 20, 0};
    s.plastic = true;
    (void)m->Update(s, {3e-3 + 1e-4, -3e-3 + 2e-4, 0, 0});
    (void)m->Update(s, {1e-4, 2e-4, 0, 6e-3}); // (the turn: shear at 90 degrees to the first step)
    drift[u] = std::abs(VonMises(s.sigma) / Ludwik(165.3, 673.5, 0.927)(s.ep) - 1);
  }
  std::printf("auto: |sbar/sy - 1| %.1e after a turn with equilibrium increments (forward: %.1e)\n", drift[0],
              drift[1]);
  CHECK(drift[0] < kRoundOff && drift[1] > 1e-3);
}

} // namespace

int main()
{
  ProportionalPath("ludwik aluminum", std::make_unique<LudwikHardening>(165.3, 673.5, 0.927),
                   Ludwik(165.3, 673.5, 0.927));
  ProportionalPath("ludwik n = 1", std::make_unique<LudwikHardening>(165.3, 673.5, 1.0), Ludwik(165.3, 673.5, 1.0));
  ProportionalPath("ludwik n = 0.1", std::make_unique<LudwikHardening>(165.3, 673.5, 0.1), Ludwik(165.3, 673.5, 0.1));
  ProportionalPath("perfectly plastic", std::make_unique<LudwikHardening>(165.3, 0.0, 1.0),
                   [](double) { return 165.3; });
  ProportionalPath("swift", std::make_unique<SwiftHardening>(165.3, 500.0, 0.2), Swift(165.3, 500.0, 0.2));
  ProportionalPath(
    "table", std::make_unique<TableHardening>(std::vector<double>{0, 0.01, 0.05}, std::vector<double>{165, 200, 240}),
    Table);
  ProportionalPath("ludwik aluminum", std::make_unique<LudwikHardening>(165.3, 673.5, 0.927),
                   Ludwik(165.3, 673.5, 0.927), PlasticUpdate::Radial);
  ProportionalPath("ludwik n = 0.1", std::make_unique<LudwikHardening>(165.3, 673.5, 0.1), Ludwik(165.3, 673.5, 0.1),
                   PlasticUpdate::Radial);
  ProportionalPath(
    "perfectly plastic", std::make_unique<LudwikHardening>(165.3, 0.0, 1.0), [](double) { return 165.3; },
    PlasticUpdate::Radial);
  ProportionalPath(
    "table", std::make_unique<TableHardening>(std::vector<double>{0, 0.01, 0.05}, std::vector<double>{165, 200, 240}),
    Table, PlasticUpdate::Radial);
  RadialNonProportional();
  RadialStepTangent();
  AutoUpdate();
  ElasticClosedForm();
  LinearHardeningTangent();

  // The laws against their formulas at a few points (Swift starts at sy0; the
  // table interpolates and stays flat past its end).
  for (const double ep : {0.0, 1e-4, 0.003, 0.02, 0.3}) {
    CHECK_NEAR(LudwikHardening(165.3, 673.5, 0.927).YieldStress(ep), Ludwik(165.3, 673.5, 0.927)(ep),
               kRoundOff * 165.3);
    CHECK_NEAR(SwiftHardening(165.3, 500.0, 0.2).YieldStress(ep), Swift(165.3, 500.0, 0.2)(ep), kRoundOff * 165.3);
    CHECK_NEAR(TableHardening({0, 0.01, 0.05}, {165, 200, 240}).YieldStress(ep), Table(ep), kRoundOff * 165);
  }
  {
    // The flow stress memo (FlowMemo): one law asked for more strains than it
    // has slots, each several times in a scattered order, answers each exactly
    // as the formula does (a slot taken by another strain must not answer).
    const LudwikHardening l(165.3, 673.5, 0.927);
    const SwiftHardening s(165.3, 500.0, 0.2);
    std::vector<double> eps;
    for (int i = 1; i <= 20000; ++i) eps.push_back(1e-6 * i * (1 + 1e-3 * (i % 7)));
    int wrong = 0;
    for (int pass = 0; pass < 3; ++pass)
      for (size_t k = 0; k < eps.size(); ++k) {
        const double ep = eps[(k * 7919 + pass * 104729) % eps.size()];
        wrong += l.YieldStress(ep) != 165.3 + 673.5 * std::pow(ep, 0.927);
        wrong += s.YieldStress(ep) != Swift(165.3, 500.0, 0.2)(ep);
      }
    CHECK(wrong == 0);
  }
  CHECK_NEAR(SwiftHardening(165.3, 500.0, 0.2).YieldStress(0), 165.3, kRoundOff * 165.3);
  const TableHardening t({0, 0.01, 0.05}, {165, 200, 240});
  CHECK_NEAR(t.YieldStress(0.005), 182.5, kRoundOff * 182.5);
  CHECK_NEAR(t.YieldStress(1.0), 240, kRoundOff * 240);
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
    // The linear path of the increment: dsigma = D de + (W sigma - sigma W) - sigma tr(de),
    // D written out (plane strain: lambda + 2G on the diagonal, lambda off it, G for gamma).
    const double dm[4][4] = {{kLambda + 2 * kG, kLambda, kLambda, 0},
                             {kLambda, kLambda + 2 * kG, kLambda, 0},
                             {kLambda, kLambda, kLambda + 2 * kG, 0},
                             {0, 0, 0, kG}};
    // Spin (W = [[0, w], [-w, 0]]): W sigma - sigma W = (2 w sxy, -2 w sxy, 0, w (syy - sxx)).
    const Voigt spin = {2 * omega * s.sigma[3], -2 * omega * s.sigma[3], 0, omega * (s.sigma[1] - s.sigma[0])};
    Voigt at = s.sigma;
    for (int i = 0; i < 4; ++i) {
      double ds = 0;
      for (int j = 0; j < 4; ++j) ds += dm[i][j] * de[j];
      at[i] += r * (ds + spin[i] - s.sigma[i] * (de[0] + de[1] + de[2]));
    }
    CHECK_NEAR(VonMises(at), 165.3, kRoundOff * 165.3);
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
