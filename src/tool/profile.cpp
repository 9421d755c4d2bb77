#include "tubeform/tool/profile.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace tf {

namespace {

// A segment as walked: its start and end points and its directions there.
struct Walk {
  Vec2 start, end, dir_start, dir_end;
  bool arc;
};

std::string Where(const std::string &file, int line) { return file + ":" + std::to_string(line) + ": "; }
std::string Where(const std::string &file, const ProfileItem &item)
{
  return item.where.empty() ? Where(file, item.line) : file + ": " + item.where + ": ";
}

double Angle(const Vec2 &a, const Vec2 &b)
{
  return std::acos(std::max(-1.0, std::min(1.0, a[0] * b[0] + a[1] * b[1])));
}

} // namespace

std::string ParseProfile(const std::string &text, const std::string &file, Tool &tool)
{
  std::vector<ProfileItem> items;
  std::istringstream in(text);
  std::string raw;
  for (int line = 1; std::getline(in, raw); ++line) {
    std::istringstream words(raw.substr(0, raw.find('#')));
    ProfileItem item;
    item.line = line;
    std::string kind;
    if (!(words >> kind)) continue;
    double x;
    while (words >> x) item.v.push_back(x);
    if (!words.eof()) return Where(file, line) + "not a number among the values of '" + kind + "'";
    if (kind == "line") {
      if (item.v.size() != 4) return Where(file, line) + "'line' takes X0 Y0 X1 Y1 (mm)";
      item.arc = false;
    } else if (kind == "arc") {
      if (item.v.size() != 5) return Where(file, line) + "'arc' takes CX CY R A0 A1 (mm, degrees)";
      item.arc = true;
    } else {
      return Where(file, line) + "'" + kind + "' is not a segment (line, arc)";
    }
    items.push_back(item);
  }
  return BuildProfile(items, file, tool);
}

std::string BuildProfile(const std::vector<ProfileItem> &items, const std::string &file, Tool &tool)
{
  tool = Tool{};
  tool.name = "die";
  std::vector<Walk> walks;
  for (const ProfileItem &item : items) {
    const std::vector<double> &v = item.v;
    Segment s;
    Walk w{};
    if (!item.arc) {
      s.a = {v[0], v[1]}, s.b = {v[2], v[3]};
      const double len = std::hypot(v[2] - v[0], v[3] - v[1]);
      if (!(len > kProfileGap)) return Where(file, item) + "a line of no length";
      const Vec2 d = {(v[2] - v[0]) / len, (v[3] - v[1]) / len};
      s.n_line = {d[1], -d[0]}; // the right-hand side of the walk: the tube's
      w = {s.a, s.b, d, d, false};
    } else {
      if (!(v[2] > 0)) return Where(file, item) + "an arc needs a positive radius";
      if (!(std::abs(v[4] - v[3]) > 0 && std::abs(v[4] - v[3]) < 360))
        return Where(file, item) + "an arc turns through more than 0 and less than 360 degrees";
      const double a0 = v[3] * M_PI / 180, a1 = v[4] * M_PI / 180, sense = a1 > a0 ? 1 : -1;
      s.kind = Segment::Arc;
      s.c = {v[0], v[1]}, s.radius = v[2];
      s.t0 = std::min(a0, a1), s.t1 = std::max(a0, a1);
      s.concave = sense < 0; // walked clockwise, the tube (on the right) is inside the circle
      const auto at = [&](double a) { return Vec2{v[0] + v[2] * std::cos(a), v[1] + v[2] * std::sin(a)}; };
      const auto dir = [&](double a) { return Vec2{-sense * std::sin(a), sense * std::cos(a)}; };
      w = {at(a0), at(a1), dir(a0), dir(a1), true};
    }
    if (walks.empty() && std::abs(w.start[0]) > kProfileGap)
      return Where(file, item) +
             "the profile must start on the axis x = 0 (the die's middle), not at x = " + std::to_string(w.start[0]);
    if (!walks.empty()) {
      const Walk &p = walks.back();
      const double gap = std::hypot(w.start[0] - p.end[0], w.start[1] - p.end[1]);
      char buf[160];
      if (gap > kProfileGap) {
        std::snprintf(buf, sizeof buf, "a gap of %.3g mm from the end of the previous segment (%g, %g)", gap, p.end[0],
                      p.end[1]);
        return Where(file, item) + buf;
      }
      const double turn = Angle(p.dir_end, w.dir_start);
      if ((w.arc || p.arc) && turn > kProfileTangency) {
        std::snprintf(buf, sizeof buf, "the arc is not tangent to its neighbour at (%g, %g): they turn by %.3g degrees",
                      w.start[0], w.start[1], turn * 180 / M_PI);
        return Where(file, w.arc ? item : items[walks.size() - 1]) + buf;
      }
    }
    walks.push_back(w);
    tool.segments.push_back(s);
  }
  if (walks.empty()) return file + ": no segment (line or arc) in the profile";
  // Orientation: where the die comes nearest the tube's centre, its tube side must face the centre.
  Projection pr = tool.Project({0, 0});
  if (pr.segment >= 0 && pr.n[0] * -pr.point[0] + pr.n[1] * -pr.point[1] <= 0)
    return Where(file, items[pr.segment]) +
           "the tube is on the wrong side: walk the profile from the axis outward with the tube on the right";
  return "";
}

int LongestLine(const Tool &tool)
{
  int best = -1;
  double longest = 0;
  for (size_t k = 0; k < tool.segments.size(); ++k) {
    const Segment &s = tool.segments[k];
    const double len = s.kind == Segment::Line ? std::hypot(s.b[0] - s.a[0], s.b[1] - s.a[1]) : 0;
    if (len > longest) longest = len, best = (int)k;
  }
  return best;
}

} // namespace tf
