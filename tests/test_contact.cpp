// The contact set's step diagnostics on states built by hand, through the
// real mesh, body, system and MUMPS (1 or more ranks). A stiff elastic block
// (4 x 2 cells, 2 x 1 mm, E = 1e9 MPa) is pressed on a rigid floor by a load
// P on its top nodes, then pulled by -3P:
//  - r5, separation: the pull is -3 times the press, so every bottom node's
//    normal force f_n + r df_n reaches zero at r = 1/3 of it, up to the
//    change of geometry and initial stress after the press (relative size:
//    the strain, 1e-8 here; measured 2.8e-9): within 3e-7;
//  - committing the pull scaled to r5 (what the controller does) leaves no
//    tension and drops no more force than the group tolerance allows (nodes
//    whose r5 is within 1 + 1e-6 of the smallest go together: 1e-6 of a
//    node's force; the squaring test's threshold is 1e-6 of the load);
//  - committing the whole pull past r5 (a state with nodes in tension) must
//    be seen: the commit reports the tension the nodes reached before it
//    released them, 2P in all over five nodes, so the largest is at least
//    2P/5 and the squaring test's check (tension <= 1e-6 of the load) fails
//    on it. A tension column measured after the releases
//    would read 0 on such a state;
//  - a turning floor (spin 1 rad per unit stroke) cuts a step of 0.1 to its
//    turn bound turn_max = 1e-2 rad: r = 0.1 exactly, by the tool's r3
//    (Limiter::Rotation, no node: -1); the press itself sets no limit.
#include <petscsys.h>

#include <memory>

#include "check.hpp"
#include "tubeform/body/body.hpp"
#include "tubeform/contact/contact.hpp"
#include "tubeform/mesh/generator.hpp"
#include "tubeform/tool/shape.hpp"

using namespace tf;

namespace {

constexpr double kP = 10.0; // press (N/mm)

struct Block {
  Mesh mesh;
  System system;
  Body body;
  ContactSet contact;
  Vec du = nullptr;
  ~Block() { (void)VecDestroy(&du); }
};

// A tool that only turns about its frame's origin, `spin` radians per unit stroke (within a step: Turn stays 0).
class Spinning : public Motion {
public:
  explicit Spinning(double spin) : spin_(spin) {}
  std::unique_ptr<Motion> Clone() const override { return std::make_unique<Spinning>(*this); }
  std::string Kind() const override { return "spinning"; }
  Vec2 Offset(double s) const override { return {0 * s, -1 * s}; }
  Vec2 Direction() const override { return {0, -1}; }
  double Spin() const override { return spin_; }
  void Map(const TurnMap &) override {}

private:
  double spin_;
};

PetscErrorCode Build(MPI_Comm comm, std::unique_ptr<Block> &b, double spin = 0)
{
  PetscMPIInt rank;
  SerialMesh serial;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (rank == 0) serial = GenerateRectangle(2.0, 1.0, 4, 2);
  b = std::make_unique<Block>();
  PetscCall(b->mesh.Create(comm, serial, {"left", "right", "bottom", "top"}));
  PetscCall(b->system.Setup(b->mesh));
  BodyParams prm;
  prm.material.law = FlowLaw::Elastic;
  prm.material.E = 1e9, prm.material.nu = 0.3; // strains ~1e-8: the steps are linear to that
  PetscCall(b->body.Setup(b->mesh, prm));
  ContactSpec spec;
  spec.tools = {BuildFlatPlate(0.0, -10.0, 10.0, true)};
  spec.tools[0].motion = MotionHandle(std::make_unique<Spinning>(spin));
  spec.candidates = "bottom";
  PetscCall(b->contact.Setup(b->mesh, b->system, b->body.position(), spec));
  PetscCall(b->contact.Initialize());
  b->du = b->system.CreateLocalVector();
  PetscFunctionReturn(PETSC_SUCCESS);
}

// One linear solve with a vertical load fy spread evenly over the top nodes;
// the bottom-left node is held in x (no friction: no other x support).
PetscErrorCode Solve(Block &b, double fy, StepLimit &limit)
{
  std::vector<double> reactions;
  PetscFunctionBeginUser;
  const auto &top = b.mesh.node_sets["top"];
  PetscInt mine = 0, all;
  for (PetscInt n : top) mine += b.mesh.node_owned[n];
  PetscCall(MPIU_Allreduce(&mine, &all, 1, MPIU_INT, MPI_SUM, b.mesh.comm));
  PetscCall(b.system.Begin());
  PetscCall(b.body.AssembleTangent(b.system));
  PetscCall(b.contact.BeginIncrement());
  PetscCall(b.contact.Constrain(0.0));
  for (PetscInt n : top)
    if (b.mesh.node_owned[n]) b.system.AddForce(n, 0.0, fy / all);
  for (PetscInt n : b.mesh.node_sets["left"])
    if (b.mesh.x0[2 * n + 1] == 0.0) b.system.Prescribe(n, 0, 0.0);
  PetscCall(b.system.Solve(b.du, reactions));
  limit = StepLimit{};
  PetscCall(b.contact.LimitStep(b.du, 0.0, limit));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Commit(Block &b, double r, ContactCommit &report)
{
  Body::CommitInfo info;
  PetscFunctionBeginUser;
  PetscCall(VecScale(b.du, r));
  PetscCall(b.body.Commit(b.du, r, info)); // the geometry first: the contact set projects the new positions
  PetscCall(b.contact.Commit(b.du, 0.0, r, report));
  PetscFunctionReturn(PETSC_SUCCESS);
}

// Press by P, then pull by -3P committed at the fraction r_commit of the pull (< 0: at r5).
PetscErrorCode PressAndPull(MPI_Comm comm, double r_commit, StepLimit &pull, ContactCommit &pressed,
                            ContactCommit &pulled)
{
  std::unique_ptr<Block> b;
  StepLimit press;
  PetscFunctionBeginUser;
  PetscCall(Build(comm, b));
  PetscCall(Solve(*b, -kP, press));
  PetscCall(Commit(*b, 1.0, pressed));
  PetscCall(Solve(*b, 3 * kP, pull));
  PetscCall(Commit(*b, r_commit < 0 ? pull.r : r_commit, pulled));
  PetscFunctionReturn(PETSC_SUCCESS);
}

} // namespace

int main(int argc, char **argv)
{
  PetscCall(PetscInitialize(&argc, &argv, nullptr, nullptr));
  MPI_Comm comm = PETSC_COMM_WORLD;
  StepLimit pull;
  ContactCommit pressed, pulled;

  // The controller's way: the pull scaled to r5.
  PetscCall(PressAndPull(comm, -1, pull, pressed, pulled));
  CHECK(pull.who == Limiter::Separation);
  // r5 is off 1/3 by the geometry change after the press: measured 2.8e-9 (1 and 2 ranks, OpenBLAS Haswell,
  // SkylakeX, Prescott); about 100 times that.
  CHECK_NEAR(pull.r, 1.0 / 3.0, 3e-7);
  CHECK(pressed.tension == 0 && pressed.release_force == 0);
  // Round-off of the forces (~1e-15 of P) is all the tension left at r5 (measured 0 and 2.2e-16 N/mm): 100 times
  // that round-off level. The force dropped stays within the group tolerance (1e-6 of a node's force): measured
  // 4.2e-8 N/mm (both kernels, 1 and 2 ranks), bounded at about 100 times that.
  CHECK(pulled.tension <= 1e-13 * kP && pulled.release_force <= 5e-7 * kP);
  PetscCall(PetscPrintf(comm, "pull scaled to r5 = %.12f: tension %.1e, force dropped %.1e N/mm\n", pull.r,
                        pulled.tension, pulled.release_force));

  // Past r5: the nodes end the step in tension; the commit must say so.
  PetscCall(PressAndPull(comm, 1.0, pull, pressed, pulled));
  CHECK(pulled.tension >= 2 * kP / 5 * (1 - 1e-6)); // 2P in tension over 5 bottom nodes: the largest carries >= 2P/5
  CHECK(pulled.tension <= 2 * kP);                  // and no more than all of it: the squaring test's check fails here
  PetscCall(PetscPrintf(comm, "pull committed whole: tension before the release %.4f N/mm (2P = %g in all)\n",
                        pulled.tension, 2 * kP));
  // A turning tool's step: its turn bounded by turn_max (ContactParams' default 1e-2 rad).
  {
    std::unique_ptr<Block> b;
    StepLimit press, turn;
    PetscCall(Build(comm, b, 1.0));
    PetscCall(Solve(*b, -kP, press));
    CHECK(press.r == kNever);
    PetscCall(b->contact.LimitStep(b->du, 0.1, turn));
    CHECK(turn.who == Limiter::Rotation && turn.where == -1);
    CHECK_NEAR(turn.r, ContactParams{}.turn_max / 0.1, 1e-15);
    PetscCall(
      PetscPrintf(comm, "a floor turning 0.1 rad in a step: r = %.15g (%s)\n", turn.r, LimiterName((int)turn.who)));
  }
  PetscMPIInt rank;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  const int rc = rank == 0 ? ReportChecks("test_contact") : 0;
  PetscCall(PetscFinalize());
  return rc;
}
