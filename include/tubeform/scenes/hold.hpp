// The full model's rotation hold (docs/dies.md, "A die off the axis: the
// rotation hold"): in place of the pins, which hold the tube's slide along
// the press's x as well as its rotation, the two inner nodes on (in a press
// turned by another angle, nearest) the press's y axis, top and bottom, never
// in contact, move along the press's x by one unknown s of each solve, s
// chosen so that their forces along it sum to zero. They then carry a couple
// only: the tube's rotation is held, its slide is left to the dies (a die off
// the axis moves it sideways). The couple is a moment the real tube does not
// get; the history reports it beside the largest moment the contacts'
// friction could carry (hold_moment, hold_friction), so a run says when the
// real tube may turn instead.
#pragma once

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "tubeform/scenes/scene.hpp"
#include "tubeform/scenes/support.hpp"
#include "tubeform/scenes/tool_columns.hpp"

namespace tf {

class RotationHold : public ExtraUnknown, public Support {
public:
  // Support (collective): the hold's nodes in the press's frame `press` (node set "hold"), on every pass's start.
  PetscErrorCode Mark(Model &m, const TurnMap &press) override;
  // Support (collective): while it pins the slide, lets it go once the dies hold it (FreeSlide).
  PetscErrorCode Settle(Model &m, const SupportStep &step) override
  {
    return pins_ ? FreeSlide(m, step.stroke()) : PETSC_SUCCESS;
  }
  void TakeFrames(Model &m, const TurnMap &to_tube) const override;
  // Support: the increment's constraint: both nodes along the press's x by the system's extra unknown.
  PetscErrorCode Constrain(Model &m, const SupportStep &step) override;
  // ExtraUnknown (collective): minus the sum of the nodes' reactions along `along` (0 for a couple).
  PetscErrorCode Missing(double &missing) override;
  void Moved(double) override {} // (a slide the body keeps: nothing to carry)
  std::string Name() const override { return "the rotation hold"; }
  std::string Stalled(double slope) const override;
  // Collective: the couple the hold puts on the tube (counter-clockwise in the tube's frame, N mm/mm), from the
  // force the body needs at its nodes (`f_int`: internal force contributions, local vector, global frame), and
  // the largest moment the contacts' friction could carry about the nodes' midpoint (0 without contact).
  PetscErrorCode Moment(Model &m, Vec f_int, double &moment, double &friction) const;
  // Collective: in a release, the moment about the tube's centre that the springback's supports (the pins, node
  // set "axis", and the local node `pin`, -1: none here) carry: their internal force less the release's reversed
  // loads (share x f_rev); 0 in balance: the reversed loads, the hold's forces among them, need no support.
  PetscErrorCode SupportMoment(Model &m, Vec f_int, Vec f_rev, double share, PetscInt pin, double &moment) const;
  // Its history columns (scenes/tool_columns.hpp): the couple and the friction's largest.
  enum Column { kMoment, kFriction };
  static const ToolColumns &Columns();
  // Collective: the couple and the friction's largest into the history (`det`: the press's frame's determinant,
  // the row's load and stroke already in), and a warning the first time friction may not carry it.
  PetscErrorCode Measure(Model &m, Vec f_int, double det, double ro, HistoryRow &row);
  // The tube's slide at a pass's start: the hold's nodes are fixed along the press's x (`pinned`: a pass the
  // hold holds), holding the slide with the rotation, until FreeSlide finds the dies holding it; then they move
  // by the unknown. Before, contacts whose normals are parallel (a flank of each die facing the other's, on a tube
  // the last pass left off its axis) leave the slide along them to friction alone, whose stiffness mu f_n / vcri
  // vanishes with the first touches' forces: r6 then cuts the steps to a crawl (3,342 stick-limited increments
  // at 1e-6 mm of the stroke each, in the second pass after an off-axis one) while round-off sways the tube back
  // and forth. The hold's nodes are inner ones, never in contact, with frames along the press (any turn).
  void PinSlide(bool pinned) { pins_ = pinned, pinned_steps_ = 0; }
  bool pins() const { return pins_; }
  // Collective, before an increment: the dies hold the slide once their contacts' normals spread over the plane
  // (ContactSet::NormalSpread above kSlideHeld); then the nodes go free along x and, after a pinned increment, a
  // line says from which stroke U.
  PetscErrorCode FreeSlide(Model &m, double stroke);
  // Every history row's load: the warning's floor follows the largest so far.
  void SeeLoad(double load) { largest_load_ = std::max(largest_load_, std::abs(load)); }
  double largest_load() const { return largest_load_; }
  // Support (collective): the warning's state (a restart warns as the run it continues would) and the slide's pin.
  PetscErrorCode Persist(Model & /*m*/, Archive &ar, const TurnMap & /*press*/) override
  {
    PetscFunctionBeginUser;
    PetscCall(ar.Value("hold_largest_load", largest_load_));
    PetscCall(ar.Value("hold_warned", warned_));
    PetscCall(ar.Value("hold_pins_slide", pins_));
    PetscCall(ar.Value("hold_pinned_steps", pinned_steps_));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  // Collective: the forces the hold puts on the body (its nodes' internal force, owned nodes, global frame) added
  // to `f`: a release's reversed loads take them down with the contact forces.
  PetscErrorCode AddForces(Model &m, Vec f) const;

private:
  // A couple within this fraction of the largest punch load so far times the tube's radius is one the method
  // does not resolve (its equilibrium tolerance, 0.5 % of the mean nodal force, over the few contact nodes at
  // arm Ro): no warning below it (the first touches of a pass, where friction's largest is nearly 0).
  static constexpr double kUnresolved = 1e-3;
  // Normals this far apart hold a slide by their forces: tan^2 of half of 11.4 degrees (NormalSpread), well clear
  // of the round-off spread of parallel flanks and far below a V-die's two flanks (1 at 90 degrees).
  static constexpr double kSlideHeld = 1e-2;
  bool pins_ = false;         // the nodes hold the slide too (PinSlide)
  PetscInt pinned_steps_ = 0; // increments of the pass so far with the nodes holding the slide
  double largest_load_ = 0;
  Model *m_ = nullptr;
  Vec2 along_{1, 0};
  bool warned_ = false; // the warning printed
};

} // namespace tf
