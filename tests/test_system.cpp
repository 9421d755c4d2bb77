// Verification of the distributed system on 1 or more ranks:
//  - patch test: a distorted mesh under a prescribed linear displacement on
//    its boundary reproduces the linear field at interior nodes and a
//    constant stress, to round-off (Q4 and B-bar);
//  - rotated frames: a block whose edges are inclined by alpha, supported by
//    rollers written in rotated node frames and stretched by a prescribed
//    rotated-frame displacement, gives the exact uniaxial plane-strain field
//    and the exact reaction;
//  - a boundary segment that is no cell edge is refused by every rank alike.
#include <petscsys.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "check.hpp"
#include "tubeform/assembly/system.hpp"
#include "tubeform/core/core.hpp"
#include "tubeform/core/log.hpp"
#include "tubeform/material/elastic.hpp"
#include "tubeform/mesh/generator.hpp"
#include "tubeform/mesh/mesh.hpp"

using namespace tf;

static const double kE = 1000.0, kNu = 0.3;

// Elastic stiffness of every local cell into `sys`.
static PetscErrorCode AssembleElastic(const Mesh &mesh, System &sys, fe::Formulation f)
{
  PetscFunctionBeginUser;
  Mat4 c[4];
  Voigt s[4] = {};
  for (auto &m : c) m = IsotropicElasticMatrix(kE, kNu);
  PetscCall(sys.Begin());
  for (PetscInt e = 0; e < mesh.num_cells; ++e) {
    double xe[8];
    fe::QuadGeometry geo;
    fe::ElemMat ke;
    for (int a = 0; a < 4; ++a) {
      const PetscInt n = mesh.cell_nodes[4 * e + a];
      xe[2 * a] = mesh.x0[2 * n], xe[2 * a + 1] = mesh.x0[2 * n + 1];
    }
    PetscCheck(fe::ComputeGeometry(xe, geo), PETSC_COMM_SELF, PETSC_ERR_PLIB, "inverted test cell");
    fe::ElementStiffness(geo, f, c, s, false, ke);
    PetscCall(sys.AddElement(e, ke));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode PatchTest(MPI_Comm comm, fe::Formulation f)
{
  PetscMPIInt rank;
  SerialMesh serial;
  Mesh mesh;
  System sys;
  std::vector<double> reactions;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  const std::vector<std::string> sets = {"left", "right", "bottom", "top"};
  if (rank == 0) {
    serial = GenerateRectangle(2.0, 1.0, 4, 3);
    // Distort the interior nodes (deterministically) so that no cell is a parallelogram.
    for (int n = 0; n < serial.num_nodes(); ++n) {
      const double x = serial.xy[2 * n], y = serial.xy[2 * n + 1];
      if (x > 0 && x < 2 && y > 0 && y < 1) {
        serial.xy[2 * n] += 0.13 * std::sin(7.1 * n);
        serial.xy[2 * n + 1] += 0.09 * std::cos(3.3 * n);
      }
    }
  }
  PetscCall(mesh.Create(comm, serial, sets));
  PetscCall(sys.Setup(mesh));
  PetscCall(AssembleElastic(mesh, sys, f));
  // Linear field u = a + G x.
  const double a[2] = {0.01, -0.02}, g[2][2] = {{1e-3, 4e-4}, {-2e-4, -6e-4}};
  const auto exact = [&](PetscInt n, int k) { return a[k] + g[k][0] * mesh.x0[2 * n] + g[k][1] * mesh.x0[2 * n + 1]; };
  std::set<PetscInt> boundary;
  for (const auto &name : sets)
    for (PetscInt n : mesh.node_sets[name]) boundary.insert(n);
  for (PetscInt n : boundary)
    for (int k = 0; k < 2; ++k) sys.Prescribe(n, k, exact(n, k));
  Vec du = sys.CreateLocalVector();
  PetscCall(sys.Solve(du, reactions));
  const PetscScalar *d;
  double err = 0, gerr;
  PetscCall(VecGetArrayRead(du, &d));
  for (PetscInt n = 0; n < mesh.num_nodes; ++n)
    for (int k = 0; k < 2; ++k) err = std::max(err, std::fabs(PetscRealPart(d[mesh.node_dof[n] + k]) - exact(n, k)));
  // Stress at every Gauss point equals D eps.
  const Mat4 dm = IsotropicElasticMatrix(kE, kNu);
  const Voigt eps = {g[0][0], g[1][1], 0.0, g[0][1] + g[1][0]};
  double serr = 0, gserr;
  for (PetscInt e = 0; e < mesh.num_cells; ++e) {
    double xe[8];
    fe::ElemVec due;
    fe::QuadGeometry geo;
    for (int q = 0; q < 4; ++q) {
      const PetscInt n = mesh.cell_nodes[4 * e + q];
      xe[2 * q] = mesh.x0[2 * n], xe[2 * q + 1] = mesh.x0[2 * n + 1];
      due[2 * q] = PetscRealPart(d[mesh.node_dof[n]]), due[2 * q + 1] = PetscRealPart(d[mesh.node_dof[n] + 1]);
    }
    fe::ComputeGeometry(xe, geo);
    for (int gp = 0; gp < 4; ++gp) {
      Voigt de;
      double w;
      fe::IncrementKinematics(geo, gp, f, due, de, w);
      for (int r = 0; r < 4; ++r) {
        double s = 0, sx = 0;
        for (int c = 0; c < 4; ++c) s += dm[r][c] * de[c], sx += dm[r][c] * eps[c];
        serr = std::max(serr, std::fabs(s - sx));
      }
    }
  }
  PetscCall(VecRestoreArrayRead(du, &d));
  PetscCall(VecDestroy(&du));
  PetscCall(MPIU_Allreduce(&err, &gerr, 1, MPIU_REAL, MPIU_MAX, comm));
  PetscCall(MPIU_Allreduce(&serr, &gserr, 1, MPIU_REAL, MPIU_MAX, comm));
  // Round-off level: displacements ~1e-2 and stresses ~1 in these units. Measured at most 1.7e-17 and 5.6e-14
  // (1 and 2 ranks; OpenBLAS Haswell, SkylakeX, Prescott): about 100 times that.
  CHECK(gerr < 2e-15);
  CHECK(gserr < 5e-12);
  PetscCall(PetscPrintf(comm, "patch test (%s): max displacement error %.2e, max stress error %.2e\n",
                        f == fe::Formulation::Q4 ? "q4" : "bbar", gerr, gserr));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode RotatedFrameTest(MPI_Comm comm, double alpha)
{
  PetscMPIInt rank;
  SerialMesh serial;
  Mesh mesh;
  System sys;
  std::vector<double> reactions;
  const double lx = 3.0, ly = 1.0, delta = 0.003;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  const std::vector<std::string> sets = {"left", "right", "bottom", "top"};
  if (rank == 0) {
    serial = GenerateRectangle(lx, ly, 6, 3);
    for (int n = 0; n < serial.num_nodes(); ++n) {
      const double x = serial.xy[2 * n], y = serial.xy[2 * n + 1];
      serial.xy[2 * n] = std::cos(alpha) * x - std::sin(alpha) * y;
      serial.xy[2 * n + 1] = std::sin(alpha) * x + std::cos(alpha) * y;
    }
  }
  PetscCall(mesh.Create(comm, serial, sets));
  PetscCall(sys.Setup(mesh));
  // Frames on the supported edges: l along the block's axis, n across it.
  for (const char *name : {"left", "right", "bottom"})
    for (PetscInt n : mesh.node_sets[name]) sys.SetFrame(n, alpha);
  PetscCall(AssembleElastic(mesh, sys, fe::Formulation::BBar));
  for (PetscInt n : mesh.node_sets["left"]) sys.Prescribe(n, 0, 0.0);    // u.l = 0
  for (PetscInt n : mesh.node_sets["bottom"]) sys.Prescribe(n, 1, 0.0);  // u.n = 0
  for (PetscInt n : mesh.node_sets["right"]) sys.Prescribe(n, 0, delta); // u.l = delta
  Vec du = sys.CreateLocalVector();
  PetscCall(sys.Solve(du, reactions));

  // Exact: uniaxial stress in the block's axis, plane strain.
  const double ex = delta / lx, ey = -kNu / (1 - kNu) * ex, sx = kE / (1 - kNu * kNu) * ex;
  const PetscScalar *d;
  double err = 0, gerr, fsum = 0, gfsum;
  PetscCall(VecGetArrayRead(du, &d));
  for (PetscInt n = 0; n < mesh.num_nodes; ++n) {
    const double x = mesh.x0[2 * n], y = mesh.x0[2 * n + 1];
    const double xl = std::cos(alpha) * x + std::sin(alpha) * y, yl = -std::sin(alpha) * x + std::cos(alpha) * y;
    const double ul = ex * xl, vl = ey * yl;
    const double ux = std::cos(alpha) * ul - std::sin(alpha) * vl, uy = std::sin(alpha) * ul + std::cos(alpha) * vl;
    err = std::max({err, std::fabs(PetscRealPart(d[mesh.node_dof[n]]) - ux),
                    std::fabs(PetscRealPart(d[mesh.node_dof[n] + 1]) - uy)});
  }
  PetscCall(VecRestoreArrayRead(du, &d));
  PetscCall(VecDestroy(&du));
  const auto &pres = sys.prescribed();
  for (size_t q = 0; q < pres.size(); ++q)
    if (pres[q].value == delta) fsum += reactions[q]; // entries of unowned nodes are 0
  PetscCall(MPIU_Allreduce(&err, &gerr, 1, MPIU_REAL, MPIU_MAX, comm));
  PetscCall(MPIU_Allreduce(&fsum, &gfsum, 1, MPIU_REAL, MPIU_SUM, comm));
  // Displacements ~1e-3 and the reaction sigma_l * height: round-off. Measured at most 2.2e-18 and 2.4e-15
  // relative (1 and 2 ranks; OpenBLAS Haswell, SkylakeX, Prescott): about 100 times that.
  CHECK(gerr < 2e-16);
  CHECK_NEAR(gfsum, sx * ly, 3e-13 * sx * ly);
  PetscCall(PetscPrintf(comm,
                        "rotated frame alpha=%.3f: max displacement error %.2e, reaction %.12g (exact %.12g, %.1e "
                        "relative)\n",
                        alpha, gerr, gfsum, sx * ly, std::abs(gfsum / (sx * ly) - 1)));
  PetscFunctionReturn(PETSC_SUCCESS);
}

// The unsymmetric friction row: node p in a rotated frame gets row l += c row n.
// The solution must satisfy (K du)_l + c R_n = f_l at p (R_n its normal
// reaction), K du = f at the other free dofs, with K du formed here element by
// element (independently of the assembled matrix).
static PetscErrorCode CouplingRowTest(MPI_Comm comm)
{
  PetscMPIInt rank;
  SerialMesh serial;
  Mesh mesh;
  System sys;
  std::vector<double> reactions;
  const double c = 0.37, angle = 0.4, f_l = 0.8;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  const std::vector<std::string> sets = {"left", "right", "bottom", "top"};
  if (rank == 0) serial = GenerateRectangle(2.0, 1.0, 4, 2);
  PetscCall(mesh.Create(comm, serial, sets));
  PetscCall(sys.Setup(mesh));
  // The node at the middle of the top edge carries the frame and the coupling.
  PetscInt p = -1;
  for (PetscInt n : mesh.node_sets["top"])
    if (std::abs(mesh.x0[2 * n] - 1.0) < 1e-12) p = n;
  if (p >= 0) sys.SetFrame(p, angle);
  PetscCall(AssembleElastic(mesh, sys, fe::Formulation::BBar));
  for (PetscInt n : mesh.node_sets["bottom"]) sys.Prescribe(n, 0, 0.0), sys.Prescribe(n, 1, 0.0);
  if (p >= 0) {
    sys.Prescribe(p, 1, -2e-3);                             // pushed along its n
    if (mesh.node_owned[p]) sys.AddFrameForce(p, f_l, 0.0); // a load is added once
    if (mesh.node_owned[p]) sys.AddRowCoupling(p, c);
  }
  Vec du = sys.CreateLocalVector();
  PetscCall(sys.Solve(du, reactions));

  // K du from the elements, on the local nodes, summed over ranks into a global vector.
  Vec kdu_local = sys.CreateLocalVector(), kdu;
  const PetscScalar *d;
  PetscScalar *k;
  PetscCall(VecZeroEntries(kdu_local));
  PetscCall(VecGetArrayRead(du, &d));
  PetscCall(VecGetArray(kdu_local, &k));
  const Mat4 dm = IsotropicElasticMatrix(kE, kNu);
  for (PetscInt e = 0; e < mesh.num_cells; ++e) {
    double xe[8];
    fe::ElemVec due, fe_;
    fe::QuadGeometry geo;
    Voigt sig[4];
    for (int q = 0; q < 4; ++q) {
      const PetscInt n = mesh.cell_nodes[4 * e + q];
      xe[2 * q] = mesh.x0[2 * n], xe[2 * q + 1] = mesh.x0[2 * n + 1];
      due[2 * q] = PetscRealPart(d[mesh.node_dof[n]]), due[2 * q + 1] = PetscRealPart(d[mesh.node_dof[n] + 1]);
    }
    fe::ComputeGeometry(xe, geo);
    for (int g = 0; g < 4; ++g) {
      Voigt de;
      double w;
      fe::IncrementKinematics(geo, g, fe::Formulation::BBar, due, de, w);
      sig[g] = Voigt{};
      for (int r = 0; r < 4; ++r)
        for (int cc = 0; cc < 4; ++cc) sig[g][r] += dm[r][cc] * de[cc];
    }
    fe::InternalForce(geo, fe::Formulation::BBar, sig, fe_);
    for (int q = 0; q < 4; ++q) {
      const PetscInt n = mesh.cell_nodes[4 * e + q];
      k[mesh.node_dof[n]] += fe_[2 * q], k[mesh.node_dof[n] + 1] += fe_[2 * q + 1];
    }
  }
  PetscCall(VecRestoreArray(kdu_local, &k));
  PetscCall(VecRestoreArrayRead(du, &d));
  PetscCall(DMGetGlobalVector(mesh.dm, &kdu));
  PetscCall(VecZeroEntries(kdu));
  PetscCall(DMLocalToGlobal(mesh.dm, kdu_local, ADD_VALUES, kdu));
  PetscCall(DMGlobalToLocal(mesh.dm, kdu, INSERT_VALUES, kdu_local));
  PetscCall(DMRestoreGlobalVector(mesh.dm, &kdu));

  // Check the rows on owned nodes.
  const PetscScalar *kk, *react;
  double err = 0, gerr, scale = 0, gscale;
  PetscCall(VecGetArrayRead(kdu_local, &kk));
  PetscCall(VecGetArrayRead(sys.reactions_local(), &react));
  std::set<PetscInt> fixed(mesh.node_sets["bottom"].begin(), mesh.node_sets["bottom"].end());
  for (PetscInt n = 0; n < mesh.num_nodes; ++n) {
    if (!mesh.node_owned[n] || fixed.count(n)) continue;
    double kx = PetscRealPart(kk[mesh.node_dof[n]]), ky = PetscRealPart(kk[mesh.node_dof[n] + 1]);
    scale = std::max({scale, std::abs(kx), std::abs(ky)});
    if (n == p) {
      // Into the frame: l = (cos, sin), n = (-sin, cos).
      const double kl = std::cos(angle) * kx + std::sin(angle) * ky, kn = -std::sin(angle) * kx + std::cos(angle) * ky;
      const double rn = PetscRealPart(react[mesh.node_dof[n] + 1]);
      err = std::max(err, std::abs(kl + c * rn - f_l));
      err = std::max(err, std::abs(kn - rn)); // the reaction is K du at the supported dof
    } else
      err = std::max({err, std::abs(kx), std::abs(ky)});
  }
  PetscCall(VecRestoreArrayRead(sys.reactions_local(), &react));
  PetscCall(VecRestoreArrayRead(kdu_local, &kk));
  PetscCall(MPIU_Allreduce(&err, &gerr, 1, MPIU_REAL, MPIU_MAX, comm));
  PetscCall(MPIU_Allreduce(&scale, &gscale, 1, MPIU_REAL, MPIU_MAX, comm));
  // Round-off: measured at most 8.9e-16 of forces up to 1.47 (1 and 2 ranks; OpenBLAS Haswell, SkylakeX,
  // Prescott): about 100 times that.
  CHECK(gerr < 6e-14 * gscale);
  PetscCall(PetscPrintf(comm, "friction correction row: max row error %.2e (forces up to %.2e)\n", gerr, gscale));
  PetscCall(VecDestroy(&du));
  PetscCall(VecDestroy(&kdu_local));
  PetscFunctionReturn(PETSC_SUCCESS);
}

// A boundary segment that is no cell edge (a diagonal), seen by rank 0 alone
// while it labels the serial mesh: every rank must return the same input error
// (none may be left waiting in the distribution; the test's timeout catches a hang).
static PetscErrorCode SegmentNotAnEdgeTest(MPI_Comm comm)
{
  PetscMPIInt rank;
  SerialMesh serial;
  Mesh mesh;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (rank == 0) {
    serial = GenerateRectangle(2.0, 1.0, 4, 3);
    serial.edge_sets["left"].push_back({serial.quads[0], serial.quads[2]}); // cell 0's diagonal
  }
  PetscCall(PetscPushErrorHandler(PetscReturnErrorHandler, nullptr));
  const PetscErrorCode err = mesh.Create(comm, serial, {"left", "right", "bottom", "top"});
  PetscCall(PetscPopErrorHandler());
  CHECK(err == PETSC_ERR_USER_INPUT);
  PetscFunctionReturn(PETSC_SUCCESS);
}

int main(int argc, char **argv)
{
  PetscCall(PetscInitialize(&argc, &argv, nullptr, nullptr));
  PetscCall(Log::Register());
  PetscCall(PatchTest(PETSC_COMM_WORLD, fe::Formulation::Q4));
  PetscCall(PatchTest(PETSC_COMM_WORLD, fe::Formulation::BBar));
  PetscCall(RotatedFrameTest(PETSC_COMM_WORLD, 0.0));
  PetscCall(RotatedFrameTest(PETSC_COMM_WORLD, 0.6));
  PetscCall(RotatedFrameTest(PETSC_COMM_WORLD, 0.5 * M_PI + 0.3));
  PetscCall(CouplingRowTest(PETSC_COMM_WORLD));
  PetscCall(SegmentNotAnEdgeTest(PETSC_COMM_WORLD));
  PetscMPIInt rank;
  PetscCallMPI(MPI_Comm_rank(PETSC_COMM_WORLD, &rank));
  int failures = tftest::failures, total;
  MPI_Allreduce(&failures, &total, 1, MPI_INT, MPI_SUM, PETSC_COMM_WORLD);
  tftest::failures = rank == 0 ? total : 0;
  const int rc = rank == 0 ? ReportChecks("test_system") : (total ? 1 : 0);
  PetscCall(PetscFinalize());
  return rc;
}
