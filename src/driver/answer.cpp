#include "tubeform/driver/answer.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

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

// The rows of one stage, in order.
std::vector<const HistoryRow *> Stage(const std::vector<HistoryRow> &rows, double stage)
{
  std::vector<const HistoryRow *> out;
  for (const auto &r : rows)
    if (r.stage == stage) out.push_back(&r);
  return out;
}

// Column `f` of a stage's rows at stroke u (linear between rows).
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

ShapeAt ShapeOf(const HistoryRow &r) { return {r.c_over_t, r.x_max, r.y_max}; }

// Pass p of a press (stages 2p and 2p + 1), or the whole run of a scene without tools (its stage 0 and its end).
PassAnswer SummarizePass(const std::vector<HistoryRow> &rows, bool tool, int p)
{
  PassAnswer a;
  const auto loading = Stage(rows, 2 * p);
  if (loading.empty()) return a;
  const HistoryRow &end = *loading.back(), &last = tool ? LastUpTo(rows, 2 * p + 1) : rows.back();
  a.springback = &last != &end;
  a.start = p == 0 ? rows.front().stroke : loading.front()->stroke;
  a.stroke = end.stroke, a.load = end.load;
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
    if (tool && u > a.start && u < a.stroke * (1 - 1e-9)) a.strokes.push_back(u);
  a.strokes.push_back(a.stroke);
  for (double u : a.strokes) {
    a.loads.push_back(At(loading, &HistoryRow::load, u));
    a.c_over_t.push_back(At(loading, &HistoryRow::c_over_t, u));
  }
  a.loaded = ShapeOf(end), a.unloaded = ShapeOf(last);
  return a;
}

// Strokes this close (mm) are one: the companions end where the run ends, up to round-off.
constexpr double kStrokeMatch = 1e-9;

// The companions' values of one quantity at one stroke: the mesh companion's, the steps companion's and the one
// that companion's difference is taken against.
struct CompanionValues {
  double mesh = 0, steps = 0, base = 0;
};

// The estimate of a value from the run's and the companions' (kStepShare, Companions), its parts apart; relative
// to `scale`.
ErrorParts Estimate(double run, const CompanionValues &v, double mesh_ratio, double scale = 1)
{
  return {kMeshShare * std::abs(v.mesh - run) / (mesh_ratio - 1) / scale,
          kStepShare * std::abs(v.steps - v.base) / scale};
}

// The stage's rows of each companion (the mesh's: the run's own with a mesh file).
struct StageRows {
  std::vector<const HistoryRow *> mesh, steps, base;
  StageRows(const std::vector<HistoryRow> &rows, const Companions &c, double stage)
  {
    mesh = Stage(c.MeshRows(rows), stage), steps = Stage(c.steps, stage), base = Stage(c.BaseRows(rows), stage);
  }
  bool Empty() const { return mesh.empty() || steps.empty() || base.empty(); }
  // The stroke to which every companion reached.
  double Reach() const { return std::min({mesh.back()->stroke, steps.back()->stroke, base.back()->stroke}); }
  CompanionValues At(double HistoryRow::*f, double u) const
  {
    return {tf::At(mesh, f, u), tf::At(steps, f, u), tf::At(base, f, u)};
  }
};

// The larger of two estimates.
ErrorParts Larger(const ErrorParts &a, const ErrorParts &b) { return b.Total() > a.Total() ? b : a; }

// A loading row's estimate from the companions at its stroke: its load's (relative) and its C/t's.
std::pair<ErrorParts, ErrorParts> RowEstimate(const HistoryRow &r, const StageRows &at, double mesh_ratio)
{
  return {Estimate(r.load, at.At(&HistoryRow::load, r.stroke), mesh_ratio, std::max(std::abs(r.load), kTiny)),
          Estimate(r.c_over_t, at.At(&HistoryRow::c_over_t, r.stroke), mesh_ratio)};
}

// The estimate of the load and C/t at the end of a stage's loading: the largest over the rows of its last trial
// increment (`window` of stroke before `end`), not at the end's stroke alone. Where the wall locks against the die
// the load climbs by a quarter in a tenth of a millimetre, and the companions' curves can cross the run's at the last
// row: a difference near zero there is where the curves meet, not how close they are (docs/accuracy.md, "The error
// estimate").
void EstimateEnd(const std::vector<const HistoryRow *> &loading, const StageRows &at, double mesh_ratio, double window,
                 ErrorParts &load, ErrorParts &ct)
{
  const double end = loading.back()->stroke;
  for (const HistoryRow *r : loading) {
    if (r->stroke < end - window) continue;
    const auto [row_load, row_ct] = RowEstimate(*r, at, mesh_ratio);
    load = Larger(load, row_load), ct = Larger(ct, row_ct);
  }
}

// The pass's estimate from the companions' same pass (none when a companion did not reach it); `trial` the run's
// trial increment as a fraction of the pass's loading.
void EstimatePass(PassAnswer &a, const std::vector<HistoryRow> &rows, const Companions &c, bool tool, int p,
                  double trial)
{
  const StageRows at(rows, c, 2 * p);
  if (at.Empty() || a.strokes.empty()) return;
  a.estimated = true;
  for (size_t k = 0; k < a.strokes.size(); ++k) {
    const double u = a.strokes[k], load = a.loads[k];
    a.load_parts.push_back(Estimate(load, at.At(&HistoryRow::load, u), c.mesh_ratio, std::max(std::abs(load), kTiny)));
    a.ct_parts.push_back(Estimate(a.c_over_t[k], at.At(&HistoryRow::c_over_t, u), c.mesh_ratio));
  }
  EstimateEnd(Stage(rows, 2 * p), at, c.mesh_ratio, trial * (a.stroke - a.start), a.load_parts.back(),
              a.ct_parts.back());
  for (size_t k = 0; k < a.strokes.size(); ++k) {
    a.load_error.push_back(a.load_parts[k].Total());
    a.ct_error.push_back(a.ct_parts[k].Total());
  }
  const auto end = [&](const std::vector<HistoryRow> &h) {
    return (tool ? LastUpTo(h, 2 * p + 1) : h.back()).c_over_t;
  };
  if (a.springback) {
    const CompanionValues v{end(c.MeshRows(rows)), end(c.steps), end(c.BaseRows(rows))};
    a.ct_unloaded_parts = Estimate(a.unloaded.c_over_t, v, c.mesh_ratio);
    a.ct_unloaded_error = a.ct_unloaded_parts.Total();
  }
}

} // namespace

Answer Summarize(const std::vector<HistoryRow> &rows, bool tool, const Companions *companions, double trial)
{
  Answer a;
  a.tool = tool;
  if (companions) a.estimate_level = companions->level, a.estimate_ratio = companions->mesh_ratio;
  if (rows.empty()) return a;
  int passes = 1; // (a tool scene's pass k presses in stage 2k: the passes the history reached)
  for (const HistoryRow &r : rows) passes = tool ? std::max(passes, (int)(r.stage / 2) + 1) : 1;
  for (int p = 0; p < passes; ++p) {
    a.passes.push_back(SummarizePass(rows, tool, p));
    PassAnswer &pass = a.passes.back();
    if (companions && companions->Ran()) EstimatePass(pass, rows, *companions, tool, p, trial);
    if (!pass.estimated) continue;
    a.estimated = true;
    for (size_t k = 0; k < pass.strokes.size(); ++k) {
      if (pass.load_error[k] > a.worst_load_error)
        a.worst_load_error = pass.load_error[k], a.worst_load = pass.load_parts[k];
      if (pass.ct_error[k] > a.worst_ct_error) a.worst_ct_error = pass.ct_error[k], a.worst_ct = pass.ct_parts[k];
    }
    if (pass.ct_unloaded_error > a.worst_ct_error)
      a.worst_ct_error = pass.ct_unloaded_error, a.worst_ct = pass.ct_unloaded_parts;
  }
  return a;
}

std::vector<std::pair<std::string, double>> AnswerAttributes(const Answer &a)
{
  std::vector<std::pair<std::string, double>> out;
  for (size_t p = 0; p < a.passes.size(); ++p) {
    const PassAnswer &s = a.passes[p];
    const std::string pre = p == 0 ? "" : Formatted("pass%d_", (int)p + 1);
    out.push_back({pre + "loaded_stroke", s.stroke});
    out.push_back({pre + "loaded_load", s.load});
    out.push_back({pre + "max_load", s.load_max});
    if (s.transient_max > 0) {
      out.push_back({pre + "max_load_transient", s.transient_max});
      out.push_back({pre + "max_load_transient_stroke", s.transient_stroke});
    }
    for (size_t k = 0; k + 1 < s.strokes.size(); ++k) {
      const std::string u = Formatted("%g", s.strokes[k]);
      out.push_back({pre + "load_at_" + u, s.loads[k]});
      out.push_back({pre + "c_over_t_at_" + u, s.c_over_t[k]});
    }
    if (a.tool) {
      out.push_back({pre + "springback_x_max", s.unloaded.c1 - s.loaded.c1});
      out.push_back({pre + "springback_y_max", s.unloaded.c2 - s.loaded.c2});
    }
    if (!s.estimated) continue;
    for (size_t k = 0; k + 1 < s.strokes.size(); ++k) {
      const std::string u = Formatted("%g", s.strokes[k]);
      out.push_back({pre + "error_load_at_" + u, s.load_error[k]});
      out.push_back({pre + "error_c_over_t_at_" + u, s.ct_error[k]});
    }
    out.push_back({pre + "error_loaded_load", s.load_error.back()});
    out.push_back({pre + "error_loaded_c_over_t", s.ct_error.back()});
    if (s.springback) out.push_back({pre + "error_unloaded_c_over_t", s.ct_unloaded_error});
  }
  if (a.estimated && a.mesh_covered && (a.target_load > 0 || a.target_ct > 0))
    out.push_back({"target_met", a.Over() ? 0.0 : 1.0});
  if (a.estimated) {
    out.push_back({"error_load", a.worst_load_error});
    out.push_back({"error_c_over_t", a.worst_ct_error});
    out.push_back({"error_covers_mesh", a.mesh_covered ? 1.0 : 0.0});
    out.push_back({"error_covers_wall", a.mesh_covered && a.wall_covered ? 1.0 : 0.0});
  }
  return out;
}

std::vector<std::pair<std::string, std::vector<double>>> ErrorColumns(const std::vector<HistoryRow> &rows,
                                                                      const Companions &c, const Answer &a)
{
  std::vector<double> load(rows.size(), kNoEstimate), ct(rows.size(), kNoEstimate);
  double stage = -1; // the companions' rows of the stage of the rows at hand
  StageRows at(rows, c, stage);
  for (size_t k = 0; k < rows.size(); ++k) {
    const HistoryRow &r = rows[k];
    const size_t p = (size_t)(r.stage / 2);
    if (std::fmod(r.stage, 2.0) != 0) { // a release: the estimate of the loaded state it releases
      if (p < a.passes.size() && a.passes[p].estimated) {
        const PassAnswer &s = a.passes[p];
        load[k] = s.load_error.back(), ct[k] = std::max(s.ct_error.back(), s.ct_unloaded_error);
      }
      continue;
    }
    if (r.stage != stage) stage = r.stage, at = StageRows(rows, c, stage);
    if (at.Empty() || r.stroke > at.Reach() + kStrokeMatch) continue; // (past where a companion reached)
    const auto [row_load, row_ct] = RowEstimate(r, at, c.mesh_ratio);
    load[k] = row_load.Total(), ct[k] = row_ct.Total();
  }
  return {{"error_load", load}, {"error_c_over_t", ct}};
}

} // namespace tf
