// The press's dies' history columns (scenes/tool_columns.hpp), declared in src/scenes/die_columns.cpp: each die's
// force and moment, the side dies' force and travel, the upper die's own path; and the dies' work over a step
// that their columns give.
#pragma once

#include "tubeform/scenes/common.hpp"
#include "tubeform/scenes/tool_columns.hpp"

namespace tf {

// A die's columns: the model's force on it, x and y (N/mm), and its moment about the die frame's origin (N mm/mm),
// in the press's frame. The upper die's (tool_fx, tool_fy, tool_moment) are the scene's tool's: the slide's floor;
// the upper die's also its contact nodes on the V-die's apex fillet (n_contact_apex; the squaring scene's).
enum DieColumn { kDieFx, kDieFy, kDieMoment, kDieApexContacts };
const ToolColumns &UpperDieColumns();
const ToolColumns &LowerDieColumns(); // lower_fx, lower_fy, lower_moment: the half and full models' lower die
// The side dies' (-side_die): each one's force along its motion on the whole tube, and their travel.
enum SideDieColumn { kSideLoad, kSideStroke };
const ToolColumns &SideDieColumns();
// The upper die's own path (-die_path): its sideways displacement (mm) and its turn (degrees).
enum DiePathColumn { kDieX, kDieTurn };
const ToolColumns &DiePathColumns();

// The press scenes' dies' work on the model over a step, each die's reported force over its own travel (the
// trapezoid rule; self-check (a), Scene::ToolWork): the upper die's share of the punch load (the quarter's y = 0
// plane stands in for a mirrored lower die; the upper die travels `upper_per_u` per unit U: 2 over a lower die
// that stays); in the half and full models a moving lower die's own force (a floor carries less than the die
// above it when side dies take some of the vertical force by friction) over its rise in the step `lower_rise`;
// the side dies' force over their travel (`side_stroke`); the upper die's force along x over its sideways
// travel (`die_x`, -die_path), and its moment about its pivot over its turn (`die_turn`, -die_path_turn).
struct DieTravel {
  double upper_per_u = 1; // the upper die's travel per unit U
  bool lower_moves = true;
  double lower_rise = 0; // the lower die's rise in the step (mm)
};
double PressToolWork(TubePart part, const DieTravel &travel, const HistoryRow &prev, const HistoryRow &row);

} // namespace tf
