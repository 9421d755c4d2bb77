#include "tubeform/driver/refine.hpp"

#include <algorithm>
#include <cmath>

#include "tubeform/core/core.hpp"

namespace tf {

namespace {

// The ratios that bring the parts of an error `e` within the target `target` (0: none), each part falling in
// proportion (driver/answer.hpp, kMeshShare): the target shared between
// the mesh and the increments, half each (the cheapest split when the cost grows as the cells times the
// increments), or the whole of it to one part where the other is within its half already.
void Ratios(const ErrorParts &e, double target, double &mesh, double &steps)
{
  if (target <= 0) return;
  const double aim = kTargetAim * target;
  double m_share = aim / 2, s_share = aim / 2;
  if (e.mesh < m_share) s_share = aim - e.mesh;
  if (e.steps < s_share && e.steps < aim / 2) m_share = aim - e.steps;
  if (e.mesh > m_share) mesh = std::max(mesh, e.mesh / m_share);
  if (e.steps > s_share) steps = std::max(steps, e.steps / s_share); // (first order)
}

// n scaled by r and rounded up to a multiple of `multiple`.
PetscInt Scaled(PetscInt n, double r, PetscInt multiple)
{
  const PetscInt m = (PetscInt)std::ceil(n * r - 1e-9);
  return (m + multiple - 1) / multiple * multiple;
}

// Whether a level refined by these ratios takes the last one as its mesh companion (kReuseRatio).
bool Reuses(double step_ratio, double cell_ratio) { return step_ratio == 1 && cell_ratio >= kReuseRatio; }

} // namespace

double CellRatio(const Options &last, const Options &next)
{
  return std::min((double)next.mesh_nt / last.mesh_nt, (double)next.mesh_ntheta / last.mesh_ntheta);
}

Options LevelChange::Applied(const Options &last) const
{
  Options n = last;
  n.level = level, n.mesh_nt = mesh_nt, n.mesh_ntheta = mesh_ntheta, n.driver.increments = increments;
  n.driver.rmin_deps = rmin_deps, n.driver.rmin_deps_yield = rmin_deps_yield, n.driver.rmin_domega = rmin_domega;
  return n;
}

Refinement NextLevel(const Options &level, const Answer &a, double level_seconds, double job_seconds)
{
  Refinement r;
  const AccuracyParams &held = level.accuracy;
  const double load = held.target_load, ct = a.tool ? held.target_c_over_t : 0; // (demanded: 0 none)
  if (!a.demanded || !a.Over()) return r; // (a demand holds the answer to these alone: finish.cpp, HoldTo)
  if (level.level >= held.target_levels) {
    r.why = Formatted("this was level %d of -target_levels %d", (int)level.level, (int)held.target_levels);
    return r;
  }
  Ratios(a.worst_load, load, r.mesh_ratio, r.step_ratio);
  Ratios(a.worst_ct, ct, r.mesh_ratio, r.step_ratio);
  // A wall the estimate cannot read (Answer::wall_covered): the cells at least kReuseRatio finer, so that the next
  // level's mesh companion (this level, or its own companions at half its cells) has other cells through the wall.
  if (a.WallUnread()) r.mesh_ratio = std::max(r.mesh_ratio, kReuseRatio);
  if (!level.mesh_file.empty()) r.mesh_ratio = 1; // (a mesh file is as it is)
  r.mesh_ratio = std::min(r.mesh_ratio, kMaxRatio), r.step_ratio = std::min(r.step_ratio, kMaxRatio);
  // The cost of a level: its cells times its increments, the factorization's growing faster than the cells
  // (a 2D direct solve: about n^1.5, so the ratio cubed).
  const double predicted = level_seconds * std::pow(r.mesh_ratio, 3) * r.step_ratio;
  if (held.target_time > 0 && job_seconds + predicted > held.target_time) {
    r.why = Formatted("the next level (about %.0f s) would pass -target_time %g s", predicted, held.target_time);
    return r;
  }
  LevelChange &c = r.change;
  c = {level.level + 1,         level.mesh_nt,          level.mesh_ntheta,
       level.driver.increments, level.driver.rmin_deps, level.driver.rmin_deps_yield,
       level.driver.rmin_domega};
  if (r.mesh_ratio > 1) {
    // A level that will take this one as its mesh companion (kReuseRatio) runs none: even counts do. Any other runs
    // a companion of half its cells through the wall and around: multiples of 4, so that the companion's counts are
    // even (odd ones converge unevenly, docs/accuracy.md, "The element through the wall").
    const PetscInt multiple = Reuses(r.step_ratio, r.mesh_ratio) ? 2 : 4;
    c.mesh_nt = Scaled(level.mesh_nt, r.mesh_ratio, multiple);
    c.mesh_ntheta = Scaled(level.mesh_ntheta, r.mesh_ratio, multiple);
  }
  if (r.step_ratio > 1) {
    c.increments = Scaled(level.driver.increments, r.step_ratio, 1);
    c.rmin_deps /= r.step_ratio, c.rmin_deps_yield /= r.step_ratio, c.rmin_domega /= r.step_ratio;
  }
  r.next = c.Applied(level), r.last = level;
  const Options &n = r.next;
  r.follows = true;
  r.reuse = Reuses(r.step_ratio, CellRatio(level, n)); // (the counts as rounded: multiples of 4 may reach it too)
  r.why =
    Formatted("level %d follows: %d x %d cells, %d trial increments, increment limits / %.2g (about %.0f s)",
              (int)n.level, (int)n.mesh_nt, (int)n.mesh_ntheta, (int)n.driver.increments, r.step_ratio, predicted);
  return r;
}

} // namespace tf
