#include "tubeform/driver/release_report.hpp"

#include <algorithm>

#include "tubeform/core/core.hpp"

namespace tf {

std::vector<ReleaseSummary> SummarizeReleases(const std::vector<HistoryRow> &rows)
{
  std::vector<ReleaseSummary> out;
  const HistoryRow *start = nullptr; // the row the release under way began from
  for (size_t k = 0; k < rows.size(); ++k) {
    const HistoryRow &r = rows[k];
    if (r.release == 0) {
      start = nullptr;
      continue;
    }
    if (!start) {
      start = k > 0 ? &rows[k - 1] : &r;
      out.push_back({});
      out.back().elastic = r.release == 2;
    }
    ReleaseSummary &s = out.back();
    s.reached = std::max(s.reached, r.release_yielded);
    s.excess = std::max(s.excess, r.release_excess);
    s.dep = std::max(s.dep, r.release_dep);
    if (start->w_elastic > 0) s.dissipated = (r.w_plastic - start->w_plastic) / start->w_elastic;
  }
  return out;
}

std::vector<std::pair<std::string, double>> ReleaseAttributes(const std::vector<ReleaseSummary> &releases)
{
  std::vector<std::pair<std::string, double>> out;
  for (size_t k = 0; k < releases.size(); ++k) {
    const std::string pass = k ? Formatted("pass%d_", (int)k + 1) : "";
    out.push_back({pass + "springback_yielded_points", releases[k].reached});
    out.push_back({pass + "springback_yield_excess", releases[k].excess});
    out.push_back({pass + "springback_plastic_strain", releases[k].dep});
    out.push_back({pass + "springback_plastic_work", releases[k].dissipated});
  }
  return out;
}

PetscErrorCode PrintReleases(MPI_Comm comm, const std::vector<ReleaseSummary> &releases, double points)
{
  PetscFunctionBeginUser;
  for (size_t k = 0; k < releases.size(); ++k) {
    const ReleaseSummary &s = releases[k];
    const std::string name = k ? "the " + PassOrdinal((int)k) + " pass's springback" : "the springback";
    const char *which = name.c_str();
    const bool weighs = s.excess * s.reached / std::max(points, 1.0) >= kReleaseExcessWarn;
    if (s.elastic && s.reached > 0)
      PetscCall(PetscPrintf(comm,
                            "tubeform: %s%s, elastic, carries %.0f of %.0f Gauss points past the yield surface, by up "
                            "to %.3g %% of the yield stress: the material would yield back there (%s)\n",
                            weighs ? "warning: " : "", which, s.reached, points, 100 * s.excess,
                            weighs ? "-springback material integrates it" : "too few, too little to move the answer"));
    else if (s.elastic)
      PetscCall(
        PetscPrintf(comm, "tubeform: %s, elastic, stays inside the yield surface at every Gauss point\n", which));
    else if (s.reached > 0)
      PetscCall(PetscPrintf(comm,
                            "tubeform: %s by the material's law: %.0f of %.0f Gauss points yield back in it, plastic "
                            "strain up to %.2g\n",
                            which, s.reached, points, s.dep));
    else
      PetscCall(PetscPrintf(comm, "tubeform: %s by the material's law: elastic at every Gauss point\n", which));
    if (s.dissipated > 1)
      PetscCall(PetscPrintf(comm,
                            "tubeform: warning: %s dissipates %.3g times the elastic energy stored where it began: "
                            "the loads drove the tube into a collapse (the reversed contact forces are dead loads); "
                            "release it by the die's motion (-unload withdraw) or elastically (-springback elastic)\n",
                            which, s.dissipated));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

} // namespace tf
