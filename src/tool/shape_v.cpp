// The V-die (tool/shape.hpp): the flanks of -die_angle touching the tube, the apex fillet, the parting face and
// its edge fillet, drawn as a profile (tool/profile.hpp).
#include <cmath>
#include <stdexcept>

#include "tubeform/tool/profile.hpp"
#include "tubeform/tool/shape.hpp"

namespace tf {

VAngle::VAngle(double degrees)
{
  // At 90 degrees sqrt(2) itself and pi / 4: the paper's die without the round-off of sin and cos.
  if (degrees == 90) {
    half = M_PI / 4, qs = qc = std::sqrt(2.0);
  } else {
    half = degrees * M_PI / 360, qs = 1 / std::sin(half), qc = 1 / std::cos(half);
  }
}

std::string MakeVDie(double ro, double r_apex, double u_close, double r_edge, double angle, Tool &t)
{
  // As a profile (tool/profile.hpp), so that a profile file with these numbers is the same die to the last bit.
  const VAngle v(angle);
  const double h = ro * v.qs, half = angle / 2; // the flanks' intersection (they touch the tube); degrees
  std::vector<ProfileItem> items;
  Vec2 flank_start = {0, h};
  if (r_apex > 0) {
    const double cy = h - r_apex * v.qs;
    items.push_back({true, {0, cy, r_apex, 90, half}, 0, ""}); // walked from the apex to the flank's tangent point
    flank_start = {r_apex / v.qc, cy + r_apex / v.qs};
  }
  if (u_close > 0) {
    // The flank meets the parting face y = u_close at x = xe; a convex fillet of radius r_edge tangent to both
    // turns through 90 - half degrees, its tangent points set back from the corner by r_edge tan of half that.
    const double xe = (h - u_close) * (v.qc / v.qs);
    const double d = r_edge * std::tan((M_PI / 2 - v.half) / 2);
    items.push_back({false, {flank_start[0], flank_start[1], xe - d / v.qs, u_close + d / v.qc}, 0, ""});
    if (r_edge > 0) items.push_back({true, {xe + d, u_close + r_edge, r_edge, 180 + half, 270}, 0, ""});
    items.push_back({false, {xe + d, u_close, 2.0 * ro, u_close}, 0, ""});
  } else {
    items.push_back({false, {flank_start[0], flank_start[1], 1.3 * ro, h - 1.3 * ro * (v.qs / v.qc)}, 0, ""});
  }
  const std::string error = BuildProfile(items, "the V-die", t);
  t.name = "V-die";
  return error;
}

Tool BuildVDie(double ro, double r_apex, double u_close, double r_edge, double angle)
{
  Tool t;
  const std::string error = MakeVDie(ro, r_apex, u_close, r_edge, angle, t);
  if (!error.empty()) throw std::invalid_argument(error);
  return t;
}

double StrokeForCornerRadius(double ro, double rc, double angle)
{
  // The cavity is a rhombus of vertical half-diagonal D = h - U and sides D / cos(half); rounding each corner
  // (turning by 2 (pi/2 - half) at the top and bottom, 2 half at the sides) by rc cuts 2 rc tan(turn / 2) from
  // the sides and adds rc x turn: perimeter 4 D / cos(half) - 4 rc (cot(half) + tan(half)) + 2 pi rc = 2 pi ro.
  const VAngle v(angle);
  const double d = (2 * M_PI * ro + (4 * (v.qs / v.qc + v.qc / v.qs) - 2 * M_PI) * rc) / (4 * v.qc);
  return ro * v.qs - d;
}

} // namespace tf
