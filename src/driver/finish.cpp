// Step 7 of a run: its answer (driver/answer.hpp) with the error estimate
// from the companion run, the self-checks, the result file renamed into
// place, and the stop that ended the run early, reported last.
#include <string>
#include <vector>

#include "tubeform/core/log.hpp"
#include "tubeform/core/signals.hpp"
#include "tubeform/driver/answer.hpp"
#include "tubeform/driver/problem.hpp"
#include "tubeform/driver/release_report.hpp"

namespace tf {

PetscErrorCode Problem::Finish(ResultWriter &writer, const Stop &ended)
{
  Stop stop = ended;
  std::vector<HistoryRow> companion; // its history (none: no estimate)
  PetscFunctionBeginUser;
  if (companion_run_ && stop.why.empty()) {
    // A stop signal during the companion: this run's results are complete and
    // written as such, without an estimate; the job still ends as asked.
    const PetscErrorCode c = companion_run_(companion);
    if (c == PETSC_ERR_SIG) {
      int mine = StopSignal(), any;
      PetscCallMPI(MPI_Allreduce(&mine, &any, 1, MPI_INT, MPI_MAX, comm_));
      companion.clear();
      stop.signal = any, stop.code = PETSC_ERR_SIG;
      stop.why = std::string("interrupted by ") + SignalName(any) +
                 " during the companion run of the error estimate (the run itself had reached its end: complete, "
                 "without an estimate)";
    } else {
      PetscCall(c);
    }
  }
  PetscCall(PetscLogStagePush(Log::output_stage));
  const HistoryRow &last = history_.rows().back();
  // Shape metrics (C/t, C1/C2, springback) are the press scenes': those with final metrics of their own.
  const auto scene_metrics = scene_->FinalMetrics(history_);
  Answer answer = Summarize(history_.rows(), !scene_metrics.empty(), companion.empty() ? nullptr : &companion);
  answer.stroke_name = scene_->StrokeName(), answer.load_unit = scene_->LoadUnit();
  for (const auto &[name, value] : scene_metrics) // (the second pass's start: the scene's, before its first row)
    if (name == "pass2_start_stroke" && answer.passes.size() > 1) answer.passes[1].start = value;
  answer.mesh_covered = opt_.mesh_file.empty();
  answer.release = opt_.unload == "withdraw" ? "the dies withdrawn" : "the contact forces reversed, the dies removed";
  std::vector<std::pair<std::string, double>> metrics = {{"final_stroke", last.stroke},
                                                         {"final_load", last.load},
                                                         {"x_max", last.x_max},
                                                         {"y_max", last.y_max},
                                                         {"stalled", stop.stalled ? 1.0 : 0.0},
                                                         {"stopped", stop.why.empty() ? 0.0 : 1.0},
                                                         {"interrupted", double(stop.signal)},
                                                         {"target_load", opt_.target_load},
                                                         {"target_c_over_t", opt_.target_c_over_t}};
  for (const auto &m : scene_metrics) metrics.push_back(m);
  for (const auto &m : AnswerAttributes(answer)) metrics.push_back(m);
  const auto releases = SummarizeReleases(history_.rows());
  for (const auto &m : ReleaseAttributes(releases)) metrics.push_back(m);
  double points = fe::kGauss * mesh_.num_cells, all_points;
  PetscCallMPI(MPI_Allreduce(&points, &all_points, 1, MPI_DOUBLE, MPI_SUM, comm_));
  PetscCall(writer.Close(history_, metrics));
  int ok = history_.FinishCsv(); // rank 0 holds the file; every rank learns the outcome
  PetscCallMPI(MPI_Bcast(&ok, 1, MPI_INT, 0, comm_));
  PetscCheck(ok, comm_, PETSC_ERR_FILE_WRITE, "-history_csv %s: cannot rename the finished file into place",
             opt_.history_csv.c_str());
  PetscCall(PetscLogStagePop());
  if (stop.why.empty() && !quiet_) {
    PetscCall(PetscPrintf(comm_, "tubeform: %s done, %d increments, %d factorizations; results in %s\n",
                          opt_.scene.c_str(), (int)at_.inc, (int)system_.factorizations(), opt_.output.c_str()));
    PetscCall(PrintAnswer(comm_, answer, opt_.target_load, opt_.target_c_over_t));
    PetscCall(PrintReleases(comm_, releases, all_points));
    PetscCall(PetscPrintf(comm_,
                          "tubeform: self-checks: energy balance within %.2g %%, internal work within %.2g %%; "
                          "compromises: %d steps past an event, %d unsettled, %d with inconsistent loading states\n",
                          100 * worst_error_, 100 * worst_internal_, (int)events_inside_, (int)unsettled_,
                          (int)inconsistent_));
  }
  // An early stop is a failure of the run, reported after its results are written.
  PetscCheck(stop.why.empty(), comm_, stop.code, "%s; results up to there are in %s", stop.why.c_str(),
             opt_.output.c_str());
  PetscFunctionReturn(PETSC_SUCCESS);
}

} // namespace tf
