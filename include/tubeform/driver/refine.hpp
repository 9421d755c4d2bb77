// Accuracy on demand (docs/accuracy.md, "Accuracy on demand"): a run whose
// estimated error passes its targets (-target_load, -target_c_over_t) runs
// again at a finer level, chosen from the estimate's parts: each falls in
// proportion to its cells' size or increment limits (the estimate's first
// order, driver/answer.hpp), so each is refined by the ratio that brings it
// within its share of the target. A level whose estimate does not read its wall (Answer::WallUnread) runs again
// too, its cells at least kReuseRatio finer. A level at most kMaxRatio finer than the last, at most
// -target_levels levels, none that would pass -target_time.
#pragma once

#include <string>

#include "tubeform/driver/answer.hpp"
#include "tubeform/io/options.hpp"

namespace tf {

// The next level aims at this fraction of the target: the next estimate has its own scatter (the validation's
// effectivities spread by about 1.5 x around their median), and a level that lands just above the target costs a
// whole further level.
constexpr double kTargetAim = 0.7;
// At most this ratio of cell size and of increment limits from one level to the next: the estimate bounds the
// error at a median of about 2.7 x (docs/accuracy.md), so a larger jump would overshoot the level that meets
// the target by about as much, at the ratio cubed in cost; at 2 the next level's own companion is this level's
// mesh, and each level costs about 8 x the last.
constexpr double kMaxRatio = 2.0;

// A finer level that keeps the last level's increments and whose cells are at least this ratio finer takes the
// last level as its estimate's mesh companion (Companions::mesh_ratio): Richardson's 1 / (r - 1) then multiplies the
// difference's noise (the two meshes' contact phases) at most 2 times; a level refined less, or in its increments
// too, runs companions of its own.
constexpr double kReuseRatio = 1.5;

// What a finer level changes in the options of the last (plain data: it also travels to the ranks of the
// estimate's companions, driver/beside.hpp).
struct LevelChange {
  PetscInt level = 0, mesh_nt = 0, mesh_ntheta = 0, increments = 0;
  double rmin_deps = 0, rmin_deps_yield = 0, rmin_domega = 0;
  // The options of the level `last`, with its own choices kept (Problem::OwnChoices: its element and friction
  // regularization, the first level's), with this change: the levels differ in their cells and increments alone,
  // so that each reads as the last one's finer discretization (its mesh companion, kReuseRatio), not as another
  // element or friction law.
  Options Applied(const Options &last) const;
};

struct Refinement {
  bool follows = false;  // a finer level runs next
  std::string why;       // what decided (a line for the user)
  double mesh_ratio = 1; // the cell size's divisor (through the wall and around)
  double step_ratio = 1; // the increment limits' divisor
  LevelChange change;    // the next level's (follows)
  Options next;          // its options: change.Applied(the last level's)
  // The next level's estimate from this level (kReuseRatio): `companions` as the next level takes them, this level's
  // run as its mesh companion (filled once this level's estimate is made); its increments' part from a run of
  // `last` (this level's options, its own choices kept) at twice its increment limits.
  bool reuse = false;
  Companions companions;
  Options last;
};

// The ratio of a level's cell size to a finer level's: the smaller of the two directions' (through the wall, around).
double CellRatio(const Options &last, const Options &next);

// What comes after a level that ended with `a` (its estimate, targets and parts), which took `level_seconds`,
// `job_seconds` since the job started; `level` its options with its own choices kept (Problem::OwnChoices).
Refinement NextLevel(const Options &level, const Answer &a, double level_seconds, double job_seconds);

} // namespace tf
