// QM6 with equilibrium iterations: a cell's nodal forces are a function of
// its nodal increment, whatever loading states the assembled tangent took
// (docs/theory.md, 5a). A plastic aluminum block (4 x 2 QM6 cells, 2 x 1 mm)
// is bent past yield and committed; for a second increment that unloads part
// of the block and loads the rest, the trial forces are evaluated twice: with
// the tangent assembled from that increment's own loading states, and after
// the tangent was switched by the scan of another increment (the reverse one,
// which turns the loading and unloading points over). Reference: the first
// evaluation; the two agree within 1e-7 of the largest force. What is left
// is the fixed point's: a point reaching the surface inside the step takes
// its elastic fraction from the modes of the last pass's condensation, which
// three passes settle to 1.7e-9 here (1 and 2 ranks, OpenBLAS Haswell and
// Prescott); 1e-7 is some 60 times that. When the modes took the assembled
// condensation (before each cell took its own) the second evaluation
// differed by 1.1e-3 of the largest force: the check fails on that by four
// orders of magnitude.
#include <petscsys.h>

#include <algorithm>
#include <cmath>
#include <memory>

#include "check.hpp"
#include "tubeform/body/body.hpp"
#include "tubeform/mesh/generator.hpp"

using namespace tf;

namespace {

struct Block {
  Mesh mesh;
  System system;
  Body body;
  Vec du = nullptr, f = nullptr;
  ~Block()
  {
    (void)VecDestroy(&du);
    (void)VecDestroy(&f);
  }
};

// du = s * (bending about the block's mid-height, plus a stretch): u_x = k x (y - 0.5) + e x,
// u_y = -k x^2 / 2, at every local node (ghosts included: the same field on every rank).
PetscErrorCode Field(Block &b, double k, double e, double s)
{
  PetscScalar *v;
  PetscFunctionBeginUser;
  PetscCall(VecGetArray(b.du, &v));
  for (PetscInt n = 0; n < b.mesh.num_nodes; ++n) {
    const double x = b.mesh.x0[2 * n], y = b.mesh.x0[2 * n + 1];
    v[b.mesh.node_dof[n]] = s * (k * x * (y - 0.5) + e * x);
    v[b.mesh.node_dof[n] + 1] = s * (-0.5 * k * x * x);
  }
  PetscCall(VecRestoreArray(b.du, &v));
  PetscFunctionReturn(PETSC_SUCCESS);
}

// The trial forces of the increment in b.du after the tangent's loading
// states were scanned from `scan` (applied) and assembled; their largest magnitude in `fmax`.
PetscErrorCode Forces(Block &b, Vec scan, std::vector<double> &out, double &fmax, PetscInt &switches)
{
  StepLimit limit;
  PetscInt transitions;
  double magnitude, count;
  const PetscScalar *f;
  PetscFunctionBeginUser;
  PetscCall(b.body.ScanTrial(scan, true, limit, switches, transitions));
  PetscCall(b.system.Begin());
  PetscCall(b.body.AssembleTangent(b.system));
  PetscCall(b.body.TrialForce(b.du, 1.0, b.f, &magnitude, &count));
  PetscInt n;
  PetscCall(VecGetLocalSize(b.f, &n));
  PetscCall(VecGetArrayRead(b.f, &f));
  out.assign(f, f + n);
  PetscCall(VecRestoreArrayRead(b.f, &f));
  fmax = 0;
  for (double v : out) fmax = std::max(fmax, std::abs(v));
  PetscFunctionReturn(PETSC_SUCCESS);
}

} // namespace

int main(int argc, char **argv)
{
  PetscCall(PetscInitialize(&argc, &argv, nullptr, nullptr));
  {
    MPI_Comm comm = PETSC_COMM_WORLD;
    PetscMPIInt rank;
    PetscCallMPI(MPI_Comm_rank(comm, &rank));
    SerialMesh serial;
    if (rank == 0) serial = GenerateRectangle(2.0, 1.0, 4, 2);
    auto b = std::make_unique<Block>();
    PetscCall(b->mesh.Create(comm, serial, {"left", "right", "bottom", "top"}));
    PetscCall(b->system.Setup(b->mesh));
    BodyParams prm; // the paper's aluminum, Ludwik hardening
    prm.element = fe::Formulation::QM6;
    prm.state_from_strain = true; // equilibrium iterations' stress update
    prm.yield_inside = true;
    prm.kinematics = ObjectiveScheme::Midpoint;
    PetscCall(b->body.Setup(b->mesh, prm));
    b->du = b->system.CreateLocalVector();
    b->f = b->system.CreateLocalVector();

    // 1. Bend past yield (curvature 0.02 / mm: outer fibre strain 0.01, some 4.5 yield strains) and commit.
    Body::CommitInfo info;
    PetscCall(Field(*b, 0.02, 0.0, 1.0));
    PetscCall(b->system.Begin());
    PetscCall(b->body.AssembleTangent(b->system));
    PetscCall(b->body.Commit(b->du, 1.0, info));
    CHECK(info.n_plastic > 0);

    // 2. An increment that unbends and stretches: the fibres on one side unload, on the other load.
    Vec reverse;
    PetscCall(VecDuplicate(b->du, &reverse));
    PetscCall(Field(*b, -0.004, -0.003, 1.0));
    PetscCall(VecCopy(b->du, reverse));
    PetscCall(VecScale(reverse, -1.0));
    std::vector<double> f_own, f_switched;
    double fmax, fmax2;
    PetscInt own_switches, switched;
    PetscCall(Forces(*b, b->du, f_own, fmax, own_switches));
    PetscCall(Forces(*b, reverse, f_switched, fmax2, switched));
    double diff = 0;
    for (size_t k = 0; k < f_own.size(); ++k) diff = std::max(diff, std::abs(f_own[k] - f_switched[k]));
    PetscCall(MPIU_Allreduce(MPI_IN_PLACE, &diff, 1, MPIU_REAL, MPIU_MAX, comm));
    PetscCall(MPIU_Allreduce(MPI_IN_PLACE, &fmax, 1, MPIU_REAL, MPIU_MAX, comm));
    // The reverse scan must have switched loading states (else nothing is tested).
    CHECK(switched > 0);
    CHECK(diff <= 1e-7 * fmax);
    PetscCall(PetscPrintf(comm,
                          "own tangents: %d points plastic after bending; the reverse scan switched %d loading "
                          "states; trial forces differ by %.1e of the largest (%.4g N/mm)\n",
                          (int)info.n_plastic, (int)switched, diff / fmax, fmax));
    PetscCall(VecDestroy(&reverse));
  }
  const int rc = ReportChecks("test_own_tangents");
  PetscCall(PetscFinalize());
  return rc;
}
