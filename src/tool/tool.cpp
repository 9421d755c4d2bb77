#include "tubeform/tool/tool.hpp"

#include <stdexcept>

#include <algorithm>
#include <cmath>

namespace tf {

namespace {
double Dot(const Vec2 &a, const Vec2 &b) { return a[0] * b[0] + a[1] * b[1]; }
Vec2 Sub(const Vec2 &a, const Vec2 &b) { return {a[0] - b[0], a[1] - b[1]}; }
Vec2 Add(const Vec2 &a, const Vec2 &b) { return {a[0] + b[0], a[1] + b[1]}; }
Vec2 Scale(const Vec2 &a, double s) { return {s * a[0], s * a[1]}; }
Vec2 TangentOf(const Vec2 &n) { return {n[1], -n[0]}; } // n turned by -90 degrees

// Angle of v in [t0, t0 + 2 pi).
double AngleFrom(const Vec2 &v, double t0)
{
  double t = std::atan2(v[1], v[0]);
  while (t < t0) t += 2 * M_PI;
  while (t >= t0 + 2 * M_PI) t -= 2 * M_PI;
  return t;
}

// v turned counter-clockwise by the angle of cosine c and sine s.
Vec2 Rotated(const Vec2 &v, double c, double s) { return {c * v[0] - s * v[1], s * v[0] + c * v[1]}; }
} // namespace

Vec2 Tool::Placed(const Vec2 &p) const
{
  const Vec2 off = Offset();
  const double t = Turn();
  if (t == 0) return Add(p, off);
  return Add(Add(origin, Rotated(Sub(p, origin), std::cos(t), std::sin(t))), off);
}

Vec2 Tool::Oriented(const Vec2 &v) const
{
  const double t = Turn();
  return t == 0 ? v : Rotated(v, std::cos(t), std::sin(t));
}

Vec2 Tool::Drawn(const Vec2 &x, double c, double s) const
{
  return Add(origin, Rotated(Sub(x, Add(origin, Offset())), c, -s));
}

Vec2 Tool::Velocity(const Vec2 &x) const
{
  const Vec2 direction = Direction();
  const double spin = Spin();
  if (spin == 0) return direction;
  const Vec2 centre = Add(origin, Offset());
  return {direction[0] - spin * (x[1] - centre[1]), direction[1] + spin * (x[0] - centre[0])};
}

Projection Tool::Project(const Vec2 &x) const
{
  const double t = Turn();
  if (t == 0) return ProjectDrawn(x, Offset());
  // In the drawing: x turned back about the frame's origin where it now is; the projection turned forward.
  const double c = std::cos(t), s = std::sin(t);
  Projection p = ProjectDrawn(Drawn(x, c, s), {0, 0});
  if (p.segment < 0) return p;
  p.point = Add(Add(origin, Offset()), Rotated(Sub(p.point, origin), c, s));
  p.n = Rotated(p.n, c, s), p.l = Rotated(p.l, c, s);
  return p;
}

Projection Tool::ProjectDrawn(const Vec2 &x, const Vec2 &off) const
{
  Projection best;
  for (size_t k = 0; k < segments.size(); ++k) {
    const Segment &s = segments[k];
    Projection p;
    p.segment = static_cast<int>(k);
    if (s.kind == Segment::Line) {
      const Vec2 a = Add(s.a, off), b = Add(s.b, off), ab = Sub(b, a);
      const double len2 = Dot(ab, ab), t = Dot(Sub(x, a), ab) / len2;
      if (t < -kOnSegment || t > 1 + kOnSegment) continue;
      p.point = Add(a, Scale(ab, std::min(1.0, std::max(0.0, t))));
      p.n = s.n_line;
      p.curvature = 0;
    } else {
      const Vec2 c = Add(s.c, off), d = Sub(x, c);
      const double r = std::hypot(d[0], d[1]);
      if (r == 0) continue;
      const double t = AngleFrom(d, s.t0);
      if (t > s.t1 + kOnSegment) continue;
      const Vec2 e = {d[0] / r, d[1] / r};
      p.point = Add(c, Scale(e, s.radius));
      p.n = s.concave ? Scale(e, -1) : e;
      p.curvature = (s.concave ? 1.0 : -1.0) / s.radius;
    }
    p.l = TangentOf(p.n);
    p.gap = Dot(Sub(x, p.point), p.n);
    if (std::abs(p.gap) < std::abs(best.gap)) best = p;
  }
  return best;
}

double Tool::FirstContact(const Vec2 &x, const Vec2 &dx, double dU) const
{
  const double t = Turn();
  // Relative motion in the tool's frame: y(r) = x - off + r (dx - dU direction).
  if (t == 0 && Spin() == 0) return FirstContactDrawn(Sub(x, Offset()), Sub(dx, Scale(Direction(), dU)));
  // Turning: the same in the drawing, x's motion relative to the tool's point there (Velocity) turned back.
  const double c = std::cos(t), s = std::sin(t);
  return FirstContactDrawn(Drawn(x, c, s), Rotated(Sub(dx, Scale(Velocity(x), dU)), c, -s));
}

double Tool::FirstContactDrawn(const Vec2 &y0, const Vec2 &dy) const
{
  double rmin = kNever;
  for (const Segment &s : segments) {
    if (s.kind == Segment::Line) {
      // (y(r) - a) . n = 0  ->  r = -(y0 - a).n / dy.n, approaching only.
      const double g0 = Dot(Sub(y0, s.a), s.n_line), dg = Dot(dy, s.n_line);
      if (!(dg < 0) || g0 < 0) continue;
      const double r = -g0 / dg;
      if (r <= 0 || r > 1) continue;
      const Vec2 ab = Sub(s.b, s.a), hit = Add(y0, Scale(dy, r));
      const double t = Dot(Sub(hit, s.a), ab) / Dot(ab, ab);
      if (t < -kOnSegment || t > 1 + kOnSegment) continue;
      rmin = std::min(rmin, r);
    } else {
      // |y(r) - c|^2 = R^2: A r^2 + B r + C = 0, C = |y0 - c|^2 - R^2.
      const Vec2 d0 = Sub(y0, s.c);
      const double qa = Dot(dy, dy), qb = 2 * Dot(d0, dy), qc = Dot(d0, d0) - s.radius * s.radius;
      if (qa == 0) continue;
      // Outside the tool: inside the circle for concave arcs (qc < 0), outside for convex.
      if (s.concave ? qc > 0 : qc < 0) continue;
      const double disc = qb * qb - 4 * qa * qc;
      if (disc < 0) continue;
      const double sq = std::sqrt(disc);
      for (double r : {(-qb - sq) / (2 * qa), (-qb + sq) / (2 * qa)}) {
        if (r <= 0 || r > 1) continue;
        const Vec2 hit = Sub(Add(y0, Scale(dy, r)), s.c);
        if (AngleFrom(hit, s.t0) > s.t1 + kOnSegment) continue;
        // Only a crossing towards the tool side counts.
        const Vec2 e = {hit[0], hit[1]};
        const double radial = Dot(e, dy);
        if (s.concave ? radial <= 0 : radial >= 0) continue;
        rmin = std::min(rmin, r);
        break;
      }
    }
  }
  return rmin;
}

TurnMap TurnMap::TurnBy(double radians)
{
  const long quarters = std::lround(radians / (M_PI / 2));
  return {false, (int)(((quarters % 4) + 4) % 4), radians - quarters * (M_PI / 2)};
}

Vec2 TurnMap::operator()(const Vec2 &v) const
{
  const Vec2 r = {v[0], reflect ? -v[1] : v[1]};
  Vec2 t;
  switch (q) {
  case 1:
    t = {-r[1], r[0]};
    break;
  case 2:
    t = {-r[0], -r[1]};
    break;
  case 3:
    t = {r[1], -r[0]};
    break;
  default:
    t = r;
  }
  if (angle == 0) return t;
  const double c = std::cos(angle), s = std::sin(angle);
  return {c * t[0] - s * t[1], s * t[0] + c * t[1]};
}

Tool Transform(const Tool &t, const TurnMap &map)
{
  Tool m = t;
  // An angle t goes to (reflect ? -t : t) + q pi / 2; a reflection reverses the range [t0, t1].
  const double turn = map.q * (M_PI / 2) + map.angle;
  for (Segment &s : m.segments) {
    s.a = map(s.a), s.b = map(s.b), s.c = map(s.c), s.n_line = map(s.n_line);
    const double t0 = s.t0;
    if (map.reflect)
      s.t0 = turn - s.t1, s.t1 = turn - t0;
    else
      s.t0 = t0 + turn, s.t1 = s.t1 + turn;
  }
  m.origin = map(t.origin);
  m.motion->Map(map);
  return m;
}

Tool Shifted(const Tool &t, const Vec2 &d)
{
  Tool m = t;
  for (Segment &s : m.segments) s.a = Add(s.a, d), s.b = Add(s.b, d), s.c = Add(s.c, d);
  m.origin = Add(t.origin, d);
  return m;
}

double ClearanceBack(const Tool &t, const std::vector<Vec2> &points, double tol)
{
  double extent = 0;
  for (const Vec2 &p : points) extent = std::max(extent, std::hypot(p[0], p[1]));
  const auto overlaps = [&](double back) {
    const Tool moved = MovedBack(t, back);
    for (const Vec2 &p : points) {
      const Projection pr = moved.Project(p);
      if (pr.segment >= 0 && pr.gap < -tol) return true;
    }
    return false;
  };
  if (!overlaps(0)) return 0;
  const Vec2 d = t.Axis();
  const double speed = std::hypot(d[0], d[1]);
  if (speed == 0 || overlaps(2 * extent / speed)) return -1;
  double lo = 0, hi = 2 * extent / speed;
  while (hi - lo > 1e-12 * extent / speed) {
    const double mid = 0.5 * (lo + hi);
    (overlaps(mid) ? lo : hi) = mid;
  }
  return hi;
}

// The mirror images about the x axis (y -> -y) and the y axis (x -> -x: the reflection, then half a turn).
Tool MirrorY(const Tool &t) { return Transform(t, {true, 0}); }

Tool MirrorX(const Tool &t) { return Transform(t, {true, 2}); }

Tool BothSides(const Tool &t)
{
  Tool both = t;
  const Tool left = MirrorX(t);
  both.segments.insert(both.segments.end(), left.segments.begin(), left.segments.end());
  return both;
}

Outline ToolOutline(const Tool &t)
{
  Outline o;
  for (const Segment &s : t.segments) {
    const int first = (int)o.points.size();
    if (s.kind == Segment::Line) {
      o.points.push_back(t.Placed(s.a));
      o.points.push_back(t.Placed(s.b));
    } else {
      const int n = std::max(1, (int)std::ceil((s.t1 - s.t0) / kOutlineStep));
      for (int k = 0; k <= n; ++k) {
        const double a = s.t0 + (s.t1 - s.t0) * k / n;
        const Vec2 e = {s.radius * std::cos(a), s.radius * std::sin(a)};
        // (a die that does not turn: the sums in their order before turns, so its outline keeps its last bits)
        o.points.push_back(t.Turn() == 0 ? Add(s.c, Add(t.Offset(), e)) : t.Placed(Add(s.c, e)));
      }
    }
    for (int k = first; k + 1 < (int)o.points.size(); ++k) o.lines.push_back({k, k + 1});
  }
  return o;
}

Tool SymmetryWall(const Vec2 &normal, double reach, const std::string &name)
{
  Tool t;
  t.name = name;
  t.motion = FixedMotion();
  Segment s;
  const Vec2 along = TangentOf(normal); // (its points have no component along the normal: gaps are exact)
  s.a = Scale(along, -reach);
  s.b = Scale(along, reach);
  s.n_line = normal;
  t.segments.push_back(s);
  return t;
}

} // namespace tf
