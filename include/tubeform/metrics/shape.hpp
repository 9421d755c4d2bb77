// Shape metrics of a pressed tube (docs/theory.md, "Metrics"): the collapse gap C
// of a side against a straight line, the outer corner radii. Pure geometry
// on the outer-surface points (no PETSc), so unit tests need no mesh.
#pragma once

#include <vector>

#include "tubeform/core/core.hpp"

namespace tf {

// A node of the outer surface: current position, whether it touches the tool
// and on which of the tool's segments.
struct SurfacePoint {
  double x = 0, y = 0;
  int contact = 0, segment = -1;
  long id = -1; // node number of the input mesh
};

// A straight line through `a` with unit normal `n` (pointing into the body)
// and tangent l = n turned by -90 degrees.
struct Line {
  Vec2 a{}, n{}, l{};
  double Along(const SurfacePoint &p) const { return (p.x - a[0]) * l[0] + (p.y - a[1]) * l[1]; }
  double Gap(const SurfacePoint &p) const { return (p.x - a[0]) * n[0] + (p.y - a[1]) * n[1]; }
};

// The largest and smallest gap to a line over the points whose coordinate
// along it lies in [smin, smax]; empty when no point does.
struct GapRange {
  double min = kNever, max = -kNever;
  bool empty() const { return max < min; }
};
GapRange GapsTo(const std::vector<SurfacePoint> &points, const Line &line, double smin, double smax);

// The side of the tube along a die's flank (docs/theory.md, "Metrics"): between the
// outermost points touching the flank segment, and, when a point touches the
// apex segment, reaching the flank's apex end at s_apex_end (the side of a
// tube that lost its flank contacts near the apex has folded in between the
// apex and the corner; the fillet's own curve is not the side). `ends` are
// indices into the points (the nearest point for s_apex_end); empty when no
// point touches the flank.
struct SideSpan {
  double smin = kNever, smax = -kNever;
  size_t ends[2] = {0, 0};
  bool empty() const { return smax < smin; }
};
SideSpan SideOnFlank(const std::vector<SurfacePoint> &points, const Line &flank, int flank_segment, int apex_segment,
                     double s_apex_end);

// C of a side without a tool (after unloading; docs/theory.md, "Metrics"): the largest
// gap between the chord through points[first] and points[last] and the points
// between them, measured towards the origin (the tube's centre): the side
// bowing inwards. 0 for a straight or outward-bowing side, whatever its tilt
// or shift (a rigid motion of the side counts nothing).
double ChordGap(const std::vector<SurfacePoint> &points, size_t first, size_t last);

// Radius of the circle centred on a symmetry axis through a node on the axis
// (at distance on_axis from the origin) and its neighbour (nx along the axis,
// ny across it): the local corner radius there.
double AxisCornerRadius(double on_axis, double nx, double ny);

} // namespace tf
