#include "tubeform/contact/contact.hpp"

#include <algorithm>
#include <cmath>

#include "tubeform/contact/friction.hpp"
#include "tubeform/core/log.hpp"

namespace tf {

namespace {
double Dot(const Vec2 &a, const Vec2 &b) { return a[0] * b[0] + a[1] * b[1]; }
} // namespace

Vec2 ContactSet::Increment(const PetscScalar *d, PetscInt node) const
{
  const PetscInt o = mesh_->node_dof[node];
  return {PetscRealPart(d[o]), PetscRealPart(d[o + 1])};
}

// Slip of a contact node relative to the tool in an increment: its motion
// along l minus the tool's.
double ContactSet::SlipFrom(PetscInt node, const Vec2 &u, double dU, const Vec2 &x) const
{
  return Dot(u, l_[node]) - Dot(MotionAt(node, dU, x), l_[node]);
}

PetscErrorCode ContactSet::Remove()
{
  PetscFunctionBeginUser;
  // The symmetry walls stay, and the nodes on them keep their state: they are the tube's own mirror image, which
  // the springback does not release (a wall no node touches at the end of loading may be met in the springback).
  const bool walls = num_walls() > 0;
  for (PetscInt node : candidates_)
    if (!walls || tool_of_[node] < num_dies_) contact_[node] = 0, fn_[node] = x_[node] = 0;
  std::fill(released_.begin(), released_.end(), 0);
  std::fill(frozen_.begin(), frozen_.end(), 0);
  std::fill(pending_.begin(), pending_.end(), Vec2{0, 0}); // the scene has taken them over with the contact forces
  removed_ = !walls;
  dies_removed_ = true;
  pad_step_ = 0; // (no longer the system's unknown, has_pad: the force-controlled die stays where the press left it)
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode ContactSet::BeginIncrement()
{
  PetscFunctionBeginUser;
  // Force scale of "zero" (grazing nodes): a millionth of the largest contact force.
  double fmax = 0;
  for (PetscInt node : candidates_)
    if (contact_[node]) fmax = std::max(fmax, fn_[node]);
  PetscCallMPI(MPI_Allreduce(&fmax, &f_small_, 1, MPI_DOUBLE, MPI_MAX, comm()));
  f_small_ *= kSmallForce;
  for (PetscInt node : candidates_) {
    if (!contact_[node]) continue;
    const Projection pr = tools_[tool_of_[node]].Project(Position(node));
    if (pr.segment < 0) {
      // Slid off the end of the tool: released, its force unloaded by the next steps (and reported).
      if (mesh_->node_owned[node]) slid_off_ = std::max(slid_off_, fn_[node]);
      contact_[node] = 0;
      Leave(node, 1.0);
      continue;
    }
    TakeFrame(node, tool_of_[node], pr);
    // The frame (l, n) must contain a symmetry plane's held direction; if not
    // (a node on y = 0 against an inclined flank), the node keeps the global
    // frame and both its components are prescribed.
    const Vec2 s = sym_dir_[node];
    const bool on_plane = s[0] != 0 || s[1] != 0;
    global_frame_[node] = on_plane && std::abs(std::abs(Dot(s, pr.l)) - 1) > kAxisTol;
    system_->SetFrame(node, global_frame_[node] ? 0.0 : std::atan2(pr.l[1], pr.l[0]));
  }
  if (has_pad()) PetscCall(PadForce(pad_start_));
  PetscFunctionReturn(PETSC_SUCCESS);
}

void ContactSet::ResetIterates()
{
  iteration_ = 0;
  // A new trial starts from the committed active set: releases decided for
  // an earlier trial of this increment (a longer step) are undone.
  for (PetscInt node : candidates_)
    if (released_[node]) contact_[node] = 1;
  std::fill(released_.begin(), released_.end(), 0);
  std::fill(frozen_.begin(), frozen_.end(), 0);
  // The first iterate is predicted in Constrain from the latest slip per unit stroke.
  predict_ = true;
  settled_ = true;
  fnk_ = fn_;
}

void ContactSet::LinearizeAtStart()
{
  iteration_ = 0;
  predict_ = false;
  std::fill(dxk_.begin(), dxk_.end(), 0.0);
  fnk_ = fn_;
}

PetscErrorCode ContactSet::Constrain(double dU)
{
  PetscFunctionBeginUser;
  if (has_pad()) system_->SetExtraUnknown(this);
  // Moving tool: the slip per unit stroke of the latest solution; static tool: the last increment's slip
  // (so too a force-controlled tool's nodes when the scene's stroke stands still: -die_force).
  if (predict_)
    for (PetscInt node : candidates_) dxk_[node] = !contact_[node] ? 0.0 : dU != 0 ? rate_[node] * dU : last_dx_[node];
  predict_ = false;
  for (PetscInt node : candidates_) {
    // Forces the tool no longer carries go to zero as loads: pending ones (a
    // node back in contact hands them to the tool again, through its normal
    // reaction), and the start force of a node released in this trial.
    Vec2 f = pending_[node];
    if (released_[node] && mesh_->node_owned[node]) {
      const Vec2 start = NodeForce(node, true);
      f = {f[0] + start[0], f[1] + start[1]};
    }
    if (f[0] != 0 || f[1] != 0) system_->AddForce(node, -f[0], -f[1]);
    if (!contact_[node]) continue;
    // Follow the tool along n and close any gap left by the last increment.
    // (A force-controlled tool's nodes: per unit of its motion as well, the system's extra unknown.)
    const double dn = Dot(Motion(node, dU), n_[node]) - gap_[node];
    const double unit = tools_[tool_of_[node]].Unknown() ? Dot(Direction(node), n_[node]) : 0.0;
    if (global_frame_[node]) {
      // du . n = dn with the held component zero: the free global component follows.
      const Vec2 s = sym_dir_[node];
      const int free = 1 - HeldComponent(s);
      system_->Prescribe(node, free, dn / n_[node][free], unit / n_[node][free]);
      continue; // the symmetry support itself is prescribed by the scene
    }
    system_->Prescribe(node, 1, dn, unit);
    if (!friction() || !SlipFree(node) || !mesh_->node_owned[node]) continue;
    const friction::RowTerms t = friction::Linearize(prm_.mu, prm_.vcri, fn_[node], fnk_[node], x_[node], dxk_[node],
                                                     Dot(Motion(node, dU), l_[node]), kappa_[node], TurnIn(node, dU));
    system_->AddRowCoupling(node, t.row_n_coeff);
    PetscCall(system_->AddFrameStiffness(node, t.diag));
    system_->AddFrameForce(node, t.rhs, 0.0);
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

double ContactSet::NormalIncrement(PetscInt node, double reaction_n, double s, double dU) const
{
  const double f_lk = SlipFree(node) ? friction::Force(prm_.mu, prm_.vcri, fnk_[node], x_[node] + dxk_[node]) : 0.0;
  return friction::NormalIncrement(reaction_n, kappa_[node], f_lk, s, TurnIn(node, dU));
}

double ContactSet::NormalReaction(PetscInt node, const PetscScalar *react) const
{
  const PetscInt o = mesh_->node_dof[node];
  if (!global_frame_[node]) return PetscRealPart(react[o + 1]);
  // Global frame: the free component's reaction is the normal force's share.
  const Vec2 s = sym_dir_[node];
  const int free = 1 - HeldComponent(s);
  return PetscRealPart(react[o + free]) / n_[node][free];
}

PetscErrorCode ContactSet::UpdateIterates(Vec du, double dU, bool &converged)
{
  const PetscScalar *d, *react;
  int local = 1, global;
  const double relax = ++iteration_ > kPlainIterations ? kRelax : 1.0;

  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(Log::friction, 0, 0, 0, 0));
  PetscCall(VecGetArrayRead(du, &d));
  PetscCall(VecGetArrayRead(system_->reactions_local(), &react));
  for (PetscInt node : candidates_) {
    if (!SlipFree(node)) continue;
    const double dx = Slip(node, Increment(d, node), dU);
    const double fn = fn_[node] + NormalIncrement(node, NormalReaction(node, react), dx, dU);
    const double before = friction::Force(prm_.mu, prm_.vcri, fnk_[node], x_[node] + dxk_[node]);
    const double after = friction::Force(prm_.mu, prm_.vcri, fn, x_[node] + dx);
    if (std::abs(after - before) > prm_.mu * prm_.tol * std::max(std::abs(fn), kFloorOfSmallForces * f_small_))
      local = 0;
    // Under-relaxed after a few iterations: the tanh law can make plain
    // iterates oscillate between sticking and sliding.
    dxk_[node] += relax * (dx - dxk_[node]);
    fnk_[node] += relax * (fn - fnk_[node]);
    if (dU != 0) rate_[node] = dx / dU;
  }
  PetscCall(VecRestoreArrayRead(system_->reactions_local(), &react));
  PetscCall(VecRestoreArrayRead(du, &d));
  PetscCallMPI(MPI_Allreduce(&local, &global, 1, MPI_INT, MPI_LAND, comm()));
  converged = global;
  settled_ = converged;
  PetscCall(PetscLogEventEnd(Log::friction, 0, 0, 0, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode ContactSet::ReleasePulled(Vec du, double dU, double release_fraction, bool apply, PetscInt &released)
{
  const PetscScalar *react, *d;
  PetscInt local = 0;
  PetscFunctionBeginUser;
  PetscCall(VecGetArrayRead(system_->reactions_local(), &react));
  PetscCall(VecGetArrayRead(du, &d));
  for (PetscInt node : candidates_) {
    if (!contact_[node]) {
      if (!released_[node] || !settled_) continue;
      // Where the released node ends, relative to the tool at the end of the
      // step: inside means the release was wrong (the node grazes the tool).
      // Judged on settled friction iterates only: a passing iterate can swing
      // the node through the tool and would hold it there for the trial.
      const Vec2 x = Position(node), u = Increment(d, node);
      const Vec2 t = Motion(node, dU); // of the tool it was released from
      const Vec2 end = {x[0] + u[0] - t[0], x[1] + u[1] - t[1]};
      const Projection pr = tools_[tool_of_[node]].Project(end);
      if (pr.segment < 0 || pr.gap >= 0) continue;
      local += mesh_->node_owned[node];
      if (apply) contact_[node] = frozen_[node] = 1, released_[node] = 0;
      continue;
    }
    // Only a clear pull counts: a grazing node (force ~ 0 either way) stays.
    // The node's state (force, slip) is kept until the increment is committed.
    const double dfn = NormalIncrement(node, NormalReaction(node, react), Slip(node, Increment(d, node), dU), dU);
    // A node whose force is zero to the resolution of the forces (equilibrium
    // iterations balance them to -equilibrium_tol) is released rather than
    // cutting the step at its force's zero.
    const double zero = std::max(f_small_, resolution_);
    if (!frozen_[node] && dfn < -zero && fn_[node] <= std::max(release_fraction * -dfn, resolution_)) {
      local += mesh_->node_owned[node];
      if (apply) contact_[node] = 0, released_[node] = 1;
    }
  }
  PetscCall(VecRestoreArrayRead(du, &d));
  PetscCall(VecRestoreArrayRead(system_->reactions_local(), &react));
  PetscCall(MPIU_Allreduce(&local, &released, 1, MPIU_INT, MPI_SUM, comm()));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode ContactSet::LimitStep(Vec du, double dU, StepLimit &limit)
{
  const PetscScalar *d, *react;
  StepLimit touch, leave, stick, slide;

  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(Log::contact, 0, 0, 0, 0));
  PetscCall(VecGetArrayRead(du, &d));
  PetscCall(VecGetArrayRead(system_->reactions_local(), &react));
  for (PetscInt node : candidates_) {
    const PetscInt id = mesh_->node_orig[node];
    const Vec2 u = Increment(d, node);
    r4_[node] = r5_[node] = kNever;
    if (!contact_[node]) {
      // r4: exact first touch along the increment. A node released in this
      // trial starts on the surface: where it ends is checked by ReleasePulled.
      if (released_[node]) continue;
      bool first = true;
      for (int k = 0; k < (int)tools_.size(); ++k) {
        if (!MayTouch(node, k)) continue;
        const double r = tools_[k].FirstContact(Position(node), u, Step(k, dU));
        if (first || r < r4_[node]) r4_[node] = r, touch_[node] = k;
        first = false;
      }
      touch.Offer(r4_[node], Limiter::Contact, id);
      continue;
    }
    // r5: the normal force reaches zero.
    const double dfn = NormalIncrement(node, NormalReaction(node, react), Slip(node, u, dU), dU);
    if (dfn < -std::max(f_small_, resolution_) && !frozen_[node])
      r5_[node] = std::max(fn_[node], 0.0) / -dfn; // a grazing node held for this step does not limit
    leave.Offer(r5_[node], Limiter::Separation, id);
    // r6: slide to stick, the friction mobilization f_l / (mu f_n) falls by at most
    // dphi_max; stick to slide, its magnitude rises by at most dphi_rise.
    if (friction() && SlipFree(node)) {
      const double s = Slip(node, u, dU);
      stick.Offer(friction::StickFactor(x_[node], s, prm_.vcri, prm_.dphi_max), Limiter::Stick, id);
      slide.Offer(friction::SlideFactor(x_[node], s, prm_.vcri, prm_.dphi_rise), Limiter::Slide, id);
    }
  }
  PetscCall(VecRestoreArrayRead(system_->reactions_local(), &react));
  PetscCall(VecRestoreArrayRead(du, &d));
  for (StepLimit *l : {&touch, &leave, &stick, &slide}) {
    PetscCall(ReduceStepLimit(comm(), *l));
    limit.Offer(l->r, l->who, l->where);
  }
  // r3 for a turning tool (the same on every rank): its turn is taken linear in the step, as the body's rotations.
  for (int k = 0; k < (int)tools_.size(); ++k)
    limit.Offer(RotationFactor(tools_[k].Spin() * Step(k, dU), prm_.turn_max), Limiter::Rotation, -1);
  PetscCall(PetscLogEventEnd(Log::contact, 0, 0, 0, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

void ContactSet::Leave(PetscInt node, double share)
{
  // A force below the scale of zero stays zero (round-off of an exact r5 event).
  const Vec2 f = NodeForce(node, true);
  if (!balanced_ && mesh_->node_owned[node] && share * std::hypot(f[0], f[1]) > f_small_)
    for (int k = 0; k < 2; ++k) pending_[node][k] += share * f[k];
  fn_[node] = x_[node] = 0;
}

void ContactSet::TakeFrame(PetscInt node, int k, const Projection &pr)
{
  tool_of_[node] = k;
  segment_[node] = pr.segment;
  n_[node] = pr.n;
  l_[node] = pr.l;
  gap_[node] = pr.gap;
  kappa_[node] = pr.curvature;
}

PetscErrorCode ContactSet::Commit(Vec du, double dU, double r, ContactCommit &report)
{
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(Log::contact, 0, 0, 0, 0));
  pad_step_ *= r; // (the force-controlled tool's motion in the solution, scaled as du was)
  PetscCall(CommitForces(du, dU, r, report));
  // The tools have moved by dU with the increment (a force-controlled one by its own step).
  for (int k = 0; k < (int)tools_.size(); ++k) tools_[k].stroke += Step(k, dU);
  PetscCall(TakeMovedFrames(report));
  PetscCall(PetscLogEventEnd(Log::contact, 0, 0, 0, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode ContactSet::CommitForces(Vec du, double dU, double r, ContactCommit &report)
{
  const PetscScalar *d, *react;
  double local[3] = {0, 0, slid_off_}, global[3]; // friction work; tension, force dropped (maxima)
  const double event = r * (1 + prm_.group_tol);

  PetscFunctionBeginUser;
  PetscCall(VecGetArrayRead(du, &d));
  PetscCall(VecGetArrayRead(system_->reactions_local(), &react));
  for (PetscInt node : candidates_) {
    const bool owned = mesh_->node_owned[node];
    // The step removed the share r of the pending force.
    for (int k = 0; k < 2; ++k) pending_[node][k] *= 1 - r;
    if (contact_[node]) {
      const double fl_old = friction::Force(prm_.mu, prm_.vcri, fn_[node], x_[node]);
      // (the body has moved: the tool's point where the node touched it at the step's start, as the solve took it)
      const Vec2 u = Increment(d, node), p = Position(node);
      const double dx = SlipFrom(node, u, dU, {p[0] - u[0], p[1] - u[1]});
      fn_[node] += NormalIncrement(node, r * NormalReaction(node, react), dx, dU);
      if (SlipFree(node)) {
        x_[node] = friction::Cap(x_[node] + dx, prm_.vcri);
        last_dx_[node] = dx;
        const double fl_new = friction::Force(prm_.mu, prm_.vcri, fn_[node], x_[node]);
        if (owned) local[0] -= 0.5 * (fl_old + fl_new) * dx; // dissipated by sliding
      }
      if (owned) local[1] = std::max(local[1], -fn_[node]); // measured before any release
      // r5: released when its normal force has reached zero in the step, or
      // ends it below the force scale of zero (a re-solved step's end, a
      // grazing node held for the step in tension); what force is left is
      // unloaded by the next steps.
      if (r5_[node] <= event || fn_[node] < -std::max(f_small_, resolution_)) {
        if (owned) local[2] = std::max(local[2], fn_[node]);
        contact_[node] = 0;
        Leave(node, 1.0);
      }
    } else if (released_[node]) {
      // Released in this step (pulled off without force): the step removed
      // the share r of its start force.
      if (owned) local[2] = std::max(local[2], fn_[node]);
      Leave(node, 1 - r);
      released_[node] = 0;
    } else if (r4_[node] <= event) {
      contact_[node] = 1;
      tool_of_[node] = touch_[node];
      fn_[node] = x_[node] = rate_[node] = 0;
    }
  }
  PetscCall(VecRestoreArrayRead(system_->reactions_local(), &react));
  PetscCall(VecRestoreArrayRead(du, &d));
  PetscCallMPI(MPI_Allreduce(&local[0], &global[0], 1, MPI_DOUBLE, MPI_SUM, comm()));
  PetscCallMPI(MPI_Allreduce(&local[1], &global[1], 2, MPI_DOUBLE, MPI_MAX, comm()));
  report.w_friction = global[0];
  report.tension = global[1];
  report.release_force = global[2];
  slid_off_ = 0;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode ContactSet::TakeMovedFrames(ContactCommit &report)
{
  double worst[2] = {0, 0}, global_worst[2]; // gap of a contact node, penetration

  PetscFunctionBeginUser;
  for (PetscInt node : candidates_) {
    int k = tool_of_[node];
    const Projection pr = contact_[node] ? tools_[k].Project(Position(node)) : ProjectNearest(node, k);
    if (pr.segment < 0) continue;
    if (!contact_[node] && pr.gap <= prm_.gap_tol) {
      contact_[node] = 1;
      fn_[node] = x_[node] = 0;
    }
    if (contact_[node])
      TakeFrame(node, k, pr);
    else
      gap_[node] = pr.gap, tool_of_[node] = k;
    if (!mesh_->node_owned[node]) continue;
    if (contact_[node]) worst[0] = std::max(worst[0], pr.gap);
    worst[1] = std::max(worst[1], -pr.gap);
  }
  PetscCallMPI(MPI_Allreduce(worst, global_worst, 2, MPI_DOUBLE, MPI_MAX, comm()));
  report.gap = global_worst[0];
  report.penetration = global_worst[1];
  PetscFunctionReturn(PETSC_SUCCESS);
}

} // namespace tf
