// What holds a press's tube where no die does (docs/theory.md, section 8), behind one interface: the full
// model's pins on the press's y axis (AxisPins), the rotation hold in their place on a press off the axis
// (scenes/hold.hpp), and the springback's pin of the half and full models (SpringbackPin). Each marks its nodes
// at a pass's start, turns their frames with a press turned by any angle, and prescribes them at each increment.
#pragma once

#include <cmath>
#include <functional>
#include <vector>

#include "tubeform/scenes/scene.hpp"
#include "tubeform/tool/turn_map.hpp"

namespace tf {

// What a support reads of the press at an increment: the press's frame into the tube's, whether the pass's dies
// press (not its release), and the history's stroke U (asked only where a support needs it: a release has no die).
struct SupportStep {
  TurnMap to_tube;
  bool pressing = true;
  std::function<double()> stroke;
};

// The scene holds its supports at work in a list (PressScene::Supports) and, at each increment, settles, turns and
// constrains each in turn; each marks its nodes at its own moment (a pass's start, a release's) and keeps its state
// for a restart. What a support measures for the history is its own (the rotation hold's columns).
class Support {
public:
  virtual ~Support() = default;
  // Collective: its nodes, at a pass's start (`press`: the tube's coordinates into the press's frame).
  virtual PetscErrorCode Mark(Model &m, const TurnMap &press) = 0;
  // Collective, before an increment: what it takes from the press's state before it holds (the rotation hold lets
  // the tube's slide go once the dies hold it); nothing by default.
  virtual PetscErrorCode Settle(Model & /*m*/, const SupportStep & /*step*/) { return PETSC_SUCCESS; }
  // Before an increment: its nodes' frames along a press turned by an angle that is no quarter turn (`to_tube`:
  // the press's frame into the tube's); nothing in a press along the global axes.
  virtual void TakeFrames(Model &m, const TurnMap &to_tube) const = 0;
  // Collective: the increment's prescribed motion of its nodes.
  virtual PetscErrorCode Constrain(Model &m, const SupportStep &step) = 0;
  // Collective: its state for a restart, written or read back (`press` as in Mark; marked again where it needs);
  // nothing where its nodes are marked again from the pass (the default).
  virtual PetscErrorCode Persist(Model & /*m*/, Archive & /*ar*/, const TurnMap & /*press*/) { return PETSC_SUCCESS; }

protected:
  // `nodes`' frames along a press turned by an angle that is no quarter turn (`to_tube` as in
  // TakeFrames); nothing in a press along the global axes.
  static void TurnFrames(Model &m, const std::vector<PetscInt> &nodes, const TurnMap &to_tube)
  {
    const Vec2 axis = to_tube({1, 0}); // (the press's x in the tube's frame)
    if (axis[0] == 0 || axis[1] == 0) return;
    const double angle = std::atan2(axis[1], axis[0]);
    for (PetscInt n : nodes) m.system.SetFrame(n, angle);
  }
};

// The full model's pins, node set "axis": the outer nodes on the press's y axis at the tube's top and bottom,
// held along the press's x (scenes/pins.cpp, MarkAxisPins): the tube's rotation and its slide.
class AxisPins : public Support {
public:
  PetscErrorCode Mark(Model &m, const TurnMap &press) override;
  void TakeFrames(Model &m, const TurnMap &to_tube) const override;
  PetscErrorCode Constrain(Model &m, const SupportStep &step) override;
};

// The half and full models' springback: one inner node holds the tube's rigid motion along the press's y
// (ChooseSpringbackPin), from the release's start until a second pass's dies touch the tube.
class SpringbackPin : public Support {
public:
  PetscErrorCode Mark(Model &m, const TurnMap &press) override;
  void TakeFrames(Model &m, const TurnMap &to_tube) const override;
  // (it lets go once the dies touch the tube in a pass pressing, not its release: ReleaseOnTouch)
  PetscErrorCode Constrain(Model &m, const SupportStep &step) override;
  // It holds (every rank alike), and its local node (-1: none here, or not holding).
  bool holds() const { return holds_; }
  PetscInt node() const { return holds_ ? node_ : -1; }
  // Collective: whether it holds, for a restart, which marks it again.
  PetscErrorCode Persist(Model &m, Archive &ar, const TurnMap &press) override;

private:
  PetscInt node_ = -1;
  bool holds_ = false;

  // Collective: the pin lets go once the dies touch the tube.
  PetscErrorCode ReleaseOnTouch(Model &m);
};

} // namespace tf
