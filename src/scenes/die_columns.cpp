// The press's dies' history columns and the work they give (scenes/die_columns.hpp). Each column follows the one
// it followed in the files before the tools declared them, so a reader by position finds it where it was.
#include "tubeform/scenes/die_columns.hpp"

#include <cmath>

namespace tf {

const ToolColumns &UpperDieColumns()
{
  static const ToolColumns c({
    {"tool_fx", "force of the model on the tool, x (N/mm)", "n_contact_apex"},
    {"tool_fy", "force of the model on the tool, y (N/mm)", "tool_fx"},
    {"tool_moment",
     "moment of the model's forces on the tool about the tool frame's origin, which moves with the tool (the "
     "tube's centre at stroke 0; N mm/mm, counter-clockwise positive)",
     "tool_fy"},
    {"n_contact_apex", "contact nodes on the V-die's apex fillet (the squaring scene's upper die)", "stage"},
  });
  return c;
}

const ToolColumns &LowerDieColumns()
{
  static const ToolColumns c({
    {"lower_fx", "half and full model: force of the model on the lower die, x (N/mm; 0 in a quarter)", "fn_sum"},
    {"lower_fy", "half and full model: force of the model on the lower die, y (N/mm)", "lower_fx"},
    {"lower_moment",
     "half and full model: moment of the model's forces on the lower die about its frame's origin (N mm/mm)",
     "side_load"},
  });
  return c;
}

const ToolColumns &SideDieColumns()
{
  static const ToolColumns c({
    {"side_load",
     "-side_die: each side die's force along its motion, on the whole tube (N/mm; 0 without; the full model: the "
     "mean of the two)",
     "lower_fy"},
    {"side_stroke",
     "-side_die: the side dies' travel towards the tube's centre (mm): the stroke, or their own with -side_force",
     "lower_moment"},
  });
  return c;
}

const ToolColumns &DiePathColumns()
{
  static const ToolColumns c({
    {"die_x", "-die_path: the upper die's displacement along the press's x from where it started (mm; 0 without)",
     "hold_friction"},
    {"die_turn", "-die_path_turn: the upper die's turn about -die_pivot (degrees, counter-clockwise; 0 without)",
     "die_x"},
  });
  return c;
}

double PressToolWork(TubePart part, const DieTravel &travel, const HistoryRow &prev, const HistoryRow &row)
{
  const ToolColumns &upper = UpperDieColumns(), &lower = LowerDieColumns(), &side = SideDieColumns();
  const ToolColumns &path = DiePathColumns();
  const bool two_dies = part != TubePart::Quarter;
  const double dU = row.stroke - prev.stroke;
  // (the share of the punch load the model carries: half in the quarter and the half model, all in the full one)
  const double share = !two_dies ? 0.5 : travel.upper_per_u / (part == TubePart::Full ? 1.0 : 2.0);
  double dw = share * 0.5 * (prev.load + row.load) * dU;
  if (two_dies && travel.lower_moves) // (moving up; the model pushes it down)
    dw -= 0.5 * (lower(prev, kDieFy) + lower(row, kDieFy)) * travel.lower_rise;
  dw += SideDiesInModel(part) * 0.5 * (side(prev, kSideLoad) + side(row, kSideLoad)) *
        (side(row, kSideStroke) - side(prev, kSideStroke));
  // (-die_path's sideways motion, and its turn)
  dw -= 0.5 * (upper(prev, kDieFx) + upper(row, kDieFx)) * (path(row, kDieX) - path(prev, kDieX));
  dw -= 0.5 * (upper(prev, kDieMoment) + upper(row, kDieMoment)) * (path(row, kDieTurn) - path(prev, kDieTurn)) *
        (M_PI / 180);
  return dw;
}

} // namespace tf
