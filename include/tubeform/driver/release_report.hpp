// What each springback of a run did at the yield surface, from its history's release columns (the rows with
// `release` 1, one run of them per release: a tool scene's first and second pass): the Gauss points that
// reached the surface, how far the elastic springback carried a point past it, the largest plastic strain the
// material's law took in it. Written as attributes and said in the run's last lines; an elastic springback that
// passes the surface is warned about (docs/theory.md, "Unloading").
#pragma once

#include <petscsys.h>

#include <string>
#include <utility>
#include <vector>

#include "tubeform/io/history.hpp"

namespace tf {

struct ReleaseSummary {
  double reached = 0; // the largest count of release_yielded over the release's rows
  double excess = 0;  // the largest release_excess (-springback elastic)
  double dep = 0;     // the largest release_dep (-springback material)
};

// The releases of `rows` in order.
std::vector<ReleaseSummary> SummarizeReleases(const std::vector<HistoryRow> &rows);
// springback_yielded_points, springback_yield_excess, springback_plastic_strain (pass2_ for the second).
std::vector<std::pair<std::string, double>> ReleaseAttributes(const std::vector<ReleaseSummary> &releases);
// One line per release; `elastic`: -springback elastic; `points`: the Gauss points of the model.
PetscErrorCode PrintReleases(MPI_Comm comm, const std::vector<ReleaseSummary> &releases, bool elastic, double points);

} // namespace tf
