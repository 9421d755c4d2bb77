#include "tubeform/driver/release_report.hpp"

#include <algorithm>

namespace tf {

std::vector<ReleaseSummary> SummarizeReleases(const std::vector<HistoryRow> &rows)
{
  std::vector<ReleaseSummary> out;
  bool in = false;
  for (const HistoryRow &r : rows) {
    if (r.release != 0 && !in) out.push_back({});
    in = r.release != 0;
    if (!in) continue;
    ReleaseSummary &s = out.back();
    s.reached = std::max(s.reached, r.release_yielded);
    s.excess = std::max(s.excess, r.release_excess);
    s.dep = std::max(s.dep, r.release_dep);
  }
  return out;
}

std::vector<std::pair<std::string, double>> ReleaseAttributes(const std::vector<ReleaseSummary> &releases)
{
  std::vector<std::pair<std::string, double>> out;
  for (size_t k = 0; k < releases.size() && k < 2; ++k) {
    const std::string pass = k ? "pass2_" : "";
    out.push_back({pass + "springback_yielded_points", releases[k].reached});
    out.push_back({pass + "springback_yield_excess", releases[k].excess});
    out.push_back({pass + "springback_plastic_strain", releases[k].dep});
  }
  return out;
}

PetscErrorCode PrintReleases(MPI_Comm comm, const std::vector<ReleaseSummary> &releases, bool elastic, double points)
{
  PetscFunctionBeginUser;
  for (size_t k = 0; k < releases.size(); ++k) {
    const ReleaseSummary &s = releases[k];
    const char *which = k ? "the second pass's springback" : "the springback";
    if (!elastic && s.reached > 0)
      PetscCall(PetscPrintf(comm,
                            "tubeform: %s with the material's law: %.0f of %.0f Gauss points yield back in it, "
                            "plastic strain up to %.2g\n",
                            which, s.reached, points, s.dep));
    else if (!elastic)
      PetscCall(PetscPrintf(comm, "tubeform: %s with the material's law: elastic at every Gauss point\n", which));
    else if (s.reached > 0)
      PetscCall(PetscPrintf(comm,
                            "tubeform: warning: %s, taken elastic (-springback elastic), carries %.0f of %.0f Gauss "
                            "points past the yield surface, by up to %.3g %% of the yield stress: the material would "
                            "yield back there (-springback material springs back by its law)\n",
                            which, s.reached, points, 100 * s.excess));
    else
      PetscCall(
        PetscPrintf(comm,
                    "tubeform: %s, taken elastic (-springback elastic), stays inside the yield surface at every "
                    "Gauss point (as the material's law would)\n",
                    which));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

} // namespace tf
