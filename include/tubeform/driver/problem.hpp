// A run (docs/theory.md, section 5): the distributed mesh, the body, the global
// system, the contact set and inertia when the scene needs them, and the
// incremental loop that drives them along the scene's load path.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "tubeform/assembly/system.hpp"
#include "tubeform/body/body.hpp"
#include "tubeform/body/inertia.hpp"
#include "tubeform/contact/contact.hpp"
#include "tubeform/driver/answer.hpp"
#include "tubeform/driver/controller.hpp"
#include "tubeform/driver/output_schedule.hpp"
#include "tubeform/driver/refine.hpp"
#include "tubeform/io/history.hpp"
#include "tubeform/io/options.hpp"
#include "tubeform/io/output.hpp"
#include "tubeform/mesh/mesh.hpp"
#include "tubeform/metrics/energy.hpp"
#include "tubeform/scenes/scene.hpp"

namespace tf {

class Problem {
public:
  Problem() = default;
  Problem(const Problem &) = delete;
  Problem &operator=(const Problem &) = delete;
  ~Problem();

  // Collective: the scene of -scene (or one made by the caller, for tests),
  // its mesh partitioned and distributed, the body, the system, inertia (the
  // contact set is made by Run from the scene's tools).
  PetscErrorCode Setup(MPI_Comm comm, const Options &opt);
  PetscErrorCode Setup(MPI_Comm comm, const Options &opt, std::unique_ptr<Scene> scene);
  // Collective: the load path from lambda = 0 to its end; results written.
  PetscErrorCode Run();
  // The error estimate's companion runs of the same case (driver/answer.hpp,
  // Companions), given the options as this run ran them (its element and
  // friction regularization fixed: the companions keep them): called once the
  // run has reached its end (not on a stop) and its results are final
  // (complete, closed and in place). Whatever error it returns means no
  // estimate (one line why); a stop signal also ends the job.
  using CompanionRun = std::function<PetscErrorCode(const Options &ran, Companions &)>;
  void SetCompanion(CompanionRun run) { companion_run_ = std::move(run); }
  // Collective, after Setup and before Run (a problem set up for this alone: its scene's tools are set up here):
  // the options the companions of this run will take (the run's, its element and friction regularization fixed).
  PetscErrorCode CompanionOptions(Options &ran);
  // No lines on the standard output (a companion run, which also writes no files: its -output is empty).
  void SetQuiet() { quiet_ = true; }

  MPI_Comm comm() const { return comm_; }
  Mesh &mesh() { return mesh_; }
  const Body &body() const { return body_; }
  const System &system() const { return system_; }
  const History &history() const { return history_; }
  // After Run: whether a finer level follows this one (accuracy on demand), and its options.
  const Refinement &refinement() const { return refinement_; }

private:
  MPI_Comm comm_ = MPI_COMM_NULL;
  PetscMPIInt rank_ = 0, size_ = 1;
  Options opt_;
  std::unique_ptr<Scene> scene_;
  LoadPath path_;
  Mesh mesh_;
  System system_;
  Body body_;
  std::unique_ptr<Inertia> inertia_;    // -dynamics implicit or auto
  std::unique_ptr<ContactSet> contact_; // scenes with tools
  std::unique_ptr<Model> model_;        // what the scene sees
  History history_;
  CompanionRun companion_run_; // none: no estimate
  Refinement refinement_;
  double started_ = 0; // MPI_Wtime when Run began
  bool quiet_ = false;

  // Where the loop stands on the load path (a checkpoint keeps it).
  struct Cursor {
    double lambda = 0;
    PetscInt inc = 0, step = 0; // increments committed, field steps written
    double lambda_mark = 0;     // the stall watch: lambda and increment at its last mark
    PetscInt inc_mark = 0;
    std::vector<double> started;  // 1 for each stage begun (breakpoints and the end)
    PetscInt iterate_tangent = 0; // 1: the corrections take their iterate's tangent (the Controller's)
  } at_;

  // The state of the loop between increments.
  // Forces at the end of the last increment (local contribution vectors) and at its start (0).
  struct Forces {
    Vec f_app = nullptr, f_app0 = nullptr; // the scene's applied loads
    Vec f_ext = nullptr, f_ext0 = nullptr; // applied loads + friction forces
    Vec f_int = nullptr, f_int0 = nullptr; // internal forces (+ inertia forces)
    Vec f_res = nullptr;                   // out-of-balance force f_ext - f_int
    // With equilibrium iterations: what acts on the body besides its stresses
    // (applied loads, contact forces, inertia force with its sign), the next
    // increment's start.
    Vec f_start = nullptr;
    Vec f_net = nullptr; // f_int - f_app ghost-summed: the contact forces the body needs
  } forces_;
  EnergyAccount energy_;
  // The force scale of the equilibrium criterion: the sum over increments of
  // the mean magnitude of the cells' nodal forces, and their number (Abaqus's
  // time-averaged force q~ = sum / count).
  double q_sum_ = 0, q_count_ = 0;
  double q_now_ = 0; // the mean magnitude of the cells' nodal forces at the last EndForces
  // Compromises so far (history columns of those names).
  PetscInt unsettled_ = 0, events_inside_ = 0, inconsistent_ = 0;
  PetscInt unsettled_run_ =
    0; // increments in a row taken unsettled, in kDeepPerUnsettled-ths (-friction_max_unsettled)
  double worst_error_ = 0, worst_internal_ = 0; // largest |energy_error|, |internal_error| so far
  bool warned_ = false;                         // the energy warning was printed
  bool diverged_ = false;                       // the energy balance error passed -max_energy_error
  std::string nonfinite_;                       // a history column the last increment made NaN or Inf

  PetscErrorCode CreateForces(Vec like);
  // The steps of Run that are not the increment's: outputs checked, tools set
  // up and results opened (step 0), the initial state (increment 0), the
  // answer and results at the end (step 7, src/driver/finish.cpp).
  PetscErrorCode Open(ResultWriter &writer);
  PetscErrorCode Start(ResultWriter &writer);
  // Why and how a run ends before its path does (src/driver/stops.cpp): a
  // one-line reason (empty: it goes on) and the exit code reported once the
  // results so far are written.
  struct Stop {
    std::string why;
    PetscErrorCode code = 0;
    bool stalled = false;      // the stall watch ended it
    int signal = 0;            // the stop signal that ended it
    bool checkpointed = false; // the last checkpoint asked for was written
    bool after_end = false;    // it came after the run's end (its results are complete)
  };
  // Before an increment: the stall watch, the increment budget, the clock and
  // stop signals (with a checkpoint to continue from).
  PetscErrorCode StopBefore(ResultWriter &writer, const OutputSchedule &output, double t_start, Stop &stop);
  // An increment that failed on every rank alike (the controller's code).
  PetscErrorCode StopOnFailure(PetscErrorCode failed, Stop &stop);
  // After a committed one: a number that overflowed, an energy balance that
  // diverged, friction that does not settle (wrote_last: whether the last
  // fields written stand for the last state).
  PetscErrorCode StopAfter(Stop &stop, bool &wrote_last);
  // ... and the tube's wall where the model cannot hold it: past a symmetry plane (ContactSet::Crossing), or
  // crossing itself (metrics/crossing.hpp).
  PetscErrorCode StopOnCrossing(Stop &stop);
  // A checkpoint; one that cannot be written stops the run (stop.why).
  PetscErrorCode Checkpoint(ResultWriter &writer, const OutputSchedule &output, Stop &stop);
  // Step 7 (src/driver/finish.cpp): the answer; the results final (written,
  // closed, renamed into place: PlaceResults), then the estimate added to them
  // (Estimate, src/driver/estimate.cpp); the stop reported last.
  PetscErrorCode Finish(ResultWriter &writer, const Stop &ended);
  // The run's own attributes of /history: where it ended and how, what it was held to, its level; in scenes with
  // contact its friction regularization (the scene's own where -friction_vcri does not give it).
  std::vector<std::pair<std::string, double>> RunMetrics(const Stop &stop, const Answer &answer) const;
  PetscErrorCode PlaceResults(ResultWriter &writer, const std::vector<std::pair<std::string, double>> &metrics,
                              const std::string &stop_reason);
  // The companion runs, their ranks agreeing on how they ended: their histories
  // in `companions` (empty: no estimate, one line why); a stop signal during them
  // goes into `stop`.
  PetscErrorCode Estimate(Companions &companions, Stop &stop);
  // The run's options with what it chose for itself kept (its element, its friction regularization): what its
  // companions and a finer level of accuracy on demand start from, so that they change only what they name.
  Options OwnChoices() const;
  std::string Where() const; // where the run stands, for a stop's message
  // The forces at the end of an increment (or of a restored state) at lambda:
  // applied, external (with friction), internal (with inertia), out-of-balance.
  PetscErrorCode EndForces(double lambda);
  // Checkpoints (src/driver/checkpoint.cpp): the whole state into -checkpoint
  // (the results so far flushed first), and back from -restart.
  PetscErrorCode WriteCheckpoint(ResultWriter &writer, const OutputSchedule &output);
  PetscErrorCode ReadCheckpoint(ResultWriter &writer, OutputSchedule &output);
  // What a checkpoint says of itself and of the results it counts on.
  struct CheckpointHeader {
    double version = 0, ranks = 0, cells = 0, nodes = 0; // layout; the ranks and mesh that wrote it
    double output_bin = 0;                               // the output schedule's last bin
    std::vector<double> times;                           // the times of the field steps written
    std::string options;                                 // PetscOptionsGetAll of the run that wrote it
  };
  // A checkpoint's whole content, written or read in one order: the header
  // (checked when read), the cursor, counters, energies, history, then each part.
  PetscErrorCode Persist(Archive &ar, CheckpointHeader &head);
  PetscErrorCode CheckHeader(const CheckpointHeader &head) const;
  PetscErrorCode DestroyForces();
  // What a committed increment did, for its history row.
  struct Committed {
    Body::CommitInfo body;
    ContactCommit contact;
    double dw_inertia = 0;
  };
  // Step 6 of Run: the increment's forces, energies and the scene's measurements into the history.
  PetscErrorCode Record(PetscInt inc, double lambda0, double lambda, const Increment &step, const Committed &done,
                        Vec du);
  // Its pieces: the forces on the new geometry and the step's own columns (r_min, residuals, counters, the
  // release); the energy accounts and their self-checks; after the row is kept, the worst self-checks so far,
  // the energy warning (once) and the divergence verdict.
  PetscErrorCode StepColumns(PetscInt inc, double lambda, const Increment &step, const Committed &done,
                             HistoryRow &row);
  PetscErrorCode EnergyColumns(double lambda0, double lambda, const Committed &done, Vec du, HistoryRow &row);
  PetscErrorCode WatchEnergy(PetscInt inc, double lambda, const HistoryRow &row);
  // The contact set's columns of a history row from a commit's report (none
  // without tools; report null: the initial state).
  PetscErrorCode ContactColumns(const ContactCommit *report, HistoryRow &row);
  // The scene's applied loads and the friction forces at lambda into f_app and f_ext.
  PetscErrorCode ExternalForces(double lambda);
  PetscErrorCode PrintMonitor(PetscInt inc, double lambda, const Increment &step, const HistoryRow &row);
  PetscErrorCode WriteFields(ResultWriter &writer, PetscInt step, double t);
  // Steps 1-6 of Run: the increments from where the run stands to the path's end or a stop (`stop`).
  PetscErrorCode Increments(ResultWriter &writer, OutputSchedule &output, Stop &stop);
  // Step 2: the stages whose breakpoint lambda has reached begin (`breaks`: the stages' ends; `began`: one did).
  PetscErrorCode BeginStages(const std::vector<double> &breaks, Stop &stop, bool &began);
  // Step 3: the frames of the supports and contact nodes on the current geometry.
  PetscErrorCode BeginIncrement(double lambda);
  // Step 5: the increment committed (stresses, plastic states and geometry; inertia; contact), the compromise
  // counters, lambda moved to its end (on next_break when it ends within kSnapToBreak x dl_stage of it: on_break).
  PetscErrorCode Commit(Vec du, const Increment &taken, double next_break, double dl_stage, Committed &done,
                        bool &on_break);
};

} // namespace tf
