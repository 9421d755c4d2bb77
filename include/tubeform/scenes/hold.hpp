// The full model's rotation hold (docs/dies.md, "The rotation hold"): in
// place of the pins, which hold the tube's slide along the press's x as well
// as its rotation, the two inner nodes on the press's y axis (top and bottom,
// never in contact) move along the press's x by one unknown s of each solve,
// s chosen so that their forces along it sum to zero. They then carry a
// couple only: the tube's rotation is held, its slide is left to the dies (a
// die off the axis moves it sideways). The couple is a moment the real tube
// does not get; the history reports it beside the largest moment the
// contacts' friction could carry (hold_moment, hold_friction), so a run says
// when the real tube would turn instead.
#pragma once

#include <string>

#include "tubeform/scenes/scene.hpp"

namespace tf {

class RotationHold : public ExtraUnknown {
public:
  // Collective: the hold's nodes in the press's frame `press` (node set "hold"), on every pass's start.
  PetscErrorCode Mark(Model &m, const SquareMap &press);
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
  // Collective: the couple and the friction's largest into the history (`det`: the press's frame's determinant,
  // the row's load and stroke already in), and a warning the first time friction could not carry it.
  PetscErrorCode Measure(Model &m, Vec f_int, double det, double ro, HistoryRow &row);

private:
  // A couple below this fraction of the punch load times the tube's radius is the solver's round-off.
  static constexpr double kNoise = 1e-9;
  Model *m_ = nullptr;
  Vec2 along_{1, 0};
  bool warned_ = false; // the warning printed
};

} // namespace tf
