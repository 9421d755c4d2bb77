#include "tubeform/driver/controller.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "tubeform/core/signals.hpp"

namespace tf {

Controller::Controller(Model &model, Scene &scene, Inertia *inertia, const Options &opt, double duration,
                       PetscInt &iterate_tangent)
    : m_(model), scene_(scene), inertia_(inertia), opt_(opt), duration_(duration), iterate_tangent_(iterate_tangent)
{
  if (Equilibrium()) {
    iter_ = m_.system.CreateLocalVector();
    f_trial_ = m_.system.CreateLocalVector();
    prev_ = m_.system.CreateLocalVector();
  }
}

Controller::~Controller()
{
  (void)VecDestroy(&iter_);
  (void)VecDestroy(&f_trial_);
  (void)VecDestroy(&prev_);
}

PetscErrorCode Controller::TrialState(Vec du)
{
  double sums[2], global[2];
  PetscFunctionBeginUser;
  PetscCall(m_.body.TrialForce(du, 1.0, f_trial_, &sums[0], &sums[1]));
  PetscCall(MPIU_Allreduce(sums, global, 2, MPIU_REAL, MPIU_SUM, m_.comm));
  q_iter_ = global[0] / std::max(global[1], 1.0);
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Controller::Solve(double lambda, double dl, Vec du, double &dU, Increment &inc)
{
  std::vector<double> reactions;

  PetscFunctionBeginUser;
  // A stop signal, agreed on by the ranks (one may see it before another),
  // drops the increment at its next solve: a batch system's SIGKILL follows
  // its SIGTERM within a second or two (mpirun's), and the rest of an
  // increment of many solves may take longer. With -checkpoint the increment
  // ends first (Problem::StopBefore), so that the checkpoint holds a whole state.
  if (opt_.checkpoint.empty()) {
    int mine = StopSignal(), any;
    PetscCallMPI(MPI_Allreduce(&mine, &any, 1, MPI_INT, MPI_MAX, m_.comm));
    PetscCheck(!any, m_.comm, PETSC_ERR_SIG, "interrupted by %s", SignalName(any));
  }
  const double dt = InertiaActive() ? dl * duration_ : 0.0;
  // K of the state at the start of the increment (+ M / dt^2), then the loads:
  // the tools' prescribed motion and friction rows first, the scene's supports
  // and loads, the inertia load; for an equilibrium iterate, the start's forces
  // against the iterate's internal force.
  // The state of the last iterate with this assembly's element state: QM6's
  // modes follow the condensation of the tangent just assembled (points that
  // changed their loading state change it), so the forces and K agree.
  // With midpoint kinematics a correction's tangent is taken at its iterate
  // where the start's is off (a term of the order of the strain increment,
  // which the bulk modulus of a nearly incompressible wall makes as large as
  // the rest: docs/theory.md, 5a), from the iterate's forces.
  const bool iterate = Equilibrium() && have_iter_;
  PetscCall(m_.system.Begin());
  if (iterate && (iterate_tangent_ || m_.body.IterateTangent())) {
    PetscCall(m_.body.UpdateTangents(m_.system));
    PetscCall(TrialState(iter_));
    PetscCall(m_.body.AssembleIterateTangent(m_.system));
  } else {
    PetscCall(m_.body.AssembleTangent(m_.system));
    if (iterate) PetscCall(TrialState(iter_));
  }
  if (dt > 0) PetscCall(inertia_->AddMass(m_.system, dt));
  dU = scene_.ToolStroke(lambda + dl) - scene_.ToolStroke(lambda);
  if (ContactActive()) {
    m_.contact->SetPadTarget(scene_.ToolForce(lambda), scene_.ToolForce(lambda + dl), std::min(1.0, dl / dl_trial_));
    PetscCall(m_.contact->Constrain(dU));
  }
  PetscCall(scene_.Load(m_, lambda, dl));
  if (dt > 0) inertia_->AddLoad(m_.system, dt);
  if (Equilibrium() && have_iter_) {
    // Newton on the increment. The first solve is the paper's incremental step
    // (the start's own out-of-balance, within the tolerance, is not chased:
    // in a step many times shorter than the trial it would dominate the
    // solution and turn points' loading states over). Then the loads of the
    // start and of the step balance the internal force of the last iterate,
    // and an iterate whose largest out-of-balance force is within
    // -equilibrium_tol of the time-averaged nodal force (this state's counted
    // in) is taken.
    PetscCall(m_.system.AddForces(f_start_));
    PetscCall(m_.system.AddForces(f_trial_, -1.0));
    const double q = (q_sum_ + q_iter_) / (q_count_ + 1);
    m_.system.SetIterate(iter_, opt_.driver.equilibrium_tol * q, reject_above_);
  }
  PetscCall(m_.system.Solve(du, reactions));
  // An iterate in balance is taken exactly as it was evaluated (the system's
  // copy went through the node frames and back).
  if (Equilibrium() && have_iter_ && m_.system.accepted()) {
    PetscCall(VecCopy(iter_, du));
    SetPadStep(pad_iter_);
  }
  m_.system.SetIterate(nullptr, 0);
  ++inc.solves;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Controller::SolveTrial(double lambda, double dl, Vec du, bool last, Trial &t, Increment &inc)
{
  PetscInt switches = 0;

  PetscFunctionBeginUser;
  t = Trial{};
  const double release = ReleaseWithin(dl);
  if (ContactActive()) m_.contact->ResetIterates();
  Iterating(false);
  // Re-solve until nothing changes: friction forces linearized about the last
  // iterate, points whose loading state (alpha) disagreed with the last
  // solution switched (at most -rmin_max_redo times), contact nodes pulled off
  // without force released.
  for (PetscInt it = 0;; ++it) {
    PetscCall(Solve(lambda, dl, du, t.dU, inc));
    bool converged = true;
    if (Iterative()) PetscCall(m_.contact->UpdateIterates(du, t.dU, converged));
    t.limit = StepLimit{};
    const bool may_switch = t.redo < opt_.driver.rmin_max_redo;
    PetscCall(m_.body.ScanTrial(du, may_switch, t.limit, switches, t.transitions));
    // Contact releases always apply: they are finite by construction (a node
    // is released at most once per trial and a grazing one then stays), and a
    // node left in contact in tension would carry a wrong force.
    PetscInt released = 0;
    if (ContactActive()) PetscCall(m_.contact->ReleasePulled(du, t.dU, release, true, released));
    const bool material = switches > 0 && may_switch;
    if (material) ++t.redo;
    t.left = may_switch ? 0 : switches;
    if (converged && !material && released == 0) break;
    // With equilibrium iterations one solve locates the events: the iterations
    // of the step that will be taken settle friction and loading states too.
    if (Equilibrium()) break;
    if (it < opt_.driver.friction_max_iters + opt_.driver.rmin_max_redo) continue;
    // -dynamics auto before the switch: the caller turns inertia on instead.
    if (!last || AutoBeforeInertia()) {
      t.settled = false;
      PetscFunctionReturn(PETSC_SUCCESS);
    }
    // The shortest step still wanders (friction iterates drifting along a
    // nearly free slip mode, or a loading switch cycle): taken unsettled.
    PetscCall(SolveUnsettled(lambda, dl, du, t, inc));
    PetscFunctionReturn(PETSC_SUCCESS); // (no equilibrium iterations either)
  }
  if (ContactActive()) PetscCall(m_.contact->LimitStep(du, t.dU, t.limit));
  // A step that will be taken (its first event within -rmin_event_tol of its
  // end) is brought into balance; one that r_min will cut is not: its solution
  // only locates the events.
  if (Equilibrium() && t.limit.r >= 1.0 - opt_.driver.rmin_event_tol) {
    const Trial solved = t;
    PetscCall(Balance(lambda, dl, du, t, inc));
    if (!t.settled && last) {
      // The shortest step does not balance: taken unsettled, from the active
      // set of the located events (the iterations' releases undone).
      t = solved;
      if (ContactActive()) m_.contact->ResetIterates();
      PetscCall(SolveUnsettled(lambda, dl, du, t, inc));
    }
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Controller::SolveUnsettled(double lambda, double dl, Vec du, Trial &t, Increment &inc)
{
  PetscInt switches = 0;
  PetscFunctionBeginUser;
  ++inc.unsettled;
  if (ContactActive()) m_.contact->LinearizeAtStart();
  PetscCall(Solve(lambda, dl, du, t.dU, inc));
  t.limit = StepLimit{};
  PetscCall(m_.body.ScanTrial(du, false, t.limit, switches, t.transitions));
  t.left = switches;
  if (ContactActive()) PetscCall(m_.contact->LimitStep(du, t.dU, t.limit));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Controller::Balance(double lambda, double dl, Vec du, Trial &t, Increment &inc)
{
  PetscInt switches = 0;

  PetscFunctionBeginUser;
  const double release = ReleaseWithin(dl);
  PetscCall(VecCopy(du, iter_));
  pad_iter_ = PadStep();
  Iterating(true);
  double first = -1, previous = PETSC_MAX_REAL;
  int backtracks = 0;
  for (PetscInt it = 0;; ++it) {
    // A correction that does not reduce the out-of-balance force is halved
    // back towards the point it started from (a line search): along a soft
    // mode of the tangent (a plastic hinge near collapse) the full step overshoots.
    reject_above_ = backtracks < kBacktracks ? previous : PETSC_MAX_REAL;
    PetscCall(Solve(lambda, dl, du, t.dU, inc));
    const double residual = m_.system.iterate_residual();
    if (m_.system.accepted()) {
      // The last iterate (= du) is in balance. Its own reactions may still
      // pull a node off the tool (the corrections moved its force past zero
      // after the last release check): released, and the iterations go on
      // without it. Left in contact it would end every step at its force's
      // zero (r5 = 0), and the step would shrink to nothing.
      PetscInt released = 0;
      if (ContactActive()) PetscCall(m_.contact->ReleasePulled(du, t.dU, release, true, released));
      if (released == 0) break;
      // (the iterate is unchanged: no correction of it to halve back)
      previous = PETSC_MAX_REAL, backtracks = 0;
      PetscCall(VecCopy(iter_, prev_));
      pad_prev_ = pad_iter_;
      ++inc.balance;
      continue;
    }
    if (!m_.system.solved()) {
      ++backtracks;
      PetscCall(VecAXPBY(iter_, 0.5, 0.5, prev_)); // halfway back to where the correction started
      pad_iter_ = 0.5 * (pad_iter_ + pad_prev_);
      SetPadStep(pad_iter_);
      continue;
    }
    backtracks = 0;
    if (first < 0) first = residual;
    // Iterations that do not converge (the step crosses too much non-linearity:
    // many points changing their loading state at once) leave the step to be
    // halved, as unsettled friction does.
    if (residual > kDivergence * first || it >= opt_.driver.friction_max_iters) {
      t.settled = false;
      Iterating(false);
      PetscFunctionReturn(PETSC_SUCCESS);
    }
    previous = residual;
    PetscCall(VecCopy(iter_, prev_));
    pad_prev_ = pad_iter_;
    bool converged = true;
    if (Iterative()) PetscCall(m_.contact->UpdateIterates(du, t.dU, converged));
    t.limit = StepLimit{};
    PetscCall(m_.body.ScanTrial(du, true, t.limit, switches, t.transitions));
    PetscInt released = 0;
    if (ContactActive()) PetscCall(m_.contact->ReleasePulled(du, t.dU, release, true, released));
    ++inc.balance;
    PetscCall(VecCopy(du, iter_));
    pad_iter_ = PadStep();
  }
  Iterating(false);
  reject_above_ = PETSC_MAX_REAL;
  if (ContactActive()) PetscCall(m_.contact->LimitStep(du, t.dU, t.limit));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Controller::InertiaOn(double lambda, const char *why)
{
  PetscFunctionBeginUser;
  inertia_->Activate();
  PetscCall(PetscPrintf(
    m_.comm, "tubeform: %s at lambda %.6g: inertia on from here (-dynamics auto, docs/theory.md \"Inertia\")\n", why,
    lambda));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Controller::IterateTangentOn(double lambda)
{
  PetscFunctionBeginUser;
  // A step halved kMaxCuts times still out of balance with the start's tangent (only inertia halves further):
  // rotations inside the step that the start's configuration does not see (a wall snapping through). The iterate's
  // tangent from here on, for the run: the snapping release of the paper's thinnest tube balances with it in a
  // quarter of the solves, and in energy (docs/theory.md, 5a).
  iterate_tangent_ = 1;
  PetscCall(PetscPrintf(m_.comm,
                        "tubeform: a step halved %d times still out of balance at lambda %.6g: the equilibrium "
                        "corrections take their iterate's tangent from here (docs/theory.md, 5a)\n",
                        kMaxCuts, lambda));
  PetscFunctionReturn(PETSC_SUCCESS);
}

void Controller::Iterating(bool on)
{
  have_iter_ = on;
  m_.body.StepTangents(on);
}

PetscErrorCode Controller::SettledTrial(double lambda, double &dl, Vec du, Trial &t, Increment &inc)
{
  PetscFunctionBeginUser;
  for (int cut = 0;;) {
    const int max_cuts = MaxCuts(InertiaActive());
    PetscCall(SolveTrial(lambda, dl, du, cut == max_cuts, t, inc));
    inc.redo += t.redo;
    inc.deep = t.settled && cut > kMaxCuts;
    if (t.settled) break;
    if (cut >= kMaxCuts && !iterate_tangent_ && Equilibrium() && m_.body.MidpointKinematics())
      PetscCall(IterateTangentOn(lambda));
    if (cut == max_cuts && AutoBeforeInertia()) {
      // -dynamics auto: quasi-static steps cannot settle here; inertia from
      // now on, and this (shortest) step solved again with it.
      PetscCall(InertiaOn(lambda, "friction iterations do not settle"));
      continue;
    }
    if (cut == max_cuts) break; // (SolveTrial takes the last try whatever it finds)
    dl *= 0.5;
    m_.body.ScaleTransitions(0.5);
    ++cut;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Controller::Advance(double lambda, double dl, double end, Vec du, Increment &inc)
{
  Trial t;

  PetscFunctionBeginUser;
  inc = Increment{};
  const double dl_trial = dl;
  dl_trial_ = dl;
  m_.body.ResetTransitions();
  // 1. The trial step and its r_min = min(1, r1..r6).
  PetscCall(SettledTrial(lambda, dl, du, t, inc));
  inc.who = lambda + dl >= end - kLambdaTol ? Limiter::Final : Limiter::Trial;
  double r = 1.0;
  if (t.limit.r < 1.0) r = t.limit.r, inc.who = t.limit.who, inc.where = t.limit.where;
  if (InertiaActive()) r = std::min(1.0, std::max(r, MinStepFraction(dl)));
  PetscCheck(r > kMinRmin, m_.comm, PETSC_ERR_NOT_CONVERGED,
             "r_min = %g (%s at %d) at lambda = %g: the increment cannot advance", r, LimiterName((int)t.limit.who),
             (int)t.limit.where, lambda);
  // Points yielding inside the step (-rmin_yield inside) make it non-linear in r too.
  // So does equilibrium: a scaled solution is out of balance.
  const bool resolve = r < 1.0 && (Iterative() || InertiaActive() || t.transitions > 0 || Equilibrium());
  if (resolve) {
    bool stuck = false;
    PetscCall(ResolveCut(lambda, r, dl_trial, dl, du, t, inc, stuck));
    if (stuck) {
      // -dynamics auto: quasi-static steps cannot meet this event (a node touching and leaving the die by turns);
      // inertia from now on, and the increment again with it.
      PetscCall(InertiaOn(lambda, "the cut step does not meet its limits"));
      PetscCall(Advance(lambda, dl_trial, end, du, inc));
      PetscFunctionReturn(PETSC_SUCCESS);
    }
  } else {
    // 2b. A linear step: the solution scaled by r is the solution of the scaled step.
    PetscCall(VecScale(du, r));
    inc.scale = r;
    dl *= r;
  }
  inc.dl = dl;
  inc.r = dl / dl_trial;
  inc.dU = inc.scale * t.dU;
  inc.inconsistent = t.left;
  // A scaled step ends at its first event; a re-solved one may end past one:
  // within -rmin_event_tol that is the event's location tolerance, beyond it
  // (inertia's shortest step) a compromise.
  inc.event_inside = resolve && t.limit.r < 1.0 - opt_.driver.rmin_event_tol;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Controller::ResolveCut(double lambda, double r, double dl_trial, double &dl, Vec du, Trial &t,
                                      Increment &inc, bool &stuck)
{
  PetscFunctionBeginUser;
  // 2a. Friction is not linear in r, nor is inertia (M / dt^2): the
  // shortened step is solved again, and again while the re-solve still finds
  // an event or a bound more than -rmin_event_tol inside it (the
  // non-linearity moves them). The step taken meets its limits: with inertia
  // the response can grow much faster than the step (K + M / dt^2 nearly
  // singular at some dt, as when a tube snaps), and a step taken past a
  // rotation bound there moves the tube by millimetres with no equilibrium.
  // After kMaxResolves tries each cut at least halves the step, so the search
  // ends; only inertia's shortest step is taken as it is (a compromise,
  // counted). The last solution is taken unscaled (scaling it would break
  // the friction forces' equilibrium).
  double taken = r, within = 0, past = dl; // the longest step found within its limits, the shortest past them
  int grows = 0;
  for (int attempt = 1;; ++attempt) {
    dl *= taken;
    m_.body.ScaleTransitions(taken);
    PetscCall(SettledTrial(lambda, dl, du, t, inc));
    if (t.limit.r >= 1.0 - opt_.driver.rmin_event_tol) {
      // Within its limits. With inertia, far within: lengthened (kGrowAbove).
      // (Only a step cut by a bound on its size, r2 or r3: an event is where
      // it is, and a re-solved step ends at it.)
      const bool bound = inc.who == Limiter::Strain || inc.who == Limiter::Rotation;
      if (!InertiaActive() || !bound || grows >= kMaxGrows || t.limit.r < kGrowAbove || dl > kGrowBelow * dl_trial)
        break;
      within = dl, ++grows;
      taken = std::min({t.limit.r, kGrowFactor, std::sqrt(past / dl)});
      if (taken < kGrowAbove) break;
      continue;
    }
    past = std::min(past, dl);
    if (within > 0) {
      // A lengthened step went past its limits: back to the last one within, as it was.
      taken = within / dl, grows = kMaxGrows, within = 0;
      continue;
    }
    taken = attempt < kMaxResolves ? t.limit.r : std::min(t.limit.r, 0.5);
    if (InertiaActive()) taken = std::max(taken, MinStepFraction(dl));
    if (taken >= 1.0) break;
    if (dl * taken <= kMinRmin * dl_trial && AutoBeforeInertia()) {
      stuck = true;
      break;
    }
    PetscCheck(dl * taken > kMinRmin * dl_trial, m_.comm, PETSC_ERR_NOT_CONVERGED,
               "r_min = %g (%s at %d) at lambda = %g: the re-solved increment cannot meet its limits",
               dl * taken / dl_trial, LimiterName((int)t.limit.who), (int)t.limit.where, lambda);
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

} // namespace tf
