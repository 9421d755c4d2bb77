#include "tubeform/metrics/shape.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace tf {

GapRange GapsTo(const std::vector<SurfacePoint> &points, const Line &line, double smin, double smax)
{
  GapRange g;
  for (const auto &p : points) {
    const double s = line.Along(p);
    if (s < smin || s > smax) continue;
    const double gap = line.Gap(p);
    g.max = std::max(g.max, gap), g.min = std::min(g.min, gap);
  }
  return g;
}

SideSpan SideOnFlank(const std::vector<SurfacePoint> &points, const Line &flank, int flank_segment, int apex_segment,
                     double s_apex_end)
{
  SideSpan side;
  bool apex = false;
  for (size_t k = 0; k < points.size(); ++k) {
    const SurfacePoint &p = points[k];
    if (!p.contact) continue;
    apex = apex || p.segment == apex_segment;
    if (p.segment != flank_segment) continue;
    const double s = flank.Along(p);
    if (s < side.smin) side.smin = s, side.ends[0] = k;
    if (s > side.smax) side.smax = s, side.ends[1] = k;
  }
  if (!apex || side.empty()) return side;
  size_t nearest = 0;
  for (size_t k = 1; k < points.size(); ++k)
    if (std::abs(flank.Along(points[k]) - s_apex_end) < std::abs(flank.Along(points[nearest]) - s_apex_end))
      nearest = k;
  if (s_apex_end < side.smin) side.smin = s_apex_end, side.ends[0] = nearest;
  if (s_apex_end > side.smax) side.smax = s_apex_end, side.ends[1] = nearest;
  return side;
}

double ChordGap(const std::vector<SurfacePoint> &points, size_t first, size_t last)
{
  if (first > last) std::swap(first, last);
  const SurfacePoint &a = points[first], &b = points[last];
  const double lx = b.x - a.x, ly = b.y - a.y, len = std::hypot(lx, ly);
  if (last - first < 2 || !(len > 0)) return 0;
  Line chord{{a.x, a.y}, {-ly / len, lx / len}, {}};
  if (chord.n[0] * -a.x + chord.n[1] * -a.y < 0) chord.n = {-chord.n[0], -chord.n[1]}; // towards the origin
  double c = 0;
  for (size_t k = first + 1; k < last; ++k) c = std::max(c, chord.Gap(points[k]));
  return c;
}

double AxisCornerRadius(double on_axis, double nx, double ny)
{
  // Centre (c, 0): (on_axis - c)^2 = (nx - c)^2 + ny^2.
  const double c = (on_axis * on_axis - nx * nx - ny * ny) / (2 * (on_axis - nx));
  return on_axis - c;
}

} // namespace tf
