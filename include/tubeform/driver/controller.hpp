// The increment controller of docs/theory.md, sections 5 and 5a: solves a trial step,
// iterates friction and loading switches inside it, halves it when the
// iterations do not settle, and cuts it by r_min (paper eq. 16) — by scaling
// the linear solution, or, where the step is not linear in r (friction,
// inertia), by solving the shortened step again. It returns what it took;
// the driver commits it.
#pragma once

#include <petscvec.h>

#include <algorithm>

#include "tubeform/body/inertia.hpp"
#include "tubeform/io/options.hpp"
#include "tubeform/scenes/scene.hpp"
#include "tubeform/step/rmin.hpp"

namespace tf {

// Equilibrium iterations whose out-of-balance force grows to this many times
// their first are diverging: the step is halved instead.
constexpr double kDivergence = 10;
// Halvings of a correction that does not reduce the out-of-balance force.
constexpr int kBacktracks = 3;
// Halvings of a trial step whose iterations do not settle; the last is taken unsettled. With inertia a step short
// enough is dominated by the mass (M / dt^2 grows as 1 / dt^2) and balances, as through the snap of a thin wall's
// springback: halvings down to about 1e-6 of the trial (kMinDynamicStep, below).
constexpr int kMaxCuts = 6, kMaxCutsInertia = 20;
inline int MaxCuts(bool inertia) { return inertia ? kMaxCutsInertia : kMaxCuts; }
// Steps that settled only past kMaxCuts halvings are balanced, but a run of them creeps on at 1e-6 of a step: this
// many in a row count as one unsettled step towards -friction_max_unsettled (50: a thousand in a row). The
// figures' R/t 50 tube at mu 0.35 passes a run of more than 50 of them and goes on at full steps.
constexpr int kDeepPerUnsettled = 20;
// Re-solves of a shortened non-linear step that go to its limits' estimate; later ones at least halve it.
constexpr int kMaxResolves = 3;
// Inertia: a re-solved step cut by a bound on its size (r2, r3) and well
// inside its limits (at least kGrowAbove times its length away) is lengthened, at most kGrowFactor
// times and at most halfway (geometrically) to the shortest step found past
// them, up to kMaxGrows times. A step cut from the trial's linear scaling can
// be orders of magnitude too short there: near a snap K + M / dt^2 is nearly
// singular at the trial's dt and dominated by the mass at the cut one.
constexpr double kGrowAbove = 2;
// ... when it is this fraction of its trial step or less: there M / dt^2 is a
// million times its value at the trial's dt (a step cut by an event near its
// trial length is solved to the event, as it was).
constexpr double kGrowBelow = 1e-3;
constexpr double kGrowFactor = 10;
constexpr int kMaxGrows = 4;
// -dynamics implicit: no step shorter than this fraction of the trial step.
// Events closer than that (a node whose normal force is all but zero, a point
// a hair from the yield surface) are taken with it; shorter steps would make
// M / dt^2 swamp K (precision) for no gain in resolution.
constexpr double kMinDynamicStep = 1e-6;
// A step cut below this fraction of its trial step cannot advance the load path.
constexpr double kMinRmin = 1e-10;

// One increment as the controller took it.
struct Increment {
  double dl = 0;                // load step taken (of lambda)
  double r = 1;                 // r_min: the step taken as a fraction of the increment's trial step
  Limiter who = Limiter::Trial; // what set r
  PetscInt where = -1;          // element or node (input numbering) of the limiter
  double scale = 1;             // the step taken is the last solution scaled by this (1: re-solved):
                                // its reactions scale with it, its events up to it happen
  double dU = 0;                // tool step of the step taken
  PetscInt solves = 0;          // factorizations, friction iterations and re-solves included
  PetscInt redo = 0;            // re-solves for loading/unloading switches
  PetscInt unsettled = 0;       // trial steps taken with unsettled iterations
  bool deep = false;            // settled only on a trial halved more than kMaxCuts times (inertia's shorter steps)
  bool event_inside = false;    // the step taken goes past an event by more than -rmin_event_tol (a compromise)
  PetscInt inconsistent = 0;    // Gauss points whose loading state disagrees with the solution taken
  PetscInt balance = 0;         // equilibrium corrections of the step taken (solves beyond the paper's)
};

class Controller {
public:
  // iterate_tangent: 1 when the equilibrium corrections take the tangent at their iterate
  // (Body::AssembleIterateTangent), set from the first step halved kMaxCuts times still out of balance on
  // (docs/theory.md, 5a); the caller's, which a checkpoint keeps.
  Controller(Model &model, Scene &scene, Inertia *inertia, const Options &opt, double duration,
             PetscInt &iterate_tangent);
  ~Controller();
  Controller(const Controller &) = delete;
  Controller &operator=(const Controller &) = delete;
  // Equilibrium iterations (-equilibrium_tol): what acts on the body at the
  // start of the increment besides its stresses (applied loads, contact forces,
  // inertia force; the driver keeps it current), and the force scale of the
  // criterion (the sum of the increments' mean nodal force magnitudes, and
  // their number).
  void SetStartForces(Vec f_start) { f_start_ = f_start; }
  void SetForceScale(double sum, double count) { q_sum_ = sum, q_count_ = count; }
  // Collective: the increment from lambda with trial step dl (`end`: the end of
  // the load path); du (local vector) receives it.
  PetscErrorCode Advance(double lambda, double dl, double end, Vec du, Increment &inc);

private:
  struct Trial {
    StepLimit limit;          // r1..r6 of the solution
    bool settled = true;      // its iterations settled (or it was taken unsettled)
    double dU = 0;            // tool step
    PetscInt redo = 0;        // loading switches applied
    PetscInt left = 0;        // loading switches called for but not applied (the -rmin_max_redo budget ran out)
    PetscInt transitions = 0; // -rmin_yield inside: points meeting the yield surface inside the step
  };
  Model &m_;
  Scene &scene_;
  Inertia *inertia_;
  const Options &opt_;
  double duration_;
  Vec f_start_ = nullptr;
  double q_sum_ = 0, q_count_ = 0;
  // The equilibrium iterations of the current trial: the last solution, the
  // internal force of the state it reaches (its mean nodal force magnitude in
  // q_iter_); have_iter_ false before the trial's first solve.
  Vec iter_ = nullptr, f_trial_ = nullptr;
  Vec prev_ = nullptr;                   // the iterate the last correction started from (line search)
  double reject_above_ = PETSC_MAX_REAL; // an iterate out of balance by more is backtracked
  double q_iter_ = 0;
  bool have_iter_ = false;
  PetscInt &iterate_tangent_; // (the constructor's iterate_tangent)
  double dl_trial_ = 0;       // the increment's trial step (a force-controlled tool's catch-up is shared by it)
  // A force-controlled tool's stroke increment of iter_ and prev_ (ContactSet::pad_step).
  double pad_iter_ = 0, pad_prev_ = 0;
  double PadStep() const { return ContactActive() ? m_.contact->pad_step() : 0.0; }
  void SetPadStep(double step)
  {
    if (ContactActive()) m_.contact->set_pad_step(step);
  }

  bool Equilibrium() const { return opt_.driver.equilibrium_tol > 0; }
  bool ContactActive() const { return m_.contact && m_.contact->active(); }
  // The internal force and mean nodal force magnitude (q_iter_) of the state du would reach.
  PetscErrorCode TrialState(Vec du);
  bool Iterative() const { return ContactActive() && m_.contact->friction(); }
  bool InertiaActive() const { return inertia_ && inertia_->active(); }
  // -dynamics auto before it turned inertia on.
  bool AutoBeforeInertia() const { return inertia_ && !inertia_->active(); }
  // -dynamics auto: inertia on from here, saying why at lambda.
  PetscErrorCode InertiaOn(double lambda, const char *why);
  // The equilibrium corrections take their iterate's tangent from here (iterate_tangent_), saying why at lambda.
  PetscErrorCode IterateTangentOn(double lambda);
  // The equilibrium iterations of a step begin (on) or end: the iterate and the body's step tangents with them.
  void Iterating(bool on);
  // The shortest step inertia allows, as a fraction of a step of dl.
  double MinStepFraction(double dl) const { return kMinDynamicStep / (opt_.driver.increments * dl); }
  // A contact node whose force would vanish within this fraction of a step of
  // dl is released in the trial rather than cutting it: round-off
  // quasi-statically, the shortest step inertia allows otherwise.
  double ReleaseWithin(double dl) const
  {
    return InertiaActive() ? std::max(kReleaseWithin, MinStepFraction(dl)) : kReleaseWithin;
  }
  // A trial step taken unsettled (counted, history column `unsettled`): solved
  // once more the paper's way, the friction linearized about the start of the
  // increment with the current active sets; r1 and r4-r6 still limit it.
  PetscErrorCode SolveUnsettled(double lambda, double dl, Vec du, Trial &t, Increment &inc);
  // One linear solve of the step dl with the current iterates.
  PetscErrorCode Solve(double lambda, double dl, Vec du, double &dU, Increment &inc);
  // One trial: solves until friction iterates and loading switches settle. A
  // trial that does not settle within the iteration budget reports settled =
  // false, unless it is the `last` try: then it is solved once more with the
  // friction linearized at the increment start and taken.
  PetscErrorCode SolveTrial(double lambda, double dl, Vec du, bool last, Trial &t, Increment &inc);
  // Equilibrium iterations on a step that will be taken (its solution du on
  // entry): Newton corrections with the step's own tangent until the largest
  // out-of-balance force is within -equilibrium_tol; t.settled false if they
  // diverge or run out (the step is then halved).
  PetscErrorCode Balance(double lambda, double dl, Vec du, Trial &t, Increment &inc);
  // A trial halved until it settles (kMaxCuts times at most; dl is halved with it).
  PetscErrorCode SettledTrial(double lambda, double &dl, Vec du, Trial &t, Increment &inc);
  // A step r_min cut to r of its trial (dl on entry): solved at that length, and again while an event or bound
  // lies inside it (dl the step taken); `stuck` where -dynamics auto's quasi-static steps cannot meet their limits.
  PetscErrorCode ResolveCut(double lambda, double r, double dl_trial, double &dl, Vec du, Trial &t, Increment &inc,
                            bool &stuck);
};

} // namespace tf
