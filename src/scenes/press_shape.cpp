// The press scenes' shape measures (include/tubeform/scenes/press_shape.hpp).
#include "tubeform/scenes/press_shape.hpp"

#include <algorithm>

#include "tubeform/metrics/shape.hpp"
#include "tubeform/scenes/common.hpp"
#include "tubeform/scenes/die_columns.hpp"

namespace tf {

PetscErrorCode PressShape(Model &m, const PressShapeState &s, long side_ends[2], HistoryRow &row)
{
  std::vector<SurfacePoint> all;
  PetscFunctionBeginUser;
  PetscCall(GatherOuter(m, all, s.half, s.press));
  if (all.size() >= 2) {
    // (the half model's tube moves with a fixed lower die: its neighbour's height from the axis node's)
    row.r_corner_x = AxisCornerRadius(all.front().x, all[1].x, all[1].y - all.front().y);
    row.r_corner_y = AxisCornerRadius(all.back().y, all[all.size() - 2].y, all[all.size() - 2].x);
  }
  if (!s.squaring) PetscFunctionReturn(PETSC_SUCCESS);
  for (const auto &o : all) UpperDieColumns()(row, kDieApexContacts) += o.contact && s.apex >= 0 && o.segment == s.apex;
  const Tool &tool = m.contact->tool(0);
  const Segment &fl = tool.segments[s.flank];
  const Vec2 a = s.press(tool.Placed(fl.a)), n = s.press(tool.Oriented(fl.n_line));
  const Line flank{a, n, {n[1], -n[0]}};
  // The line starts at the flank's apex end (s = 0), where the fillet ends.
  const SideSpan side = s.unloading ? SideSpan{} : SideOnFlank(all, flank, s.flank, s.apex, 0.0);
  // Without a side on the flank (springback; a later pass's die still on its way to the tube), C is the
  // chord's gap of the side the last one left.
  if (s.unloading || (s.later_pass && side.empty() && side_ends[0] >= 0)) {
    // (the half and full models: the whole surface, as a pass that turned the tube finds the side the first
    // one left in another quarter)
    std::vector<SurfacePoint> whole;
    if (s.half) PetscCall(GatherOuter(m, whole, false, s.press));
    std::vector<SurfacePoint> &on = s.half ? whole : all;
    if (s.half) OrderAroundSide(on, side_ends);
    size_t ends[2] = {on.size(), on.size()};
    for (size_t k = 0; k < on.size(); ++k)
      for (int e = 0; e < 2; ++e)
        if (on[k].id == side_ends[e]) ends[e] = k;
    const bool found = ends[0] < on.size() && ends[1] < on.size();
    row.c_over_t = found ? ChordGap(on, ends[0], ends[1]) / s.t : 0.0;
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  side_ends[0] = side.empty() ? -1 : all[side.ends[0]].id;
  side_ends[1] = side.empty() ? -1 : all[side.ends[1]].id;
  const GapRange g = GapsTo(all, flank, side.smin, side.smax);
  row.c_over_t = g.empty() ? 0.0 : std::max(g.max, 0.0) / s.t;
  PetscFunctionReturn(PETSC_SUCCESS);
}

} // namespace tf
