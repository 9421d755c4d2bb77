#include "tubeform/metrics/shape.hpp"

#include <algorithm>

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

double AxisCornerRadius(double on_axis, double nx, double ny)
{
  // Centre (c, 0): (on_axis - c)^2 = (nx - c)^2 + ny^2.
  const double c = (on_axis * on_axis - nx * nx - ny * ny) / (2 * (on_axis - nx));
  return on_axis - c;
}

} // namespace tf
