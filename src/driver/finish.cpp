// Step 7 of a run: its answer, its results made final (written, closed and
// renamed into place) before anything else, then the error estimate from the
// companion run added to them, the self-checks, and the stop that ended the
// run early, reported last.
#include <algorithm>
#include <cstring>
#include <string>
#include <vector>

#include "tubeform/core/log.hpp"
#include "tubeform/driver/answer.hpp"
#include "tubeform/driver/problem.hpp"
#include "tubeform/driver/refine.hpp"
#include "tubeform/driver/release_report.hpp"

namespace tf {

namespace {

// The accuracy an answer is held to: what was demanded (only that: the levels refine for it alone,
// driver/refine.cpp), else what the preset expects.
void HoldTo(const AccuracyParams &held, Answer &a)
{
  a.demanded = held.target_load > 0 || held.target_c_over_t > 0;
  a.target_load = a.demanded ? held.target_load : held.expect_load;
  a.target_ct = a.demanded ? held.target_c_over_t : held.expect_c_over_t;
}

// Each later pass's start into the answer: the scene's pass<K>_start_stroke (before the pass's first row).
void TakePassStarts(const std::vector<std::pair<std::string, double>> &scene_metrics, Answer &a)
{
  for (const auto &[name, value] : scene_metrics)
    for (size_t p = 1; p < a.passes.size(); ++p)
      if (name == Formatted("pass%d_start_stroke", (int)p + 1)) a.passes[p].start = value;
}

// The next level's mesh companion (Refinement::reuse): this level's run, at `ratio` times its cell size (its
// increments' part follows from a run at this level's cells, main.cpp).
Companions ForNextLevel(const std::vector<HistoryRow> &rows, double ratio, int level)
{
  Companions next;
  next.mesh = rows, next.mesh_ratio = ratio, next.level = level;
  return next;
}

} // namespace

std::vector<std::pair<std::string, double>> Problem::RunMetrics(const Stop &stop, const Answer &answer) const
{
  const HistoryRow &last = history_.rows().back();
  std::vector<std::pair<std::string, double>> metrics = {{"final_stroke", last.stroke},
                                                         {"final_load", last.load},
                                                         {"x_max", last.x_max},
                                                         {"y_max", last.y_max},
                                                         {"stalled", stop.stalled ? 1.0 : 0.0},
                                                         {"stopped", stop.why.empty() ? 0.0 : 1.0},
                                                         {"interrupted", double(stop.signal)},
                                                         {"target_load", answer.target_load},
                                                         {"target_c_over_t", answer.target_ct},
                                                         {"accuracy_level", double(opt_.level)}};
  if (contact_) metrics.push_back({"friction_vcri", contact_->params().vcri});
  return metrics;
}

PetscErrorCode Problem::PlaceResults(ResultWriter &writer, const std::vector<std::pair<std::string, double>> &metrics,
                                     const std::string &stop_reason)
{
  PetscFunctionBeginUser;
  if (opt_.output.empty()) PetscFunctionReturn(PETSC_SUCCESS); // (a companion run: no files)
  // Everything is written and checked first (the CSV: rank 0 holds it, every
  // rank learns how it went; the HDF5 file and its index); only then is
  // anything renamed, so a failed write leaves the earlier results whole.
  int csv = history_.CloseCsv();
  if (csv) history_.DropCsv();
  PetscCallMPI(MPI_Bcast(&csv, 1, MPI_INT, 0, comm_));
  PetscCheck(!csv, comm_, PETSC_ERR_FILE_WRITE,
             "-history_csv %s: writing %s.partial failed (%s); it is removed, nothing is renamed into place (the "
             "results stay in %s.partial)",
             opt_.history_csv.c_str(), opt_.history_csv.c_str(), std::strerror(csv), opt_.output.c_str());
  PetscCall(writer.Close(history_, metrics, stop_reason));
  PetscCall(writer.Place(opt_.history_csv));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Problem::Finish(ResultWriter &writer, const Stop &ended)
{
  Stop stop = ended;
  Companions companions; // their histories (none: no estimate)
  PetscFunctionBeginUser;
  PetscCall(PetscLogStagePush(Log::output_stage));
  // Shape metrics (C/t, C1/C2, springback) are the press scenes': those with final metrics of their own.
  const auto scene_metrics = scene_->FinalMetrics(history_);
  const auto summarize = [&](const Companions *estimate) {
    Answer a = Summarize(history_.rows(), !scene_metrics.empty(), estimate, 1.0 / opt_.driver.increments);
    a.stroke_name = scene_->StrokeName(), a.load_unit = scene_->LoadUnit();
    TakePassStarts(scene_metrics, a);
    a.mesh_covered = opt_.mesh_file.empty();
    a.wall_covered = a.estimate_level > 0 || CompanionNt(opt_.mesh_nt) != opt_.mesh_nt;
    HoldTo(opt_.accuracy, a);
    for (size_t p = 0; p < a.passes.size(); ++p) a.passes[p].release = scene_->ReleaseOf((int)p);
    return a;
  };
  Answer answer = summarize(nullptr);
  auto metrics = RunMetrics(stop, answer);
  for (const auto &m : scene_metrics) metrics.push_back(m);
  for (const auto &m : AnswerAttributes(answer)) metrics.push_back(m);
  const auto releases = SummarizeReleases(history_.rows());
  for (const auto &m : ReleaseAttributes(releases)) metrics.push_back(m);
  double points = fe::kGauss * mesh_.num_cells, all_points;
  PetscCallMPI(MPI_Allreduce(&points, &all_points, 1, MPI_DOUBLE, MPI_SUM, comm_));
  // 1. The results final: nothing the estimate does can touch them.
  PetscCall(PlaceResults(writer, metrics, stop.why));
  PetscCall(PetscLogStagePop());
  // 2. The estimate, added to them: the attributes the answer with it adds or changes.
  if (companion_run_ && stop.why.empty()) {
    PetscCall(Estimate(companions, stop));
    if (companions.Ran()) {
      answer = summarize(&companions);
      std::vector<std::pair<std::string, double>> extra;
      for (const auto &a : AnswerAttributes(answer)) {
        auto was = std::find_if(metrics.begin(), metrics.end(), [&](const auto &m) { return m.first == a.first; });
        if (was == metrics.end() || was->second != a.second) extra.push_back(a);
      }
      std::string why;
      if (!opt_.output.empty())
        PetscCall(AddResultEstimate(comm_, opt_.output, extra, ErrorColumns(history_.rows(), companions, answer), why));
      if (!why.empty())
        PetscCall(PetscPrintf(comm_,
                              "tubeform: the error estimate is not in %s (%s): it holds the results without it\n",
                              opt_.output.c_str(), why.c_str()));
    }
  }
  if (stop.why.empty() && !quiet_) {
    PetscCall(PetscPrintf(comm_, "tubeform: %s done, %d increments, %d factorizations; results in %s\n",
                          opt_.scene.c_str(), (int)at_.inc, (int)system_.factorizations(), opt_.output.c_str()));
    double seconds[2] = {MPI_Wtime() - started_, MPI_Wtime() - opt_.job_started}; // (rank 0's: one decision)
    PetscCallMPI(MPI_Bcast(seconds, 2, MPI_DOUBLE, 0, comm_));
    refinement_ = NextLevel(OwnChoices(), answer, seconds[0], seconds[1]);
    if (refinement_.follows && refinement_.reuse)
      refinement_.companions = ForNextLevel(history_.rows(), CellRatio(opt_, refinement_.next), (int)opt_.level);
    PetscCall(PrintAnswer(comm_, answer, refinement_.follows, refinement_.why));
    PetscCall(PrintReleases(comm_, releases, all_points));
    PetscCall(PetscPrintf(comm_,
                          "tubeform: self-checks: energy balance within %.2g %%, internal work within %.2g %%; "
                          "compromises: %d steps past an event, %d unsettled, %d with inconsistent loading states\n",
                          100 * worst_error_, 100 * worst_internal_, (int)events_inside_, (int)unsettled_,
                          (int)inconsistent_));
  }
  // An early stop is a failure of the run, reported after its results are written.
  const std::string where = stop.after_end || opt_.output.empty() ? "" : "; results up to there are in " + opt_.output;
  PetscCheck(stop.why.empty(), comm_, stop.code, "%s%s", stop.why.c_str(), where.c_str());
  PetscFunctionReturn(PETSC_SUCCESS);
}

} // namespace tf
