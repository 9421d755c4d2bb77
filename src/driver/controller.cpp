#include "tubeform/driver/controller.hpp"

#include <algorithm>
#include <vector>

namespace tf {

Controller::Controller(Model &model, Scene &scene, Inertia *inertia, const Options &opt, double duration)
    : m_(model), scene_(scene), inertia_(inertia), opt_(opt), duration_(duration)
{}

PetscErrorCode Controller::Solve(double lambda, double dl, Vec du, double &dU, Increment &inc)
{
  std::vector<double> reactions;

  PetscFunctionBeginUser;
  const double dt = InertiaActive() ? dl * duration_ : 0.0;
  // K of the state at the start of the increment (+ M / dt^2), then the loads:
  // the tools' prescribed motion and friction rows first, the scene's supports
  // and loads, the inertia load, the carried out-of-balance force.
  PetscCall(m_.system.Begin());
  PetscCall(m_.body.AssembleTangent(m_.system));
  if (dt > 0) PetscCall(inertia_->AddMass(m_.system, dt));
  dU = scene_.ToolStroke(lambda + dl) - scene_.ToolStroke(lambda);
  if (ContactActive()) PetscCall(m_.contact->Constrain(dU));
  PetscCall(scene_.Load(m_, lambda, dl));
  if (dt > 0) inertia_->AddLoad(m_.system, dt);
  if (opt_.residual_correction) PetscCall(m_.system.AddFreeForce(f_res_));
  PetscCall(m_.system.Solve(du, reactions));
  ++inc.solves;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Controller::SolveTrial(double lambda, double dl, Vec du, bool last, Trial &t, Increment &inc)
{
  PetscInt switches = 0;

  PetscFunctionBeginUser;
  t = Trial{};
  // A contact node whose force would vanish within this fraction of the step
  // is released in the trial rather than cutting it: round-off quasi-statically,
  // the shortest step inertia allows otherwise.
  const double release = InertiaActive() ? std::max(kReleaseWithin, MinStepFraction(dl)) : kReleaseWithin;
  if (ContactActive()) m_.contact->ResetIterates();
  // Re-solve until nothing changes: friction forces linearized about the last
  // iterate, points whose loading state (alpha) disagreed with the last
  // solution switched (at most -rmin_max_redo times), contact nodes pulled off
  // without force released.
  for (PetscInt it = 0;; ++it) {
    PetscCall(Solve(lambda, dl, du, t.dU, inc));
    bool converged = true;
    if (Iterative()) PetscCall(m_.contact->UpdateIterates(du, t.dU, converged));
    t.limit = StepLimit{};
    const bool may_switch = t.redo < opt_.rmin_max_redo;
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
    if (it < opt_.friction_max_iters + opt_.rmin_max_redo) continue;
    // -dynamics auto before the switch: the caller turns inertia on instead.
    if (!last || (opt_.dynamics == Dynamics::Auto && !InertiaActive())) {
      t.settled = false;
      PetscFunctionReturn(PETSC_SUCCESS);
    }
    // The shortest step still wanders (friction iterates drifting along a
    // nearly free slip mode, or a loading switch cycle): it is solved once
    // more the paper's way, the friction linearized about the start of the
    // increment with the trial's active sets, and that solution is taken
    // (r4-r6 and r1 still limit it). Counted (history column `unsettled`).
    ++inc.unsettled;
    if (ContactActive()) m_.contact->LinearizeAtStart();
    PetscCall(Solve(lambda, dl, du, t.dU, inc));
    t.limit = StepLimit{};
    PetscCall(m_.body.ScanTrial(du, false, t.limit, switches, t.transitions));
    t.left = switches;
    break;
  }
  if (ContactActive()) PetscCall(m_.contact->LimitStep(du, t.dU, t.limit));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Controller::SettledTrial(double lambda, double &dl, Vec du, Trial &t, Increment &inc)
{
  PetscFunctionBeginUser;
  for (int cut = 0;;) {
    PetscCall(SolveTrial(lambda, dl, du, cut == kMaxCuts, t, inc));
    inc.redo += t.redo;
    if (t.settled) break;
    if (cut == kMaxCuts) {
      // -dynamics auto: quasi-static steps cannot settle here; inertia from
      // now on, and this (shortest) step solved again with it.
      inertia_->Activate();
      PetscCall(PetscPrintf(m_.comm,
                            "tubeform: friction iterations do not settle at lambda %.6g: inertia on from here "
                            "(-dynamics auto, docs/theory.md \"Inertia\")\n",
                            lambda));
      continue;
    }
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
  const bool resolve = r < 1.0 && (Iterative() || InertiaActive() || t.transitions > 0);
  if (resolve) {
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
    double taken = r;
    for (int attempt = 1;; ++attempt) {
      dl *= taken;
      m_.body.ScaleTransitions(taken);
      PetscCall(SettledTrial(lambda, dl, du, t, inc));
      if (t.limit.r >= 1.0 - opt_.rmin_event_tol) break;
      taken = attempt < kMaxResolves ? t.limit.r : std::min(t.limit.r, 0.5);
      if (InertiaActive()) taken = std::max(taken, MinStepFraction(dl));
      if (taken >= 1.0) break;
      PetscCheck(dl * taken > kMinRmin * dl_trial, m_.comm, PETSC_ERR_NOT_CONVERGED,
                 "r_min = %g (%s at %d) at lambda = %g: the re-solved increment cannot meet its limits",
                 dl * taken / dl_trial, LimiterName((int)t.limit.who), (int)t.limit.where, lambda);
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
  inc.event_inside = resolve && t.limit.r < 1.0 - opt_.rmin_event_tol;
  PetscFunctionReturn(PETSC_SUCCESS);
}

} // namespace tf
