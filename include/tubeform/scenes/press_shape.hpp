// The squaring and flattening scenes' shape measures (docs/theory.md, "Metrics"): C/t
// against the upper die's flank and the corner radii on the axes, in the frame
// of the press in place (a pass that turned the tube: its own).
#pragma once

#include "tubeform/io/history.hpp"
#include "tubeform/scenes/scene.hpp"
#include "tubeform/tool/tool.hpp"

namespace tf {

// What the measures read of the press scene.
struct PressShapeState {
  bool squaring;   // C/t against the die's flank (the flattening scene: the corner radii only)
  bool half;       // the half or full model: the upper right quarter of the whole surface
  bool unloading;  // a release (reversed loads or the die withdrawn): C/t is the chord's gap of the side the
                   // loading left
  bool later_pass; // a later pass's dies are in place (the second's, the third's, ...)
  int flank, apex; // the upper die's segments (scenes/die.hpp)
  double t;        // the wall thickness (mm)
  TurnMap press;   // the tube's coordinates into the press's frame
};

// Collective: C/t and the corner radii into `row`. Loading: the largest gap between the flank and the outer
// surface along the side (SideOnFlank: the outermost flank contacts, and the fillet's end when the apex
// touches), whose end nodes (input numbers) are remembered in side_ends. Unloading, or a later pass's die
// still on its way: the largest gap between the side and the chord through those two nodes.
PetscErrorCode PressShape(Model &m, const PressShapeState &s, long side_ends[2], HistoryRow &row);

} // namespace tf
