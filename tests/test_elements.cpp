// Element verification through the whole solver (mesh, assembly, MUMPS), one
// linear increment of each case:
//  - thin ring under two diametral loads, R/t = 20, 2 elements through the
//    wall: P/delta against the thin-ring value E' I / (0.1488 Rm^3);
//  - Cook's membrane (plane stress E = 1, nu = 1/3 as the equivalent plane
//    strain E* = 0.9375, nu* = 0.25, shear load 1; and nearly incompressible
//    plane strain E = 250, nu = 0.4999, load 100): the tip deflection at the
//    corner (48, 60) and at the middle of the right edge (48, 52) against the
//    converged values of an independent solver (tools/reference_cook.py:
//    quadratic and quartic elements on graded meshes, Richardson-extrapolated,
//    25.1894 / 23.9677 and 7.7713 / 7.4048, settled to 1e-4). The often-quoted
//    23.96-23.97 is the mid-edge value (FinEtools, Abaqus); at the corner it is
//    25.19.
// Each element (q4, bbar, qm6) is reported; the checks apply to qm6, the
// shear-locking-free element.
#include <petscsys.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <map>

#include "check.hpp"
#include "tubeform/core/core.hpp"
#include "tubeform/driver/problem.hpp"
#include "tubeform/mesh/generator.hpp"
#include "tubeform/scenes/scene.hpp"

using namespace tf;

namespace {

// Adds `total` (fx, fy) per unit lambda, spread over `nodes` with weights w.
struct NodalLoad {
  std::vector<std::pair<PetscInt, double>> nodes; // local node, weight (sum 1 over ranks)
  double fx = 0, fy = 0;
  PetscErrorCode Add(Model &m, double scale, Vec f, bool to_system) const
  {
    PetscScalar *a = nullptr;
    PetscFunctionBeginUser;
    if (f) PetscCall(VecGetArray(f, &a));
    for (const auto &nw : nodes) {
      if (!m.mesh.node_owned[nw.first]) continue; // each node's load once
      if (a) {
        a[m.mesh.node_dof[nw.first]] += scale * nw.second * fx;
        a[m.mesh.node_dof[nw.first] + 1] += scale * nw.second * fy;
      }
      if (to_system) m.system.AddForce(nw.first, scale * nw.second * fx, scale * nw.second * fy);
    }
    if (f) PetscCall(VecRestoreArray(f, &a));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
};

// Value of component k of the displacement at the node nearest (x, y), from its owner.
PetscErrorCode DisplacementAt(Problem &p, double x, double y, int k, double &u)
{
  double local = 0, best = kNever;
  PetscFunctionBeginUser;
  for (PetscInt n = 0; n < p.mesh().num_nodes; ++n) {
    const double d = std::hypot(p.mesh().x0[2 * n] - x, p.mesh().x0[2 * n + 1] - y);
    if (p.mesh().node_owned[n] && d < 1e-8 && d < best) best = d, local = p.body().displacement()[2 * n + k];
  }
  PetscCall(MPIU_Allreduce(&local, &u, 1, MPIU_REAL, MPIU_SUM, p.comm()));
  PetscFunctionReturn(PETSC_SUCCESS);
}

// A linear scene of nodal loads (Loads) and fixed components (Supports),
// ramped over one load step: what the ring and Cook's membrane share.
class NodalLoadScene : public Scene {
public:
  PetscErrorCode Load(Model &m, double, double dlambda) override
  {
    PetscFunctionBeginUser;
    PetscCall(Loads(m).Add(m, dlambda, nullptr, true));
    Supports(m);
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  PetscErrorCode ExternalForce(Model &m, double lambda, Vec f) override
  {
    PetscFunctionBeginUser;
    PetscCall(VecZeroEntries(f));
    PetscCall(Loads(m).Add(m, lambda, f, false));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  PetscErrorCode Measure(Model &, double, Vec, HistoryRow &) override { return 0; }
  LoadPath Path(const Options &opt) const override { return {1.0, opt.driver.dynamics_time, {}}; }

protected:
  virtual NodalLoad Loads(Model &m) const = 0;
  virtual void Supports(Model &m) const = 0;
};

// Quarter ring, diametral load P on the full ring: P/2 on the quarter, spread
// over the x = 0 section (trapezoidal weights, resultant on the mean radius).
class RingScene : public NodalLoadScene {
public:
  RingScene(double ro, double t, int ntheta, double p) : ro_(ro), t_(t), ntheta_(ntheta), p_(p) {}
  std::vector<std::string> BoundarySets() const override { return {"inner", "outer", "x0", "y0"}; }
  std::string BuildMesh(const Options &, SerialMesh &mesh) const override
  {
    mesh = GenerateQuarterAnnulus(ro_, t_, 2, ntheta_);
    return "";
  }

protected:
  void Supports(Model &m) const override
  {
    for (PetscInt n : m.mesh.node_sets["x0"]) m.system.Prescribe(n, 0, 0.0);
    for (PetscInt n : m.mesh.node_sets["y0"]) m.system.Prescribe(n, 1, 0.0);
  }
  NodalLoad Loads(Model &m) const override
  {
    NodalLoad l;
    l.fy = -0.5 * p_;
    for (PetscInt n : m.mesh.node_sets["x0"]) {
      const double r = m.mesh.x0[2 * n + 1];
      l.nodes.push_back({n, std::abs(r - (ro_ - 0.5 * t_)) < 1e-9 ? 0.5 : 0.25});
    }
    return l;
  }

private:
  double ro_, t_;
  int ntheta_;
  double p_;
};

// Cook's membrane: corners (0,0), (48,44), (48,60), (0,44); left edge clamped,
// vertical load F on the right edge (uniform traction: end nodes half weight).
class CookScene : public NodalLoadScene {
public:
  CookScene(int n, double f) : n_(n), f_(f) {}
  std::vector<std::string> BoundarySets() const override { return {"left", "right", "bottom", "top"}; }
  std::string BuildMesh(const Options &, SerialMesh &mesh) const override
  {
    mesh = GenerateRectangle(1.0, 1.0, n_, n_);
    for (int k = 0; k < mesh.num_nodes(); ++k) {
      const double xi = mesh.xy[2 * k], eta = mesh.xy[2 * k + 1];
      const double yb = 44 * xi, yt = 44 + 16 * xi;
      mesh.xy[2 * k] = 48 * xi;
      mesh.xy[2 * k + 1] = yb + eta * (yt - yb);
    }
    return "";
  }

protected:
  void Supports(Model &m) const override
  {
    for (PetscInt k : m.mesh.node_sets["left"]) m.system.Prescribe(k, 0, 0.0), m.system.Prescribe(k, 1, 0.0);
  }
  NodalLoad Loads(Model &m) const override
  {
    NodalLoad l;
    l.fy = f_;
    for (PetscInt k : m.mesh.node_sets["right"]) {
      const double y = m.mesh.x0[2 * k + 1];
      l.nodes.push_back({k, (std::abs(y - 44) < 1e-9 || std::abs(y - 60) < 1e-9) ? 0.5 / n_ : 1.0 / n_});
    }
    return l;
  }

private:
  int n_;
  double f_;
};

Options Base(fe::Formulation f, double e, double nu)
{
  Options opt;
  opt.element = f;
  opt.monitor = PETSC_FALSE;
  opt.material.law = FlowLaw::Elastic;
  opt.material.E = e;
  opt.material.nu = nu;
  opt.driver.increments = 1;
  opt.output = "test_elements.h5";
  return opt;
}

const char *Name(fe::Formulation f)
{
  return f == fe::Formulation::Q4 ? "q4" : f == fe::Formulation::BBar ? "bbar" : "qm6";
}

} // namespace

int main(int argc, char **argv)
{
  PetscCall(PetscInitialize(&argc, &argv, nullptr, nullptr));
  MPI_Comm comm = PETSC_COMM_WORLD;
  const fe::Formulation forms[] = {fe::Formulation::Q4, fe::Formulation::BBar, fe::Formulation::QM6};

  // Thin ring: Rm = 20 t, load small enough to stay linear (one increment).
  {
    const double t = 1.0, rm = 20.0, e = 75000, nu = 0.34, p = 1e-3;
    const double stiffness = e / (1 - nu * nu) * t * t * t / 12 / (0.1488 * rm * rm * rm);
    for (auto f : forms) {
      Problem prob;
      PetscCall(prob.Setup(comm, Base(f, e, nu), std::make_unique<RingScene>(rm + 0.5 * t, t, 96, p)));
      PetscCall(prob.Run());
      double v;
      PetscCall(DisplacementAt(prob, 0.0, rm, 1, v));
      const double ratio = p / (-2 * v) / stiffness;
      PetscCall(PetscPrintf(comm, "ring R/t = 20, 2 x 96 elements, %-4s: P/delta / (E'I/(0.1488 Rm^3)) = %.4f\n",
                            Name(f), ratio));
      if (f == fe::Formulation::QM6) CHECK(std::abs(ratio - 1) < 0.02);
    }
  }
  // Cook's membrane: the converged corner and mid-edge deflections of
  // tools/reference_cook.py. Bilinear elements converge slowly on uniform
  // meshes (the clamped corners are singular: order ~1.1), so the tolerances
  // are those of the discretization at 64 x 64. Plane stress: bounded by the
  // independent Q4 on the same mesh (0.58 % below the corner value, 0.18 %
  // below the mid-edge one), which bbar and qm6 must match or beat (0.6 %,
  // 0.3 %); and our q4 must equal that independent Q4 (same discretization:
  // 1e-4, the reference's printed digits). nu = 0.4999 (q4 locks): 1 % and
  // 0.5 %, as the mixed Q9/P3 on the same uniform meshes is itself still
  // 0.08 % and 0.03 % short at 64 x 64 and a bilinear element's error is
  // several times a quadratic one's. All must improve from 16 x 16 to 64 x 64.
  const std::map<int, std::array<double, 2>> q4_reference = {
    {8, {22.6726, 22.0792}}, {16, {24.2720, 23.4304}}, {64, {25.0433, 23.9245}}}; // reference_cook.py --full
  for (const double nu : {1.0 / 3.0, 0.4999}) {
    const bool stress = nu < 0.4;
    const double ref[2] = {stress ? 25.1894 : 7.7713, stress ? 23.9677 : 7.4048}; // corner, mid-edge
    std::map<int, std::array<std::array<double, 2>, 3>> tips;
    for (int n : {8, 16, 64}) {
      for (int k = 0; k < 3; ++k) {
        Problem prob;
        // Plane stress (E, nu) = plane strain (E (1 + 2 nu) / (1 + nu)^2, nu / (1 + nu)).
        const double es = stress ? (1 + 2 * nu) / ((1 + nu) * (1 + nu)) : 250.0, nus = stress ? nu / (1 + nu) : nu;
        // A load 1e-6 of the benchmark's keeps the increment linear (no r_min cut,
        // strains ~1e-7); the deflection is scaled back.
        const double load = stress ? 1.0 : 100.0, scale = 1e-6;
        PetscCall(prob.Setup(comm, Base(forms[k], es, nus), std::make_unique<CookScene>(n, scale * load)));
        PetscCall(prob.Run());
        for (int at = 0; at < 2; ++at) {
          PetscCall(DisplacementAt(prob, 48, at == 0 ? 60 : 52, 1, tips[n][k][at]));
          tips[n][k][at] /= scale;
        }
      }
      PetscCall(PetscPrintf(comm,
                            "Cook %s, %2d x %-2d: corner q4 %.3f  bbar %.3f  qm6 %.3f (ref %.4f); mid-edge q4 %.3f  "
                            "bbar %.3f  qm6 %.3f (ref %.4f)\n",
                            stress ? "plane stress nu=1/3" : "plane strain nu=0.4999", n, n, tips[n][0][0],
                            tips[n][1][0], tips[n][2][0], ref[0], tips[n][0][1], tips[n][1][1], tips[n][2][1], ref[1]));
    }
    const double tol[2] = {stress ? 6e-3 : 1e-2, stress ? 3e-3 : 5e-3};
    for (int k = 1; k < 3; ++k) // bbar, qm6 (q4 locks volumetrically at nu = 0.4999)
      for (int at = 0; at < 2; ++at) {
        const double err64 = std::abs(tips[64][k][at] / ref[at] - 1), err16 = std::abs(tips[16][k][at] / ref[at] - 1);
        CHECK(err64 < tol[at]);
        CHECK(err64 < err16);
      }
    if (stress)
      for (const auto &[n, v] : q4_reference)
        for (int at = 0; at < 2; ++at) CHECK_NEAR(tips[n][0][at] / v[at], 1.0, 1e-4);
    CHECK(tips[8][0][0] < tips[8][2][0]); // shear locking makes q4 the stiffest
  }
  PetscMPIInt rank;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  const int rc = rank == 0 ? ReportChecks("test_elements") : 0;
  PetscCall(PetscFinalize());
  return rc;
}
