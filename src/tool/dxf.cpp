// DXF die profiles through dxflib (Debian's libdxflib-dev): the file's LINE,
// ARC and LWPOLYLINE/POLYLINE entities (bulges as arcs) chained from the one
// that touches the axis x = 0 outward into profile items (tool/profile.hpp).
#include <dxflib/dl_creationadapter.h>
#include <dxflib/dl_dxf.h>

#include <cmath>
#include <cstdio>
#include <sstream>

#include "tubeform/tool/profile.hpp"

namespace tf {

namespace {

// One piece of the drawing as it comes: from p0 to p1, a line or an arc (ProfileItem values walked p0 -> p1).
struct Piece {
  ProfileItem item;
  Vec2 p0, p1;
};

double Dist(const Vec2 &a, const Vec2 &b) { return std::hypot(a[0] - b[0], a[1] - b[1]); }

// The piece walked the other way.
Piece Reversed(Piece p)
{
  std::swap(p.p0, p.p1);
  auto &v = p.item.v;
  if (p.item.arc)
    std::swap(v[3], v[4]);
  else
    std::swap(v[0], v[2]), std::swap(v[1], v[3]);
  return p;
}

class Collector : public DL_CreationAdapter {
public:
  std::vector<Piece> pieces;

  void addLine(const DL_LineData &d) override
  {
    Flush();
    Piece p;
    p.item = {false, {d.x1, d.y1, d.x2, d.y2}, 0, Label("LINE")};
    p.p0 = {d.x1, d.y1}, p.p1 = {d.x2, d.y2};
    pieces.push_back(p);
  }
  void addArc(const DL_ArcData &d) override
  {
    Flush();
    // DXF arcs run counter-clockwise from angle1 to angle2 (degrees).
    const double a2 = d.angle2 > d.angle1 ? d.angle2 : d.angle2 + 360;
    Piece p;
    p.item = {true, {d.cx, d.cy, d.radius, d.angle1, a2}, 0, Label("ARC")};
    const auto at = [&](double a) {
      return Vec2{d.cx + d.radius * std::cos(a * M_PI / 180), d.cy + d.radius * std::sin(a * M_PI / 180)};
    };
    p.p0 = at(d.angle1), p.p1 = at(a2);
    pieces.push_back(p);
  }
  void addPolyline(const DL_PolylineData &d) override
  {
    Flush();
    poly_label_ = Label("LWPOLYLINE");
    closed_ = d.flags & 1;
  }
  void addVertex(const DL_VertexData &d) override { vertices_.push_back(d); }
  void endSequence() override { Flush(); }
  void Flush()
  {
    const size_t n = vertices_.size(), segments = closed_ ? n : (n ? n - 1 : 0);
    for (size_t k = 0; k < segments; ++k) {
      const DL_VertexData &a = vertices_[k], &b = vertices_[(k + 1) % n];
      Piece p;
      p.p0 = {a.x, a.y}, p.p1 = {b.x, b.y};
      const std::string where = poly_label_ + " segment " + std::to_string(k + 1);
      if (a.bulge == 0) {
        p.item = {false, {a.x, a.y, b.x, b.y}, 0, where};
      } else {
        // bulge = tan(theta / 4), theta the signed included angle (counter-clockwise positive).
        const double theta = 4 * std::atan(a.bulge), chord = Dist(p.p0, p.p1);
        const Vec2 u = {(b.x - a.x) / chord, (b.y - a.y) / chord};
        const double off = chord / (2 * std::tan(theta / 2)); // the centre's offset to the chord's left
        const Vec2 c = {0.5 * (a.x + b.x) - u[1] * off, 0.5 * (a.y + b.y) + u[0] * off};
        const double a0 = std::atan2(a.y - c[1], a.x - c[0]) * 180 / M_PI;
        p.item = {
          true, {c[0], c[1], std::abs(chord / (2 * std::sin(theta / 2))), a0, a0 + theta * 180 / M_PI}, 0, where};
      }
      pieces.push_back(p);
    }
    vertices_.clear();
    closed_ = false;
  }

private:
  int count_ = 0;
  std::string poly_label_;
  bool closed_ = false;
  std::vector<DL_VertexData> vertices_;
  std::string Label(const char *kind) { return "entity " + std::to_string(++count_) + " (" + kind + ")"; }
};

std::string Point(const Vec2 &p)
{
  char buf[64];
  std::snprintf(buf, sizeof buf, "(%g, %g)", p[0], p[1]);
  return buf;
}

} // namespace

std::string DxfProfile(const std::string &text, const std::string &file, std::vector<ProfileItem> &items)
{
  Collector drawing;
  DL_Dxf dxf;
  std::istringstream in(text);
  if (!dxf.in(in, &drawing)) return file + ": not a DXF file dxflib can read";
  drawing.Flush();
  std::vector<Piece> &left = drawing.pieces;
  if (left.empty()) return file + ": no LINE, ARC or LWPOLYLINE entity in the drawing";
  // The chain's start: the one piece with an end on the axis.
  std::vector<size_t> on_axis;
  for (size_t k = 0; k < left.size(); ++k)
    if (std::abs(left[k].p0[0]) <= kProfileGap || std::abs(left[k].p1[0]) <= kProfileGap) on_axis.push_back(k);
  if (on_axis.size() != 1)
    return file + ": " + std::to_string(on_axis.size()) +
           " entities touch the axis x = 0; the profile (the die's right half) starts at one";
  Piece first = left[on_axis[0]];
  left.erase(left.begin() + on_axis[0]);
  if (std::abs(first.p0[0]) > kProfileGap) first = Reversed(first);
  items = {first.item};
  Vec2 end = first.p1;
  while (!left.empty()) {
    std::vector<size_t> next;
    for (size_t k = 0; k < left.size(); ++k)
      if (Dist(left[k].p0, end) <= kProfileGap || Dist(left[k].p1, end) <= kProfileGap) next.push_back(k);
    if (next.empty()) break;
    if (next.size() > 1)
      return file + ": " + left[next[0]].item.where + " and " + left[next[1]].item.where + " both go on from " +
             Point(end) + ": the profile must be one chain";
    Piece p = left[next[0]];
    left.erase(left.begin() + next[0]);
    if (Dist(p.p0, end) > kProfileGap) p = Reversed(p);
    items.push_back(p.item);
    end = p.p1;
  }
  if (!left.empty())
    return file + ": " + left[0].item.where + " is not joined to the chain, which ends at " + Point(end) +
           " (a gap of more than 1e-6 mm?)";
  return "";
}

} // namespace tf
