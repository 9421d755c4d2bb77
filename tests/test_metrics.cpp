// Shape metrics of docs/theory.md ("Metrics") on constructed outer surfaces, against
// their geometric definitions (no mesh, no MPI):
//  - C after unloading (chord): a straight side gives 0 however it is tilted
//    or shifted (a rigid motion of the side counts nothing: the defect of the
//    old measure against the fixed 45-degree flank line); a side
//    bowed inwards by a circular sag s gives s, bowed outwards 0, and
//    rotating the bowed side rigidly keeps s;
//  - C while loaded (flank line): a straight side on the flank gives 0, a
//    sag s between the outermost contacts gives s; a side that touches the
//    flank only near the corner but the apex fillet too spans to the
//    fillet's end, so its sag is found (a flank-only side read 0);
//  - the corner radius of a circle through the axis node is the circle's;
//  - the surface crossing itself (metrics/crossing.hpp): a closed ring of edges crosses nowhere; pulled in at one
//    node until it passes the opposite side, its crossing is found where the two straight edges meet (solved
//    by hand below), whatever order the edges come in; a node pulled only onto the opposite edge (touching, not
//    crossing) or two edges on one line count nothing.
// Tolerance 1e-12 mm: exact geometry up to round-off of coordinates ~20 mm.
#include <algorithm>
#include <cmath>
#include <vector>

#include "check.hpp"
#include "tubeform/metrics/crossing.hpp"
#include "tubeform/metrics/shape.hpp"

using namespace tf;

namespace {

// n + 1 points along the 45-degree flank x + y = h sqrt2 from s = -L to L,
// bowed towards the origin by sag * (1 - (s/L)^2) (a parabola: its largest gap
// is `sag`, at the middle).
std::vector<SurfacePoint> Side(double h, double L, double sag, int n)
{
  std::vector<SurfacePoint> p;
  const double r2 = 1 / std::sqrt(2.0);
  for (int k = 0; k <= n; ++k) {
    const double s = -L + 2 * L * k / n, g = sag * (1 - (s / L) * (s / L));
    // Point on the line, then moved along the inward normal (-1, -1)/sqrt2 by g.
    const double x = h * r2 + s * r2 - g * r2, y = h * r2 - s * r2 - g * r2;
    p.push_back({x, y, 1, 1, k});
  }
  return p;
}

// The points turned by angle a about (cx, cy) and shifted by (dx, dy).
std::vector<SurfacePoint> Moved(std::vector<SurfacePoint> p, double a, double cx, double cy, double dx, double dy)
{
  const double c = std::cos(a), s = std::sin(a);
  for (auto &q : p) {
    const double x = q.x - cx, y = q.y - cy;
    q.x = cx + c * x - s * y + dx, q.y = cy + s * x + c * y + dy;
  }
  return p;
}

// The closed ring of n edges through n points on a circle of radius r, node k at angle 2 pi k / n.
std::vector<SurfaceEdge> Ring(double r, int n)
{
  std::vector<SurfaceEdge> e;
  for (int k = 0; k < n; ++k) {
    const double a = 2 * M_PI * k / n, b = 2 * M_PI * (k + 1) / n;
    e.push_back({{r * std::cos(a), r * std::sin(a)}, {r * std::cos(b), r * std::sin(b)}, k, (k + 1) % n});
  }
  return e;
}

// The ring with node 0 moved to p (both edges it ends).
std::vector<SurfaceEdge> Pulled(std::vector<SurfaceEdge> e, const Vec2 &p)
{
  for (auto &f : e) {
    if (f.na == 0) f.a = p;
    if (f.nb == 0) f.b = p;
  }
  return e;
}

void CheckSelfCrossing()
{
  const double r = 10, tol = 1e-12;
  const int n = 8; // node 4 at (-r, 0); edges 3-4 and 4-5 its neighbours
  CHECK(!FindSelfCrossing(Ring(r, n)).found);
  // Node 0 pulled along y = 0 to x = -1.5 r: its edge 0-7 crosses 4-5 and, mirrored in y = 0, its edge 0-1 crosses
  // 3-4; the pair of the lowest nodes is 0-1 with 3-4. Edge 0-7 runs from (X, 0) to (r c, -r c), c = cos 45, 4-5
  // from (-r, 0) to (-r c, -r c): their lines, y = -r c (x - X) / (r c - X) and y = -(x + r) c / (1 - c), solved
  // by hand; the crossing found is that point mirrored, (x, -y).
  const double c = std::cos(M_PI / 4), X = -1.5 * r;
  const SelfCrossing hit = FindSelfCrossing(Pulled(Ring(r, n), {X, 0}));
  CHECK(hit.found);
  const double x = (X * (r - r * c) + r * (r * c - X)) / ((r - r * c) - (r * c - X));
  const double y = -(x + r) * c / (1 - c);
  CHECK_NEAR(hit.at[0], x, tol);
  CHECK_NEAR(hit.at[1], -y, tol);
  CHECK(hit.nodes[0] == 0 && hit.nodes[1] == 1 && hit.nodes[2] == 3 && hit.nodes[3] == 4);
  // The same answer whatever order the edges come in (the ranks gather them in theirs).
  auto reversed = Pulled(Ring(r, n), {X, 0});
  std::reverse(reversed.begin(), reversed.end());
  const SelfCrossing again = FindSelfCrossing(reversed);
  CHECK(again.found && again.at[0] == hit.at[0] && again.at[1] == hit.at[1]);
  for (int k = 0; k < 4; ++k) CHECK(again.nodes[k] == hit.nodes[k]);
  // Node 0 pulled exactly onto node 4's place: edges touch at a point, none crosses another's interior.
  CHECK(!FindSelfCrossing(Pulled(Ring(r, n), Ring(r, n)[4].a)).found);
  // Two edges on one line, overlapping: no crossing (their ends lie on each other's line).
  CHECK(!FindSelfCrossing({{{0, 0}, {2, 0}, 0, 1}, {{1, 0}, {3, 0}, 2, 3}}).found);
}

} // namespace

int main()
{
  const double h = 17.5, L = 6.0, tol = 1e-12; // flank x + y = h sqrt2, a side 2L long
  // Chord after unloading.
  const auto straight = Side(h, L, 0.0, 24);
  CHECK_NEAR(ChordGap(straight, 0, straight.size() - 1), 0.0, tol);
  for (double a : {0.05, -0.2, 0.7}) {
    const auto turned = Moved(straight, a, 3.0, 14.0, 0.4, -1.1);
    CHECK_NEAR(ChordGap(turned, 0, turned.size() - 1), 0.0, tol);
  }
  const double sag = 0.37;
  const auto bowed = Side(h, L, sag, 24);
  CHECK_NEAR(ChordGap(bowed, 0, bowed.size() - 1), sag, tol);
  CHECK_NEAR(ChordGap(bowed, bowed.size() - 1, 0), sag, tol); // ends in either order
  const auto bowed_turned = Moved(bowed, 0.3, 5.0, 9.0, 0.2, 0.1);
  CHECK_NEAR(ChordGap(bowed_turned, 0, bowed_turned.size() - 1), sag, 1e-11);
  const auto outward = Side(h, L, -sag, 24);
  CHECK_NEAR(ChordGap(outward, 0, outward.size() - 1), 0.0, tol);
  // Only the points between the two ends count: the chord y = 10 from x = -1 to
  // 1 with a point 0.5 inside it, and one far inside beyond the end.
  const std::vector<SurfacePoint> few = {{-1, 10}, {0, 9.5}, {1, 10}, {2, 3}};
  CHECK_NEAR(ChordGap(few, 0, 2), 0.5, tol);

  // Loaded: gaps to the flank line between the outermost contacts.
  const double r2 = 1 / std::sqrt(2.0);
  const Line flank{{h * r2, h * r2}, {-r2, -r2}, {-r2, r2}};
  const GapRange g0 = GapsTo(straight, flank, -L, L);
  CHECK(!g0.empty());
  CHECK_NEAR(std::max(g0.max, 0.0), 0.0, tol);
  const GapRange g1 = GapsTo(bowed, flank, -L, L);
  CHECK_NEAR(g1.max, sag, tol);
  CHECK(GapsTo(bowed, flank, 2 * L, 3 * L).empty());

  // The side's span (SideOnFlank). Along this flank s = -(the parameter of
  // Side), so the bowed side's first point (k = 0) is its apex end, at s = L.
  const int n = static_cast<int>(bowed.size()) - 1;
  auto touching = [&](std::vector<int> flank_nodes, int apex_node) {
    auto p = bowed;
    for (auto &q : p) q.contact = 0, q.segment = -1;
    for (int k : flank_nodes) p[k].contact = 1, p[k].segment = 1;
    if (apex_node >= 0) p[apex_node].contact = 1, p[apex_node].segment = 0;
    return p;
  };
  // Both ends on the flank: the side between them, its sag found.
  auto both = touching({0, n}, -1);
  SideSpan sp = SideOnFlank(both, flank, 1, 0, L);
  CHECK(!sp.empty() && sp.ends[0] == static_cast<size_t>(n) && sp.ends[1] == 0);
  CHECK_NEAR(GapsTo(both, flank, sp.smin, sp.smax).max, sag, tol);
  // Folded in: the flank touched only near the corner (k = n - 1, n), the apex
  // fillet touched beyond the side's apex end. The side reaches the fillet's
  // end (s = L, nearest point k = 0) and its sag is found; without the apex
  // rule it would be the sliver between the two corner contacts.
  auto folded = touching({n - 1, n}, 0);
  sp = SideOnFlank(folded, flank, 1, 0, L);
  CHECK(sp.ends[0] == static_cast<size_t>(n) && sp.ends[1] == 0);
  CHECK_NEAR(sp.smax, L, tol);
  CHECK_NEAR(GapsTo(folded, flank, sp.smin, sp.smax).max, sag, tol);
  auto corner_only = touching({n - 1, n}, -1);
  sp = SideOnFlank(corner_only, flank, 1, 0, L);
  CHECK(GapsTo(corner_only, flank, sp.smin, sp.smax).max < 0.2 * sag);
  // Only the apex touches: no side yet.
  CHECK(SideOnFlank(touching({}, 0), flank, 1, 0, L).empty());

  // Corner radius: nodes on a circle of radius R centred on the x axis at c.
  const double R = 4.0, c = 13.5, t = 0.15;
  CHECK_NEAR(AxisCornerRadius(c + R, c + R * std::cos(t), R * std::sin(t)), R, 1e-10);
  CheckSelfCrossing();
  return ReportChecks("test_metrics");
}
