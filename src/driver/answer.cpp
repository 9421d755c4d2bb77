#include "tubeform/driver/answer.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "tubeform/core/core.hpp"

namespace tf {

namespace {

// The last row of the stages up to `stage`.
const HistoryRow &LastUpTo(const std::vector<HistoryRow> &rows, double stage)
{
  const HistoryRow *last = &rows.front();
  for (const auto &r : rows)
    if (r.stage <= stage) last = &r;
  return *last;
}

// The loading stage's rows (stage 0), in order.
std::vector<const HistoryRow *> Loading(const std::vector<HistoryRow> &rows)
{
  std::vector<const HistoryRow *> out;
  for (const auto &r : rows)
    if (r.stage == 0) out.push_back(&r);
  return out;
}

// Column `f` of the loading stage at stroke u (linear between rows).
double At(const std::vector<const HistoryRow *> &rows, double HistoryRow::*f, double u)
{
  if (rows.empty()) return 0;
  if (u <= rows.front()->stroke) return rows.front()->*f;
  for (size_t k = 1; k < rows.size(); ++k)
    if (rows[k]->stroke >= u) {
      const HistoryRow &a = *rows[k - 1], &b = *rows[k];
      const double w = b.stroke > a.stroke ? (u - a.stroke) / (b.stroke - a.stroke) : 1.0;
      return a.*f + w * (b.*f - a.*f);
    }
  return rows.back()->*f;
}

std::string Format(const char *fmt, double v)
{
  char buf[64];
  std::snprintf(buf, sizeof(buf), fmt, v);
  return buf;
}

} // namespace

Answer Summarize(const std::vector<HistoryRow> &rows, bool tool, const std::vector<HistoryRow> *companion)
{
  Answer a;
  a.tool = tool;
  const auto loading = Loading(rows);
  if (loading.empty()) return a;
  // The springback is the first pass's (stage 1); a second pass (stages 2, 3) is reported apart.
  const HistoryRow &end = *loading.back(), &last = tool ? LastUpTo(rows, 1) : rows.back();
  a.springback = &last != &end;
  a.stroke = end.stroke;
  a.load = end.load;
  // The largest load is the quasi-static curve's: a row where a snap is
  // resolved with inertia in a fraction of a microsecond reads the impact of
  // the wall, which is reported apart.
  const HistoryRow *transient = nullptr;
  for (const HistoryRow *r : loading) {
    if (r->w_kinetic > kQuasiStaticKinetic * std::abs(r->w_ext)) {
      if (!transient || r->load > transient->load) transient = r;
    } else {
      a.load_max = std::max(a.load_max, r->load);
    }
  }
  if (transient && transient->load > a.load_max)
    a.transient_max = transient->load, a.transient_stroke = transient->stroke;
  for (double u : kReportedStrokes) // (tool strokes in mm: the tool scenes')
    if (tool && u < a.stroke * (1 - 1e-9)) a.strokes.push_back(u);
  a.strokes.push_back(a.stroke);
  for (double u : a.strokes) {
    a.loads.push_back(At(loading, &HistoryRow::load, u));
    a.c_over_t.push_back(At(loading, &HistoryRow::c_over_t, u));
  }
  a.ct_loaded = end.c_over_t, a.dr_loaded = end.deviation_ratio, a.x_loaded = end.x_max, a.y_loaded = end.y_max;
  a.ct_unloaded = last.c_over_t, a.dr_unloaded = last.deviation_ratio;
  a.x_unloaded = last.x_max, a.y_unloaded = last.y_max;
  if (tool && rows.back().stage >= 2) {
    const HistoryRow &end2 = LastUpTo(rows, 2), &last2 = rows.back();
    a.pass2 = true;
    a.stroke2 = end2.stroke, a.load2 = end2.load, a.ct_loaded2 = end2.c_over_t, a.dr_loaded2 = end2.deviation_ratio;
    a.ct_unloaded2 = last2.c_over_t, a.dr_unloaded2 = last2.deviation_ratio;
  }
  if (!companion) return a;
  const auto coarse = Loading(*companion);
  if (coarse.empty()) return a;
  a.estimated = true;
  for (size_t k = 0; k < a.strokes.size(); ++k) {
    const double u = a.strokes[k], p = a.loads[k];
    const double dp = std::abs(p - At(coarse, &HistoryRow::load, u)) / std::max(std::abs(p), kTiny);
    const double dc = std::abs(a.c_over_t[k] - At(coarse, &HistoryRow::c_over_t, u));
    a.load_error.push_back(kEstimateSafety * dp);
    a.ct_error.push_back(kEstimateSafety * dc);
    a.worst_load_error = std::max(a.worst_load_error, a.load_error.back());
    a.worst_ct_error = std::max(a.worst_ct_error, a.ct_error.back());
  }
  if (a.springback) {
    a.ct_unloaded_error =
      kEstimateSafety * std::abs(a.ct_unloaded - (tool ? LastUpTo(*companion, 1) : companion->back()).c_over_t);
    a.worst_ct_error = std::max(a.worst_ct_error, a.ct_unloaded_error);
  }
  return a;
}

std::vector<std::pair<std::string, double>> AnswerAttributes(const Answer &a)
{
  std::vector<std::pair<std::string, double>> out = {
    {"loaded_stroke", a.stroke}, {"loaded_load", a.load}, {"max_load", a.load_max}};
  if (a.transient_max > 0) {
    out.push_back({"max_load_transient", a.transient_max});
    out.push_back({"max_load_transient_stroke", a.transient_stroke});
  }
  for (size_t k = 0; k + 1 < a.strokes.size(); ++k) {
    const std::string u = Format("%g", a.strokes[k]);
    out.push_back({"load_at_" + u, a.loads[k]});
    out.push_back({"c_over_t_at_" + u, a.c_over_t[k]});
  }
  if (a.tool) {
    out.push_back({"springback_x_max", a.x_unloaded - a.x_loaded});
    out.push_back({"springback_y_max", a.y_unloaded - a.y_loaded});
  }
  if (a.estimated) {
    for (size_t k = 0; k + 1 < a.strokes.size(); ++k) {
      const std::string u = Format("%g", a.strokes[k]);
      out.push_back({"error_load_at_" + u, a.load_error[k]});
      out.push_back({"error_c_over_t_at_" + u, a.ct_error[k]});
    }
    out.push_back({"error_loaded_load", a.load_error.back()});
    out.push_back({"error_loaded_c_over_t", a.ct_error.back()});
    if (a.springback) out.push_back({"error_unloaded_c_over_t", a.ct_unloaded_error});
    out.push_back({"error_load", a.worst_load_error});
    out.push_back({"error_c_over_t", a.worst_ct_error});
  }
  return out;
}

PetscErrorCode PrintAnswer(MPI_Comm comm, const Answer &a, double target_load, double target_ct)
{
  PetscFunctionBeginUser;
  std::string at;
  for (size_t k = 0; k + 1 < a.strokes.size(); ++k) at += Format(k ? ", %.5g" : "%.5g", a.loads[k]);
  std::string where;
  for (size_t k = 0; k + 1 < a.strokes.size(); ++k) where += Format(k ? ", %g" : "%g", a.strokes[k]);
  PetscCall(PetscPrintf(comm, "tubeform: load at the end of loading (%s = %g) %.5g %s, largest %.5g",
                        a.stroke_name.c_str(), a.stroke, a.load, a.load_unit.c_str(), a.load_max));
  if (!at.empty()) PetscCall(PetscPrintf(comm, "; at %s = %s: %s", a.stroke_name.c_str(), where.c_str(), at.c_str()));
  PetscCall(PetscPrintf(comm, "\n"));
  if (a.transient_max > 0)
    PetscCall(PetscPrintf(comm,
                          "tubeform: a dynamic transient reads %.5g N/mm at U = %.4g (a local snap resolved with "
                          "inertia: the wall's impact, not the quasi-static curve; docs/results.md)\n",
                          a.transient_max, a.transient_stroke));
  if (a.tool) {
    PetscCall(PetscPrintf(comm, "tubeform: C/t %.4f, C1/C2 %.4f loaded", a.ct_loaded, a.dr_loaded));
    if (a.springback)
      PetscCall(PetscPrintf(comm,
                            "; after springback C/t %.4f, C1/C2 %.4f (C1 %+.4f mm, C2 %+.4f mm: the springback of "
                            "the half-extents)",
                            a.ct_unloaded, a.dr_unloaded, a.x_unloaded - a.x_loaded, a.y_unloaded - a.y_loaded));
    PetscCall(PetscPrintf(comm, "\n"));
  }
  if (a.pass2)
    PetscCall(PetscPrintf(comm,
                          "tubeform: second pass: load at its end (%s = %g) %.5g %s; C/t %.4f, C1/C2 %.4f loaded; "
                          "after springback C/t %.4f, C1/C2 %.4f\n",
                          a.stroke_name.c_str(), a.stroke2, a.load2, a.load_unit.c_str(), a.ct_loaded2, a.dr_loaded2,
                          a.ct_unloaded2, a.dr_unloaded2));
  if (a.estimated) {
    PetscCall(PetscPrintf(comm,
                          "tubeform: estimated error (an upper bound: %s x the difference from a run at half the "
                          "resolution): load %.2g %%",
                          Format("%g", kEstimateSafety).c_str(), 100 * a.worst_load_error));
    if (a.tool) PetscCall(PetscPrintf(comm, ", C/t %.2g", a.worst_ct_error));
    if (target_load > 0) PetscCall(PetscPrintf(comm, " (targets %.3g %%, %.3g)", 100 * target_load, target_ct));
    PetscCall(PetscPrintf(comm, "\n"));
    const bool over = (target_load > 0 && a.worst_load_error > target_load) ||
                      (a.tool && target_ct > 0 && a.worst_ct_error > target_ct);
    if (over)
      PetscCall(PetscPrintf(comm, "tubeform: warning: the estimated error passes the accuracy target, which this "
                                  "run therefore cannot confirm: refine (-mesh_density, -mesh_nt, -increments) or "
                                  "take a more accurate preset (docs/accuracy.md)\n"));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

} // namespace tf
