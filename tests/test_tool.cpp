// Unit tests of the tools' geometry on concave and convex arcs of both
// orientations: an upper die (the body below it) and its
// images under the eight maps of a square onto itself (TurnMap: the mirror
// image below the body, MirrorY, is the half model's lower die; the quarter
// turns are the dies of a pass that turns the tube) and turns by other angles.
//   - A point at distance delta from any segment, on the body's side along the
//     segment's normal (from the construction: centre, radius, angle), projects
//     back onto it with gap delta, that normal, and curvature +1/R on concave
//     arcs, -1/R on convex ones, 0 on lines; its image does the same on the
//     mapped tool, with the normal mapped (the map applied to the
//     construction's numbers here, independently of Transform's arcs).
//   - First contact: the point moving by -2 delta n meets the static tool at
//     r = 1/2 exactly, on arcs by the quadratic of Tool::FirstContact; the
//     mapped tool, moving by its own (mapped) direction, meets the mapped
//     point at the same r, and an original die moving by U meets a point
//     rising towards it where the closed form says.
// ClearanceBack (how far back a second pass's die starts to clear the tube) against
// the closed forms of a plate and the V-die over a circle larger than the tube's.
// The motions and their registry against hand values (CheckMotions). The shapes' registry (CheckShapes): the
// V-die's flanks tangent to the tube's circle (the closed form: a point of the circle at the flank's normal
// angle projects onto it with gap 0, 1e-12 mm: round-off of a 17.5 mm geometry), its apex on the y axis at
// h - r_apex / sin + r_apex; the plate along its line; the flat-bottomed die from its profile file and from the
// DXF drawing of it (options/dies/) the same segments to 1e-12 mm (the DXF's bulge is the arc's, given to 16
// digits); refusals name what is wrong.
// The tools: the flat-bottomed die of options/dies/flat_bottom.profile (a
// concave fillet between face and flank) and the V-die with a parting face
// (a concave apex fillet, the tube inside its circle, and a convex edge
// fillet).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "check.hpp"
#include "tubeform/tool/profile.hpp"
#include "tubeform/tool/shape.hpp"
#include "tubeform/tool/tool.hpp"

using namespace tf;

namespace {

// Every segment of `tool` and of its image under `map`, sampled at three points.
void CheckImage(const Tool &tool, const TurnMap &map, int &concave, int &convex)
{
  const double delta = 0.05;
  const Tool image = Transform(tool, map);
  CHECK_NEAR(image.Direction()[0], map(tool.Direction())[0], 0.0);
  CHECK_NEAR(image.Direction()[1], map(tool.Direction())[1], 0.0);
  for (size_t k = 0; k < tool.segments.size(); ++k) {
    const Segment &s = tool.segments[k];
    if (s.kind == Segment::Arc && map.identity()) (s.concave ? concave : convex)++;
    for (double f : {0.2, 0.5, 0.8}) {
      Vec2 q, n;
      double curvature = 0;
      if (s.kind == Segment::Line) {
        q = {s.a[0] + f * (s.b[0] - s.a[0]), s.a[1] + f * (s.b[1] - s.a[1])};
        n = s.n_line;
      } else {
        const double t = s.t0 + f * (s.t1 - s.t0), sg = s.concave ? -1.0 : 1.0;
        q = {s.c[0] + s.radius * std::cos(t), s.c[1] + s.radius * std::sin(t)};
        n = {sg * std::cos(t), sg * std::sin(t)};
        curvature = (s.concave ? 1.0 : -1.0) / s.radius;
      }
      const Vec2 p = {q[0] + delta * n[0], q[1] + delta * n[1]};
      const Projection a = tool.Project(p), b = image.Project(map(p));
      CHECK(a.segment == (int)k && b.segment == (int)k);
      CHECK_NEAR(a.gap, delta, 1e-12);
      CHECK_NEAR(b.gap, delta, 1e-12);
      CHECK_NEAR(a.n[0], n[0], 1e-12);
      CHECK_NEAR(a.n[1], n[1], 1e-12);
      CHECK_NEAR(b.n[0], map(n)[0], 1e-12);
      CHECK_NEAR(b.n[1], map(n)[1], 1e-12);
      CHECK_NEAR(a.curvature, curvature, 1e-12);
      CHECK_NEAR(b.curvature, curvature, 1e-12);
      // Straight at the surface along -n: half way there in a step of 2 delta.
      const Vec2 dx = {-2 * delta * n[0], -2 * delta * n[1]}, back = {-dx[0], -dx[1]};
      CHECK_NEAR(tool.FirstContact(p, dx, 0.0), 0.5, 1e-9);
      CHECK_NEAR(image.FirstContact(map(p), map(dx), 0.0), 0.5, 1e-9);
      // Moving away it never meets the segment it left.
      CHECK(tool.FirstContact(p, back, 0.0) > 1);
      CHECK(image.FirstContact(map(p), map(back), 0.0) > 1);
      // A line coming down by dU onto a point that stays: gap delta closed at the rate dU (-n_y); the image
      // moving by its own direction closes the image's gap alike.
      if (s.kind == Segment::Line && n[1] < -0.2) {
        const double dU = 2 * delta / -n[1];
        CHECK_NEAR(tool.FirstContact(p, {0, 0}, dU), 0.5, 1e-9);
        CHECK_NEAR(image.FirstContact(map(p), {0, 0}, dU), 0.5, 1e-9);
      }
    }
  }
}

// The eight maps themselves: the images of the axes (the reflection y -> -y, then q quarter turns
// counter-clockwise), each undone by its inverse, the determinant -1 for the reflections.
void CheckMaps()
{
  const Vec2 ex = {1, 0}, ey = {0, 1};
  const Vec2 turned[4] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}}; // (1, 0) after q quarter turns
  for (bool reflect : {false, true})
    for (int q = 0; q < 4; ++q) {
      const TurnMap map{reflect, q};
      const Vec2 x = map(ex), y = map(ey), v = {0.3, -1.7}, back = map.Inverse()(map(v));
      CHECK(x[0] == turned[q][0] && x[1] == turned[q][1]);
      // y: (0, 1), or (0, -1) reflected first, then turned: (1, 0) turned by q + 1 (q + 3) quarter turns
      const Vec2 &ty = turned[(q + (reflect ? 3 : 1)) % 4];
      CHECK(y[0] == ty[0] && y[1] == ty[1]);
      CHECK(back[0] == v[0] && back[1] == v[1]);
      CHECK(map.det() == (reflect ? -1.0 : 1.0));
    }
  CHECK(TurnMap::Turn(-1).q == 3 && TurnMap::Turn(5).q == 1);
  // A turn by any angle: its whole quarter turns exact, the rest a rotation; undone by its inverse to round-off.
  for (double a : {0.3, -0.7, 2.5, M_PI / 4, -3 * M_PI / 4}) {
    const TurnMap map = TurnMap::TurnBy(a);
    const Vec2 v = {0.3, -1.7}, w = map(v), back = map.Inverse()(w);
    CHECK(std::abs(map.angle) <= M_PI / 4 + 1e-15);
    CHECK_NEAR(w[0], std::cos(a) * v[0] - std::sin(a) * v[1], 1e-14);
    CHECK_NEAR(w[1], std::sin(a) * v[0] + std::cos(a) * v[1], 1e-14);
    CHECK_NEAR(back[0], v[0], 1e-14);
    CHECK_NEAR(back[1], v[1], 1e-14);
  }
  CHECK(TurnMap::TurnBy(M_PI / 2).q == 1 && TurnMap::TurnBy(M_PI / 2).angle == 0);
}

// The tool under all eight maps (MirrorY and MirrorX are two of them).
void CheckAllImages(const Tool &tool, const char *name, int &concave, int &convex)
{
  for (bool reflect : {false, true})
    for (int q = 0; q < 4; ++q) CheckImage(tool, {reflect, q}, concave, convex);
  // (and turned by angles that are no quarter turns: a second pass's dies turned by -pass2_turn 45 and others)
  for (double a : {M_PI / 4, -0.7, 2.5}) CheckImage(tool, TurnMap::TurnBy(a), concave, convex);
  std::printf("%s: %zu segments and their images under the 8 maps of a square and 3 other turns\n", name,
              tool.segments.size());
}

// ClearanceBack against closed forms: points on a circle of radius R > Ro inside a die that touches the circle
// of radius Ro at stroke 0. A flat plate at y = Ro moving down clears them moved up by R - Ro; the paper's
// V-die (flanks at 45 degrees, their distance from the centre growing by b / sqrt 2 as it moves up by b) by
// sqrt 2 (R - Ro), while the apex fillet (on the axis at Ro sqrt 2 - 3 sqrt 2 + 3 = 23.51 mm, its ends at
// 22.63 mm) stays above R.
void CheckClearance()
{
  const double ro = 17.5, r = ro + 0.3, tol = 1e-9;
  std::vector<Vec2> circle;
  for (int k = 0; k <= 720; ++k) circle.push_back({r * std::cos(k * M_PI / 360), r * std::sin(k * M_PI / 360)});
  const Tool plate = BuildFlatPlate(ro, 0, 30), vdie = BuildVDie(ro, 3.0);
  // (to the depth tol it allows, and the bisection's 1e-12 of the extent)
  CHECK_NEAR(ClearanceBack(plate, circle, tol), r - ro - tol, 5e-11);
  CHECK_NEAR(ClearanceBack(vdie, circle, tol), std::sqrt(2.0) * (r - ro - tol), 5e-11);
  // Moved back by that, the nearest point is on the die's surface (within the tolerance), none inside it.
  double nearest = kNever;
  const Tool back = MovedBack(vdie, ClearanceBack(vdie, circle, tol));
  for (const Vec2 &p : circle) {
    const Projection pr = back.Project(p);
    if (pr.segment >= 0) nearest = std::min(nearest, pr.gap);
  }
  CHECK(nearest >= -tol && nearest < 1e-9);
  // Already clear: 0. A tool that does not move cannot clear points inside it: -1.
  CHECK(ClearanceBack(vdie, {{0, 0}, {ro, 0}}, tol) == 0);
  Tool fixed = plate;
  fixed.motion = FixedMotion();
  CHECK(ClearanceBack(fixed, circle, tol) == -1);
  std::printf("ClearanceBack: the plate and the V-die clear a circle of radius Ro + 0.3 as the closed forms say\n");
}

// A tool's path of its own (tool/path.hpp): through its points at strokes of half the distance along it, the
// motion of the piece ahead at each point, straight on past the end; mapped with the tool.
void CheckPath()
{
  const ToolPath path({{0, -2}, {0.5, -2}, {0.5, -3}}); // (lengths 2, 0.5, 1: strokes 1, 1.25, 1.75)
  CHECK(path.end() == 1.75 && path.Turns() == std::vector<double>({1.0, 1.25}));
  const Vec2 a = path.At(1.0), b = path.At(1.25), c = path.At(1.75), d = path.At(2.0), e = path.At(1.1);
  CHECK(a[0] == 0 && a[1] == -2 && b[0] == 0.5 && b[1] == -2 && c[0] == 0.5 && c[1] == -3);
  CHECK(d[0] == 0.5 && d[1] == -3.5 && std::abs(e[0] - 0.2) < 1e-15 && e[1] == -2);
  // (at a point, and within round-off below it, a step runs on the piece after it)
  const Vec2 m0 = path.Motion(0.5), m1 = path.Motion(1.0), m2 = path.Motion(1.25 - 1e-15), m3 = path.Motion(9);
  CHECK(m0[0] == 0 && m0[1] == -2 && m1[0] == 2 && m1[1] == 0 && m2[0] == 0 && m2[1] == -2 && m3[1] == -2);
  CHECK(path.Deepest() == 3 && ToolPath().empty() && ToolPath().Turns().empty());
  Tool die = BuildVDie(17.5, 3.0);
  die.motion = PathMotion(path);
  die.stroke = 1.1;
  die.FollowPath();
  const Tool mirrored = MirrorX(die);
  CHECK(die.Direction()[0] == 2 && mirrored.Offset()[0] == -die.Offset()[0] && mirrored.Offset()[1] == die.Offset()[1]);
  std::printf("ToolPath: points, pieces and the motion ahead as drawn; mirrored with the tool\n");
}

// A path that turns the tool (-die_path_turn): down 2 turning by 0.1 rad, then turning back to 0 in place (a
// piece of length reach x 0.1 = 1, at reach 10). A plate y = 1 (body below) turned about its frame's origin (0, 1).
void CheckTurningPath()
{
  const ToolPath path({{0, -2}, {0, -2}}, {0.1, 0.0}, 10.0);
  const double first = 0.5 * std::hypot(2.0, 1.0); // (the first piece: 2 down and 10 x 0.1 of turn)
  CHECK(std::abs(path.end() - (first + 0.5)) < 1e-15 && path.Turns().size() == 1);
  CHECK(std::abs(path.Turn(first) - 0.1) < 1e-15 && std::abs(path.Turn(first + 0.25) - 0.05) < 1e-15);
  CHECK(std::abs(path.Spin(0) - 0.1 / first) < 1e-15 && std::abs(path.Spin(first) + 0.2) < 1e-15);
  Tool plate = BuildFlatPlate(1.0, -5.0, 5.0);
  plate.origin = {0, 1};
  plate.motion = PathMotion(path);
  plate.stroke = first;
  plate.FollowPath();
  // At the turn: the origin moved to (0, -1), the plate turned by 0.1 about it.
  const double c = std::cos(0.1), s = std::sin(0.1);
  const Vec2 q = plate.Placed({3, 1}), v = plate.Velocity({0, -1});
  CHECK(std::abs(q[0] - 3 * c) < 1e-14 && std::abs(q[1] - (-1 + 3 * s)) < 1e-14);
  CHECK(v[0] == 0 && v[1] == 0 &&
        std::abs(plate.Spin() + 0.2) < 1e-15); // (the second piece only turns, about the centre)
  const Vec2 w = plate.Velocity({0, 2});       // (3 above the centre: turning clockwise moves it along x)
  CHECK(std::abs(w[0] - 0.6) < 1e-15 && w[1] == 0);
  // A point below the turned plate: its gap along the turned normal, its projection on the turned line.
  const Projection pr = plate.Project({0, -3});
  CHECK(std::abs(pr.gap - 2 * c) < 1e-14 && std::abs(pr.n[0] - s) < 1e-15 && std::abs(pr.n[1] + c) < 1e-15);
  // r4 of a point 2 below the centre as the plate turns back by 0.05: moving with the plate's point there
  // (0.25 x (-0.4, 0)) and across the gap 2 cos(0.1) along the normal, it meets the plate at the step's end.
  CHECK(std::abs(plate.FirstContact({0, -3}, {-0.1 - 2 * c * s, 2 * c * c}, 0.25) - 1.0) < 1e-12);
  // Mirrored (x -> -x): the turns and the spin change sign.
  const Tool mirrored = MirrorX(plate);
  CHECK(mirrored.Turn() == -plate.Turn() && mirrored.Spin() == -plate.Spin());
  const Vec2 mq = mirrored.Placed({-3, 1});
  CHECK(std::abs(mq[0] + q[0]) < 1e-14 && std::abs(mq[1] - q[1]) < 1e-14);
  std::printf("ToolPath with turns: the turn and spin along it; a turned plate placed, projected on, met; mirrored\n");
}

} // namespace

// The motions (tool/motion.hpp) and their registry, against hand values: each kind made by its name and refusing
// a spec it cannot move by; a copied tool's motion its own; the schedule (-lower_die_path) through its points at
// their strokes, standing after the last, its pieces taken from a stroke at (or within round-off below) a point.
void CheckMotions()
{
  const std::vector<std::string> builtin{"fixed", "stroke", "path", "force", "schedule"};
  const std::vector<std::string> kinds = MotionKinds(); // (the built-in ones first, a new kind after them)
  CHECK(kinds.size() >= builtin.size() && std::equal(builtin.begin(), builtin.end(), kinds.begin()));
  MotionSpec spec;
  spec.direction = {0.5, -2};
  spec.points = {{0, -2}};
  spec.at = {1, 2}, spec.to = {{0, 0}, {0, 1}};
  for (const std::string &kind : builtin) {
    MotionHandle m;
    CHECK(MakeMotion(kind, spec, m).empty() && m->Kind() == kind && m->Unknown() == (kind == "force"));
    // (what the press asks of a kind by its name: the motion's own answer; only the path carries its path)
    CHECK(MotionStrokeUnknown(kind) == m->Unknown() && MotionOwnsPath(kind) == (kind == "path"));
  }
  CHECK(!MotionStrokeUnknown("spiral") && !MotionOwnsPath("spiral"));
  MotionHandle m;
  const std::string unknown = MakeMotion("spiral", spec, m);
  CHECK(unknown.find("spiral") != std::string::npos && unknown.find("schedule") != std::string::npos);
  MotionSpec none;
  none.direction = {0, 0};
  CHECK(!MakeMotion("stroke", none, m).empty() && !MakeMotion("force", none, m).empty());
  CHECK(!MakeMotion("path", none, m).empty() && !MakeMotion("schedule", none, m).empty());
  none.at = {1, 1}, none.to = {{0, 0}, {0, 1}}; // (strokes that do not rise)
  CHECK(!MakeMotion("schedule", none, m).empty());
  // A schedule by its distances along its direction: (0, 0) and 1 x (0.5, -2) at strokes 1 and 2.
  MotionSpec along;
  along.direction = {0.5, -2}, along.at = {1, 2}, along.along = {0, 1};
  CHECK(MakeMotion("schedule", along, m).empty() && m->Offset(3)[0] == 0.5 && m->Offset(3)[1] == -2);
  CHECK(m->Offset(0.5)[0] == 0 && !std::signbit(m->Offset(0.5)[0]) && m->Offset(1.5)[1] == -1);
  // A stroke: s x direction; fixed: nothing; a copy followed elsewhere leaves the original's piece.
  CHECK(MakeMotion("stroke", spec, m).empty() && m->Offset(2)[0] == 1 && m->Offset(2)[1] == -4);
  CHECK(MakeMotion("fixed", spec, m).empty() && m->Offset(3)[0] == 0 && m->Offset(3)[1] == 0);
  Tool lower = BuildFlatPlate(-1.0, -5, 5, true);
  CHECK(MakeMotion("schedule", spec, lower.motion).empty());
  Tool copy = lower;
  copy.stroke = 1.5, copy.FollowPath();
  CHECK(lower.Direction()[1] == 0 && copy.Direction()[1] == 1);
  // The schedule: still to U = 1, up to 1 at U = 2, then standing.
  const Motion &s = *lower.motion;
  CHECK(s.Offset(0.5)[1] == 0 && s.Offset(1.5)[1] == 0.5 && s.Offset(2)[1] == 1 && s.Offset(3)[1] == 1);
  CHECK((s.Kinks(3) == std::vector<double>{1, 2}) && (s.Kinks(2) == std::vector<double>{1}));
  for (auto [at, dy] : {std::pair{0.5, 0.0}, {1.0 - 1e-15, 1.0}, {1.0, 1.0}, {1.9, 1.0}, {2.0, 0.0}, {2.5, 0.0}}) {
    lower.stroke = at, lower.FollowPath();
    CHECK(lower.Direction()[0] == 0 && lower.Direction()[1] == dy);
  }
  // Mirrored (y -> -y) with its tool: the offsets and the motion.
  const Tool image = MirrorY(copy);
  CHECK(image.Offset()[1] == -copy.Offset()[1] && image.Direction()[1] == -1 && image.Offset()[1] == -0.5);
  std::printf("Motions: the registry's kinds and refusals; the schedule through its points, piece by piece\n");
}

// The shapes' registry (the comment at the top). `root`: the source tree (for options/dies/).
void CheckShapes(const std::string &root)
{
  CHECK((ShapeKinds() == std::vector<std::string>{"v", "flat", "profile", "dxf"}));
  ShapeSpec v;
  v.ro = 17.5, v.r_apex = 3.0, v.angle = 90;
  Tool die;
  CHECK(MakeShape("v", v, die).empty());
  const double c = std::sqrt(0.5), h = 17.5 * std::sqrt(2.0);
  const Projection on_flank = die.Project({17.5 * c, 17.5 * c});
  CHECK(on_flank.segment >= 0 && std::abs(on_flank.gap) < 1e-12);
  const double top = h - 3.0 * std::sqrt(2.0) + 3.0; // (the fillet's circle, centred on the axis, at its top)
  const Projection apex = die.Project({0, top - 0.5});
  CHECK(std::abs(apex.point[1] - top) < 1e-12 && std::abs(apex.point[0]) < 1e-12 && std::abs(apex.gap - 0.5) < 1e-12);
  v.u_close = 2 * h; // (a parting face above the apex)
  CHECK(!MakeShape("v", v, die).empty());
  ShapeSpec plate;
  plate.y = 2.0, plate.x0 = -1, plate.x1 = 4, plate.floor = true;
  CHECK(MakeShape("flat", plate, die).empty() && die.segments.size() == 1 && die.Project({1, 3}).gap == 1.0);
  std::string texts[2];
  const char *files[2] = {"/options/dies/flat_bottom.profile", "/options/dies/flat_bottom.dxf"};
  for (int k = 0; k < 2; ++k) {
    std::FILE *f = std::fopen((root + files[k]).c_str(), "r");
    CHECK(f != nullptr);
    for (int ch; f && (ch = std::fgetc(f)) != EOF;) texts[k] += (char)ch;
    if (f) std::fclose(f);
  }
  Tool drawn[2];
  for (int k = 0; k < 2; ++k) {
    ShapeSpec s;
    s.text = texts[k], s.file = files[k];
    CHECK(DrawingKind(s.file) == (k ? "dxf" : "profile") && MakeShape(DrawingKind(s.file), s, drawn[k]).empty());
  }
  CHECK(drawn[0].segments.size() == drawn[1].segments.size() && drawn[0].segments.size() == 3);
  for (size_t k = 0; k < drawn[0].segments.size() && k < drawn[1].segments.size(); ++k) {
    const Segment &a = drawn[0].segments[k], &b = drawn[1].segments[k];
    const double ends = std::hypot(a.a[0] - b.a[0], a.a[1] - b.a[1]) + std::hypot(a.b[0] - b.b[0], a.b[1] - b.b[1]);
    const double arc = std::hypot(a.c[0] - b.c[0], a.c[1] - b.c[1]) + std::abs(a.radius - b.radius) +
                       17.5 * (std::abs(a.t0 - b.t0) + std::abs(a.t1 - b.t1)); // (angles as arc lengths at Ro)
    CHECK(a.kind == b.kind && (a.kind == Segment::Line ? ends : arc) < 1e-12);
  }
  ShapeSpec broken;
  broken.text = "line 0 1\n", broken.file = "broken.profile";
  CHECK(!MakeShape("profile", broken, die).empty());
  const std::string unknown = MakeShape("oval", v, die);
  CHECK(unknown.find("oval") != std::string::npos && unknown.find("dxf") != std::string::npos);
  // Each kind's options, the names docs/options-reference.md gives under the upper die's prefix die_ (-die_angle,
  // -die_r_apex, -die_u_close, -die_r_edge), each with its help; the others read none (a file is its tool's choice).
  std::vector<std::string> names;
  for (const ShapeOption &o : FindShapeKind("v")->options) names.push_back(o.help.empty() ? "" : o.name);
  CHECK((names == std::vector<std::string>{"angle", "r_apex", "u_close", "r_edge"}));
  CHECK(FindShapeKind("v")->read && FindShapeKind("v")->check && !FindShapeKind("oval"));
  for (const char *k : {"flat", "profile", "dxf"})
    CHECK(FindShapeKind(k)->options.empty() && !FindShapeKind(k)->read && !FindShapeKind(k)->check);
  std::printf(
    "Shapes: the registry's kinds and their options; the V-die against its closed form; a profile and its DXF "
    "alike\n");
}

int main(int argc, char **argv)
{
  int concave = 0, convex = 0;
  const std::string flat = "line 0 17.5 7.0 17.5\n"
                           "arc 7.0 14.5 3.0 90 45\n"
                           "line 9.121320343559642 16.621320343559642 22.75 2.992640687119284\n";
  Tool die;
  CHECK(ParseProfile(flat, "flat_bottom.profile", die).empty());
  CheckAllImages(die, "flat-bottomed die", concave, convex);
  CheckAllImages(BuildVDie(17.5, 3.0, 2.0, 1.5), "V-die with a parting face", concave, convex);
  CHECK(concave == 2 && convex == 1); // both kinds of arc were sampled (the fillets and the V's apex: concave)
  CheckMaps();
  CheckClearance();
  CheckPath();
  CheckTurningPath();
  CheckMotions();
  CheckShapes(argc > 1 ? argv[1] : "..");
  return ReportChecks("test_tool");
}
