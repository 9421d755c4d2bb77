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

namespace tf {

class RotationHold : public ExtraUnknown {
public:
  // Collective: the hold's nodes in the press's frame `press` (node set "hold"), on every pass's start.
  PetscErrorCode Mark(Model &m, const TurnMap &press);
  // The increment's constraint: both nodes along `along` (the press's x in the tube's frame) by the system's
  // extra unknown.
  PetscErrorCode Constrain(Model &m, const Vec2 &along);
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
  // Collective: the couple and the friction's largest into the history (`det`: the press's frame's determinant,
  // the row's load and stroke already in), and a warning the first time friction may not carry it.
  PetscErrorCode Measure(Model &m, Vec f_int, double det, double ro, HistoryRow &row);
  // Every history row's load: the warning's floor follows the largest so far.
  void SeeLoad(double load) { largest_load_ = std::max(largest_load_, std::abs(load)); }
  // Collective: the warning's state (a restart warns as the run it continues would).
  PetscErrorCode Persist(Archive &ar)
  {
    PetscFunctionBeginUser;
    PetscCall(ar.Value("hold_largest_load", largest_load_));
    PetscCall(ar.Value("hold_warned", warned_));
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
  double largest_load_ = 0;
  Model *m_ = nullptr;
  Vec2 along_{1, 0};
  bool warned_ = false; // the warning printed
};

} // namespace tf
