// Rigid tools: chains of straight segments and circular arcs moving rigidly
// (docs/dies.md). Pure geometry, no PETSc.
#pragma once

#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "tubeform/core/core.hpp"
#include "tubeform/tool/motion.hpp"
#include "tubeform/tool/path.hpp"
#include "tubeform/tool/turn_map.hpp"

namespace tf {

// A point whose projection falls this far (in units of the segment's length
// or angle range) past a segment's end still projects on it: joints between
// segments are found to round-off.
constexpr double kOnSegment = 1e-12;

// One piece of a tool's working surface. The body lies on the side the
// outward normal n points to; l = n turned by -90 degrees (so (l, n) is a
// right-handed frame).
struct Segment {
  enum Kind { Line, Arc } kind = Line;
  Vec2 a{}, b{};         // line: end points
  Vec2 c{};              // arc: centre
  double radius = 0;     // arc radius
  double t0 = 0, t1 = 0; // arc: angle range [t0, t1] (radians, t0 < t1)
  bool concave = false;  // arc: the body is inside the circle (n points to the centre)
  Vec2 n_line{};         // line: outward normal (towards the body)
};

// Where a point is with respect to the tool surface.
struct Projection {
  int segment = -1;     // closest segment; -1 if the point projects on none
  Vec2 point{};         // closest point on the surface
  Vec2 n{}, l{};        // outward normal and tangent there
  double gap = kNever;  // signed distance along n: > 0 outside the tool, < 0 penetrating
  double curvature = 0; // +1/radius on concave arcs, -1/radius on convex ones, 0 on lines
};

class Tool {
public:
  std::string name;
  std::vector<Segment> segments; // in the tool's frame at stroke 0
  double stroke = 0;             // current stroke
  Vec2 origin{};                 // the frame's origin at stroke 0: the tube's centre, or moved with the die (MovedBack)
  MotionHandle motion;           // how the stroke moves it (tool/motion.hpp; by default straight down)

  // Where the stroke has moved the tool from its drawing.
  Vec2 Offset() const { return motion->Offset(stroke); }
  // How far the stroke has turned it about its frame's origin (radians, counter-clockwise; 0 off a turning path).
  double Turn() const { return motion->Turn(stroke); }
  // Its motion per unit stroke on the piece it follows, and its turn about the frame's origin.
  Vec2 Direction() const { return motion->Direction(); }
  // The line it starts back along (Motion::Axis: MovedBack, ClearanceBack).
  Vec2 Axis() const { return motion->Axis(); }
  double Spin() const { return motion->Spin(); }
  // Force-controlled: its stroke is an unknown of each increment (ContactSet).
  bool Unknown() const { return motion->Unknown(); }
  // A point of the drawing where the tool now is: turned about the frame's origin, then moved by the offset.
  Vec2 Placed(const Vec2 &p) const;
  // A direction of the drawing where the tool now is (turned).
  Vec2 Oriented(const Vec2 &v) const;
  // The motion per unit stroke of the tool's point now at x: along its direction, and about the frame's origin.
  Vec2 Velocity(const Vec2 &x) const;
  // A tool on a path of its own moves and turns along the piece ahead of its stroke (per unit stroke).
  void FollowPath() { motion->Follow(stroke); }
  // Closest point of the surface at the current stroke. Points whose
  // projection falls outside every segment get segment -1.
  Projection Project(const Vec2 &x) const;
  // r4 of docs/theory.md section 5: the smallest r in (0, 1] at which the point
  // x + r dx meets the surface moved by r dU (lines: linear, arcs: quadratic,
  // exact); 1e300 if none. A turning tool's turn is taken linear in r, as the
  // body's rotations are (its step's turn is bounded by r3's rmin_domega).
  double FirstContact(const Vec2 &x, const Vec2 &dx, double dU) const;

private:
  // The point of the drawing now at x, for a tool turned by the angle of cosine c and sine s (Placed's inverse).
  Vec2 Drawn(const Vec2 &x, double c, double s) const;
  Projection ProjectDrawn(const Vec2 &x, const Vec2 &off) const;
  double FirstContactDrawn(const Vec2 &y0, const Vec2 &dy) const;
};

// A tool's working surface as lines for the results (ParaView): the points of
// each segment at the current stroke, arcs every kOutlineStep radians at most,
// and the index pairs of the lines joining them. The counts depend only on the
// segments, so a tool's outline has the same size at every stroke.
struct Outline {
  std::vector<Vec2> points;
  std::vector<std::array<int, 2>> lines;
};
constexpr double kOutlineStep = M_PI / 90; // 2 degrees: an apex fillet of 3 mm is drawn to 1.5 um
Outline ToolOutline(const Tool &t);

// A tool mapped by a TurnMap: its segments (their order kept), the body's side (the normals) and its motion.
Tool Transform(const Tool &t, const TurnMap &map);
// A tool moved by d (its segments and its frame's origin).
Tool Shifted(const Tool &t, const Vec2 &d);
// A tool moved back along its motion by `back` units of stroke (its segments at -back x its axis, Motion::Axis).
inline Tool MovedBack(const Tool &t, double back)
{
  const Vec2 d = t.Axis();
  return Shifted(t, {-back * d[0], -back * d[1]});
}
// How far back along its motion (units of stroke, >= 0) a tool must start so that none of `points` lies more
// than `tol` inside it: 0 if none does where it is; else the least such distance, to 1e-12 of the points'
// extent (bisection between an overlapping start and a clear one). -1 if it overlaps them still when moved
// back by twice their extent (a tool that does not move, or one whose motion leads into them).
double ClearanceBack(const Tool &t, const std::vector<Vec2> &points, double tol);
// The mirror image of a tool about the x axis (y -> -y): its segments, the body's side and its motion.
Tool MirrorY(const Tool &t);
// The mirror image of a tool about the y axis (x -> -x).
Tool MirrorX(const Tool &t);
// A tool drawn right of the y axis with its mirror image left of it (the right half's segments first, so their
// indices stay): the whole tool a full model presses with.
Tool BothSides(const Tool &t);

// A symmetry plane through the origin as a wall that does not move (a fixed motion): the line of the points x with
// x . normal = 0, from -reach to reach along it, the body on the side `normal` (a unit vector) points to.
Tool SymmetryWall(const Vec2 &normal, double reach, const std::string &name);

} // namespace tf
