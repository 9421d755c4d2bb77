// Node-to-rigid-surface contact with the regularized Coulomb law (docs/theory.md
// section 6; r4, r5, r6 of section 5). Each contact node carries the tool's local
// frame (l, n); its normal displacement is prescribed to follow the tool,
// its normal force is the reaction, and friction enters as an unsymmetric
// correction of its l row. State lives on every rank for its local nodes
// (owned and ghost) and is updated identically from ghost-filled vectors.
//
// A force the tool stops carrying is unloaded, never dropped: a node released
// within a step has its start force removed as a load of that step; a node
// that leaves with force at a commit (a held grazing node ending in tension, a
// release inside the group tolerance, a slide off the tool's end) keeps it as
// a pending force, removed as a load over the next increments (the share r of
// it each commits). Without this the body would keep the released force as a
// permanent out-of-balance force (the method never corrects equilibrium), and
// its work would leak out of the energy balance increment after increment.
// The driver holds the set; scenes read its forces for their measurements.
//
// A force-controlled tool (Tool::pad, a pad or holder) moves by an unknown
// stroke increment s chosen in every solve so that its force along its
// direction meets the scene's target (System's extra unknown). Its contact
// nodes follow it as any tool's do, and its events (r4, r5, r6) are those of
// the motion s of the solution.
#pragma once

#include <petscvec.h>

#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "tubeform/assembly/system.hpp"
#include "tubeform/mesh/archive.hpp"
#include "tubeform/mesh/mesh.hpp"
#include "tubeform/step/rmin.hpp"
#include "tubeform/tool/tool.hpp"

namespace tf {

// Tolerances of the contact set.
// A node on the tool surface within this (relative to the coordinates' size) starts in contact.
constexpr double kStartGap = 1e-9;
// A contact force below this fraction of the largest counts as zero (a grazing node).
constexpr double kSmallForce = 1e-6;
// Friction iterations measure the change of f_l against f_n, but not below
// this many "zero" forces (a thousandth of the largest): a node carrying
// almost nothing does not hold the iteration.
constexpr double kFloorOfSmallForces = 1e3;
// After this many friction iterates the updates are under-relaxed by kRelax:
// the tanh law can make plain iterates oscillate between sticking and sliding.
constexpr int kPlainIterations = 6;
constexpr double kRelax = 0.5;
// A node whose normal force would vanish within this fraction of a
// quasi-static step is released in the trial rather than cutting the step
// (round-off; with inertia the controller passes its shortest step instead).
constexpr double kReleaseWithin = 1e-9;
// A symmetry wall reaches this many times the body's size either way along its plane (a folded wall stays far
// inside it).
constexpr double kWallReach = 4;

struct ContactParams {
  double mu = 0;           // Coulomb coefficient
  double vcri = 0.01;      // quasi-stick slip (mm)
  double dphi_max = 0.5;   // r6: largest fall of f_l / (mu f_n) towards stick or reversal in an increment
  double dphi_rise = 1.0;  // r6, stick to slide: largest rise of |f_l / (mu f_n)| in an increment (1: none)
  double tol = 1e-4;       // friction iterations: change of f_l / (mu f_n) between iterates
  double group_tol = 1e-6; // contact/separation events within (1 + tol) r_min go together
  double gap_tol = 1e-7;   // a free node this close to the surface (mm) is in contact
  double turn_max = 1e-2;  // a turning tool's largest turn in an increment (rad; r3's -rmin_domega)
};

// What a commit did, for the history (docs/output.md): the friction work and
// the diagnostics that show whether the step's events were resolved.
struct ContactCommit {
  double w_friction = 0; // friction dissipation of the increment, -sum f_l,mid dslip
  double tension = 0;    // largest tensile normal force of a contact node at the end of the step, before releases
  // largest compressive normal force a release (or a slide off the tool's end) leaves to unload
  double release_force = 0;
  double gap = 0;         // largest gap (>= 0) of a node in contact after the commit (mm)
  double penetration = 0; // largest penetration (>= 0) of a candidate node into the tool after the commit (mm)
};

// What a scene asks of the driver's contact set.
struct ContactSpec {
  // The rigid tools, each moving by its direction per unit of the scene's
  // stroke (a fixed tool: direction 0). A node touches one tool at a time.
  std::vector<Tool> tools;
  std::string candidates; // the node set that may touch the tools (e.g. "outer")
  // Node sets whose component along a global axis is held (e.g. x0 -> (1, 0)).
  std::vector<std::pair<std::string, Vec2>> symmetry;
  // The body's surfaces (node and edge sets, e.g. outer and inner): their nodes touch the symmetry walls, and
  // their edges must not cross each other (the driver's watch of the wall meeting itself).
  std::vector<std::string> surfaces;
  // The sets of `symmetry` held on a plane through the origin that the body may not cross (the quarter's and the
  // half model's, where the tube meets its mirror image): each plane is a fixed frictionless wall after the tools,
  // touched by the nodes of `surfaces` not held on it.
  std::vector<std::string> walls;
  ContactParams params;
};

// Where the body lies beyond a tool or wall it does not touch (ContactSet::Crossing): a node touches one at a time,
// so one held on a symmetry wall passes through a die that reaches it, one on a die through the wall; and the
// springback that took the walls with the dies (none touched at the end of the loading) lets a node past them.
struct PlaneCrossing {
  double depth = 0; // how far the deepest node lies beyond it (mm; 0: none)
  int tool = -1;    // the tool's index (ContactSet::tool; a symmetry wall from num_tools() on; -1: none)
  int held = -1;    // the tool the node touches (-1: none)
  long node = -1;   // its input number
  Vec2 x{0, 0};     // where it is
  double tol = 0;   // the depth the set counts as a crossing: kCrossingTol of the body's size
};
// A node beyond a wall by more than this fraction of the body's size (its largest coordinate) has crossed it:
// 100 times the deepest penetration of a die seen with steps re-solved to their events (7e-7), below a hundredth
// of the thinnest wall the presets take (t / Ro >= 1 / 100).
constexpr double kCrossingTol = 1e-4;

class ContactSet : public ExtraUnknown {
public:
  // Collective. `x`: the body's current coordinates (2 per local node), read at each call.
  PetscErrorCode Setup(Mesh &mesh, System &system, const std::vector<double> &x, ContactSpec spec);
  PetscErrorCode Initialize(); // nodes touching the tool at stroke 0

  // Collective. The tools are removed (the paper's unloading): every node is released and the set takes no further
  // part in the increments; but where the body touches a symmetry wall at that moment (the wall pressed on its
  // mirror image), only the scene's tools go: the walls and their contact nodes stay through the springback.
  PetscErrorCode Remove();
  bool active() const { return !removed_; }
  // The tools of a restart inside a stage whose tools are not the first ones (called before Persist reads the
  // set's state, their strokes included: their number may differ from the first stage's).
  // The symmetry walls stay after them.
  void ReplaceTools(std::vector<Tool> tools)
  {
    tools.insert(tools.end(), tools_.begin() + num_dies_, tools_.end());
    num_dies_ = (int)(tools.size() - (tools_.size() - num_dies_));
    tools_ = std::move(tools);
  }
  // The node sets whose component along a direction the scene holds (ContactSpec::symmetry), in place of the
  // set's (a pass that turns the tube turns the full model's pins).
  void SetSymmetry(const std::vector<std::pair<std::string, Vec2>> &symmetry);
  // The stroke of the tools that follow the scene's (a force-controlled one keeps its own), and the motion of a
  // tool on a path of its own along the piece ahead (a step never crosses a turn of it: LoadPath::kinks).
  void SetStroke(double stroke)
  {
    for (Tool &t : tools_)
      if (!t.Unknown()) t.stroke = stroke, t.FollowPath();
  }
  bool has_pad() const
  {
    for (int k = 0; k < num_dies_ && !dies_removed_; ++k)
      if (tools_[k].Unknown()) return true;
    return false;
  }
  // The force-controlled tool's force along its direction at the end of a step, from the scene's target at its
  // start and end (the model's units, N/mm): the step adds the target's increment to the force the tool had,
  // and makes up the share `share` (the step's fraction of a full trial step) of what that force missed then.
  // A miss left by the equilibrium tolerance is made up over a full step: at a plateau of the load (a slope
  // near 0) it takes a long motion, which a step shortened to an event must not carry whole (it would land on
  // the event again, however short). Taken by the next Constrain.
  void SetPadTarget(double start, double end, double share)
  {
    pad_target_ = pad_start_ + (end - start) + share * (start - pad_start_);
  }
  // ExtraUnknown (collective): the target less the force of the force-controlled tool on the body along its
  // direction, for the reactions in the system (friction and the turning of forces on arcs at the latest
  // iterate); the motion found.
  PetscErrorCode Missing(double &missing) override;
  // Collective: the force the force-controlled tools put on the body along their directions (committed state).
  PetscErrorCode PadForce(double &force) const;
  void Moved(double ds) override { pad_step_ += ds; }
  // "the force-controlled " and the force-controlled tools' names.
  std::string Name() const override
  {
    std::string names;
    for (const Tool &t : tools_)
      if (t.Unknown()) names += (names.empty() ? "" : " and ") + t.name;
    return "the force-controlled " + names;
  }
  // The force-controlled tool's stroke increment in the latest solution: an iterate's own, which the caller
  // keeps beside the iterate's displacements (a line search halving back moves it with them).
  double pad_step() const { return pad_step_; }
  void set_pad_step(double step) { pad_step_ = step; }

  // Frames of the contact nodes on the current geometry (before assembly); the force-controlled tool's force.
  PetscErrorCode BeginIncrement();
  // New trial of a tool step: the committed active set, a new friction iteration sequence.
  void ResetIterates();
  // Friction iterate back to the increment's start (slip 0, committed f_n), no
  // predictor; the trial's releases stand.
  void LinearizeAtStart();
  // Prescribed normal motion (tool step dU, or the force-controlled tool's, closing any gap) and friction rows.
  PetscErrorCode Constrain(double dU);
  // After a solve: new slip iterates; converged when the friction forces changed
  // by less than tol (relative to mu f_n) on every rank.
  PetscErrorCode UpdateIterates(Vec du, double dU, bool &converged);
  // Nodes that came into contact without force and that the solution du would
  // pull off the tool: counted, and released with `apply` for this trial (the
  // step is then re-solved; their force and slip state are dropped only when
  // the increment is committed, and a new trial starts from the committed set).
  // A node whose force would vanish within `release_fraction` of the step is
  // released rather than limiting it. A released node that the next solution
  // leaves inside the tool is grazing: it goes back into contact and stays for
  // the rest of the trial.
  PetscErrorCode ReleasePulled(Vec du, double dU, double release_fraction, bool apply, PetscInt &released);
  // r4 (contact), r5 (separation), r6 (stick / reversal) for the solution du of step dU.
  PetscErrorCode LimitStep(Vec du, double dU, StepLimit &limit);
  // Accepts the increment du with tool step dU, the last solution scaled by r
  // (its reactions scaled by r, its events up to r (1 + group_tol) happen):
  // forces, slips, events, and the projection of every candidate on the
  // moved tool (frames of the contact nodes at the end of the step). Call
  // after the body's commit: the projection reads the positions at the end
  // of the step.
  PetscErrorCode Commit(Vec du, double dU, double r, ContactCommit &report);

  // Friction forces on the body (owned nodes, global frame) into a contribution vector.
  PetscErrorCode AddFrictionForces(Vec f) const;
  // The forces of the contact nodes (normal and friction), owned nodes, global frame, added to f.
  PetscErrorCode AddNodeForces(Vec f) const;
  // Every force the tool still puts on the body (contact nodes and the pending
  // forces of released ones), owned nodes, global frame, added to f; with `dies_only`, not the symmetry walls'
  // (the springback's loads: Remove keeps the walls).
  PetscErrorCode AddContactForces(Vec f, bool dies_only = false) const;
  // The pending forces of released nodes (owned nodes, global frame) added to
  // f: applied loads until the following increments have removed them.
  PetscErrorCode AddPendingForces(Vec f) const;
  // Collective: sum over the nodes in contact with tool `k` of the force on the body (global frame) and, if
  // asked, its moment about the tool frame's origin (Tool::origin) at the current stroke (counter-clockwise positive, N
  // mm/mm).
  PetscErrorCode TotalForce(int k, double force[2], double *moment = nullptr) const;
  // Collective: the nodes in contact (with `walls`, those on the symmetry walls too).
  PetscErrorCode Count(PetscInt &n, bool walls = true) const;
  // Collective: the largest moment about c the contact nodes' friction could put on the body, each sliding along
  // its tool with mu |f_n| (N mm/mm; the rotation hold's yardstick, scenes/hold.hpp).
  PetscErrorCode FrictionMoment(const Vec2 &c, double &capacity) const;
  // Collective: how far the contact nodes' normals spread over the plane: the smallest over the largest
  // eigenvalue of the sum of n n^T over them, tan^2 of half the angle between two normals; 0 when all are
  // parallel (or none touches): the body then slides along them against friction alone.
  PetscErrorCode NormalSpread(double &spread) const;
  // Collective: sum over contact nodes of the normal force f_n.
  PetscErrorCode NormalForceSum(double &sum) const;
  // Collective: largest penetration (>= 0) of a candidate node into the tool (mm)
  // (Commit reports it for every increment; this is for the initial state).
  PetscErrorCode Penetration(double &penetration) const;
  // Collective: the node deepest beyond a tool or symmetry wall it may touch and does not (PlaneCrossing).
  PetscErrorCode Crossing(PlaneCrossing &c) const;
  // Collective: the largest difference between a contact node's stored normal
  // force and the normal component (in its frame after the last commit) of
  // the force the body needs there (f_net = f_int - f_applied, ghost-summed local vector),
  // (N/mm): how far the force bookkeeping has drifted from the body's equilibrium. Nodes whose both components are held
  // (global frame on a symmetry plane) share their force with the support and
  // are left out.
  PetscErrorCode NormalForceMismatch(Vec f_net, double &mismatch) const;

  // Collective: writes or reads the state of the set (contact nodes, forces,
  // slips, frames, pending forces, predictors) between increments.
  PetscErrorCode Persist(Archive &ar);
  bool InContact(PetscInt node) const { return contact_[node]; }
  // The tool a node touches (or, free, the one it is nearest to) and the segment of it.
  int ToolOf(PetscInt node) const { return tool_of_[node]; }
  int Segment(PetscInt node) const { return segment_[node]; }
  // The scene's tools (tool(k), k < num_tools()), then the symmetry walls (num_walls()).
  int num_tools() const { return num_dies_; }
  int num_walls() const { return (int)tools_.size() - num_dies_; }
  const std::vector<std::string> &surfaces() const { return surfaces_; }
  const Tool &tool(int k) const { return tools_[k]; }
  bool friction() const { return prm_.mu > 0; }
  const ContactParams &params() const { return prm_; }
  // Equilibrium iterations balance every step: the force of a node leaving the
  // tool is balanced by the next step's iterations, not kept as a pending load.
  void SetBalanced(bool balanced) { balanced_ = balanced; }
  // The resolution of the forces (N/mm): equilibrium iterations balance them to
  // within it, so a normal force below it counts as zero for releases and r5.
  void SetForceResolution(double f) { resolution_ = f; }

private:
  Mesh *mesh_ = nullptr;
  System *system_ = nullptr;
  const std::vector<double> *x_body_ = nullptr;
  std::vector<Tool> tools_; // the scene's (num_dies_), then the symmetry walls
  int num_dies_ = 0;
  ContactParams prm_;
  std::vector<std::string> surfaces_;
  std::vector<char> die_node_, surface_node_; // a candidate of the scene's tools; a node of the surfaces
  std::vector<std::vector<char>> held_on_;    // per wall: the node is held on its plane (it touches it not)
  double size_ = 0;                           // the body's largest coordinate at the start (mm)
  bool removed_ = false;
  bool dies_removed_ = false; // the scene's tools are gone, the symmetry walls stay (Remove)
  bool balanced_ = false;
  double resolution_ = 0;
  std::vector<PetscInt> candidates_;
  std::vector<char> contact_, global_frame_;
  std::vector<Vec2> sym_dir_; // held direction on a symmetry plane, {0, 0} if none
  std::vector<int> segment_;
  std::vector<int> tool_of_; // the tool of segment_ (contact), or the nearest one (free)
  std::vector<int> touch_;   // the tool a free node's r4 is with
  std::vector<double> fn_, x_, gap_, kappa_, dxk_, fnk_, r4_, r5_;
  std::vector<double> rate_;    // slip per unit stroke of the latest solution: predicts the next iterate
  std::vector<double> last_dx_; // slip of the last increment (predictor for static tools)
  bool predict_ = true;
  bool settled_ = true; // the last friction iterate met the tolerance (or there is no friction)
  int iteration_ = 0;
  std::vector<char> released_, frozen_; // within the current step
  double f_small_ = 0;                  // contact forces below this count as zero
  double slid_off_ = 0;                 // largest normal force left by a slide off the tool's end (next report)
  double pad_step_ = 0;                 // the force-controlled tool's stroke increment in the latest solution
  double pad_target_ = 0;               // its force along its direction at the end of the step (SetPadTarget)
  double pad_start_ = 0;                // and at the start of the increment (BeginIncrement)
  std::vector<Vec2> n_, l_;
  // Force (global frame) a released owned node still puts on the body, unloaded by the next steps.
  std::vector<Vec2> pending_;

  MPI_Comm comm() const { return mesh_->comm; }
  // Friction acts along l: not on a node whose both components are held, nor on a symmetry wall.
  bool Frictional(PetscInt node) const
  {
    return !global_frame_[node] && sym_dir_[node][0] == 0 && sym_dir_[node][1] == 0 && tool_of_[node] < num_dies_;
  }
  // Whether a node may touch tool k: the scene's candidates its tools, the surfaces' nodes not held on a wall's
  // plane that wall.
  bool MayTouch(PetscInt node, int k) const
  {
    return k < num_dies_ ? die_node_[node] && !dies_removed_ : surface_node_[node] && !held_on_[k - num_dies_][node];
  }
  bool SlipFree(PetscInt node) const { return contact_[node] && Frictional(node); }
  Vec2 Position(PetscInt node) const { return {(*x_body_)[2 * node], (*x_body_)[2 * node + 1]}; }
  // The force of a node's contact state (f_n, slip) on the body: friction only,
  // or normal plus friction.
  Vec2 NodeForce(PetscInt node, bool with_normal) const;
  // The node leaves the tool: `share` of the force of its state becomes
  // pending (owned nodes), and the state is cleared.
  void Leave(PetscInt node, double share);
  // A symmetry plane's held direction is a global axis: the index of that axis.
  static int HeldComponent(const Vec2 &s) { return std::abs(s[0]) > std::abs(s[1]) ? 0 : 1; }
  // Frame, gap and curvature of a contact node from its projection on tool k.
  void TakeFrame(PetscInt node, int k, const Projection &pr);
  // Commit, its forces: each candidate's normal force, slip and state at the end of the step r of the increment du
  // (r5 releases, r4 touches); the friction work, the tension and the force dropped by releases into report.
  PetscErrorCode CommitForces(Vec du, double dU, double r, ContactCommit &report);
  // Commit, its new geometry on the moved tools: contact nodes take the frame where they now are (the forces are
  // reported in it) and keep their gap for the next increment to close (on arcs, sliding along the tangent leaves a
  // second-order gap); a free node that reached the surface up to round-off is in contact. The largest gap and
  // penetration into report.
  PetscErrorCode TakeMovedFrames(ContactCommit &report);
  // A node's projection on the nearest tool it may touch (the smallest gap among the
  // tools it projects on; segment -1 and k = -1 if none).
  Projection ProjectNearest(PetscInt node, int &k) const;
  // The symmetry walls of spec (after the tools) and the nodes that touch them.
  PetscErrorCode SetupWalls(const ContactSpec &spec);
  // The motion per unit stroke of the tool a node touches (or was released from).
  Vec2 Direction(PetscInt node) const { return tools_[tool_of_[node]].Direction(); }
  // The component along its tool's direction of a contact force f_n n + f_l l on a node.
  double ForceAlong(PetscInt node, double fn, double fl) const;
  // Tool k's stroke increment in a step of the scene's stroke dU (a force-controlled tool: its own).
  double Step(int k, double dU) const { return tools_[k].Unknown() ? pad_step_ : dU; }
  // The motion in that step of the tool's point where a node at x touches it (Tool::Velocity: a turning tool's
  // point moves about its centre too; taken linear in the step, as the body's rotations are).
  Vec2 MotionAt(PetscInt node, double dU, const Vec2 &x) const
  {
    const double s = Step(tool_of_[node], dU);
    const Vec2 v = tools_[tool_of_[node]].Velocity(x);
    return {s * v[0], s * v[1]};
  }
  // The same for the node where it is (the step's start, before the body's commit).
  Vec2 Motion(PetscInt node, double dU) const { return MotionAt(node, dU, Position(node)); }
  // How far the tool a node touches turns in that step (radians): its frame turns with it.
  double TurnIn(PetscInt node, double dU) const { return tools_[tool_of_[node]].Spin() * Step(tool_of_[node], dU); }
  Vec2 Increment(const PetscScalar *d, PetscInt node) const;
  double NormalReaction(PetscInt node, const PetscScalar *react) const;
  // The normal force increment of a solution with normal reaction reaction_n
  // and slip s in a step dU: the reaction less the turning of the friction force on arcs and with a turning tool
  // (friction::NormalIncrement, with the friction force of the iterate).
  double NormalIncrement(PetscInt node, double reaction_n, double s, double dU) const;
  // The slip of a node that moves by u in a step dU from x (the step's start; Position(node) before the body's
  // commit), relative to the tool's point there.
  double SlipFrom(PetscInt node, const Vec2 &u, double dU, const Vec2 &x) const;
  double Slip(PetscInt node, const Vec2 &u, double dU) const { return SlipFrom(node, u, dU, Position(node)); }
};

} // namespace tf
