// What each springback of a run did at the yield surface, from its history's release columns (the rows with
// `release` 1 or 2, one run of them per release: each of a tool scene's passes): the Gauss points that
// reached the surface, how far an elastic springback carried a point past it, the largest plastic strain the
// material's law took in it, and its plastic work against the elastic energy stored at its start. Written as
// attributes and said in the run's last lines, with a warning when an elastic springback passes the surface or
// one by the material's law dissipates more than it had stored (docs/theory.md, "Unloading").
#pragma once

#include <petscsys.h>

#include <string>
#include <utility>
#include <vector>

#include "tubeform/io/history.hpp"

namespace tf {

struct ReleaseSummary {
  bool elastic = false; // every point elastic (release 2)
  double reached = 0;   // the largest count of release_yielded over the release's rows
  double excess = 0;    // the largest release_excess (elastic)
  double dep = 0;       // the largest release_dep (the material's law)
  // The plastic work of the release over the elastic energy stored where it began. A springback is driven by
  // that energy: it dissipates a small part of it (a saturating backstress on the default tube: 0.02); above
  // 1 the loads did work on the body: a collapse under the paper's reversed contact forces, which are dead loads.
  double dissipated = 0;
};

// The releases of `rows` in order.
std::vector<ReleaseSummary> SummarizeReleases(const std::vector<HistoryRow> &rows);
// springback_yielded_points, springback_yield_excess, springback_plastic_strain, springback_plastic_work (pass2_
// for the second, pass3_ for the third, ...).
std::vector<std::pair<std::string, double>> ReleaseAttributes(const std::vector<ReleaseSummary> &releases);
// An elastic springback's weight past the yield surface, its largest excess times the share of Gauss points it
// carries past: what the material's law changes in the springback of C/t, C1, C2 is of this order relative to
// that springback (within a factor 10 either way: tests/check_springback_squaring.py). Below this it changes
// them by less than the presets resolve (the default tube: 1e-5, its springback moved by 4e-7 in C/t), and the
// run says so without a warning.
constexpr double kReleaseExcessWarn = 0.01;
// One line per release (`points`: the Gauss points of the model), and the warnings.
PetscErrorCode PrintReleases(MPI_Comm comm, const std::vector<ReleaseSummary> &releases, double points);

} // namespace tf
