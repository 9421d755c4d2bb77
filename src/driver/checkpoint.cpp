// Checkpoints of a run (docs/reliability.md, "Checkpoint and restart"): after
// an increment the whole state is written to -checkpoint (atomically: a
// scratch file renamed into place) and read back by -restart, which goes on
// with the next increment as the run would have. Everything an increment
// reads from the increments before is in it: the body's point states and
// coordinates, inertia's motion, the contact set, the scene's stage loads,
// the history and the energy accounts, the position on the load path; the
// forces at the end of the last increment are recomputed from that state by
// the same calls that computed them, so they come back bit for bit.
#include <cmath>
#include <filesystem>
#include <string>

#include "tubeform/driver/problem.hpp"

namespace tf {

namespace {
// The layout of a checkpoint; a file of another version is refused.
constexpr double kCheckpointVersion = 1;
// Room a checkpoint is given before it is written: 8-byte numbers, fewer than
// 64 per node, per cell and per history row (the state holds about 30, 40 and
// 46), and 1 MB for HDF5's own.
constexpr double kBytesPerItem = 8 * 64, kBytesOverhead = 1e6;
} // namespace

PetscErrorCode Problem::Persist(Archive &ar, CheckpointHeader &head)
{
  PetscFunctionBeginUser;
  ar.Group("/run");
  for (auto [name, v] : {std::pair{"version", &head.version},
                         {"ranks", &head.ranks},
                         {"cells", &head.cells},
                         {"nodes", &head.nodes},
                         {"output_bin", &head.output_bin}})
    PetscCall(ar.Value(name, *v));
  PetscCall(ar.Values("times", head.times));
  if (ar.reading()) PetscCall(CheckHeader(head));
  PetscCall(ar.Value("lambda", at_.lambda));
  PetscCall(ar.Value("increments", at_.inc));
  PetscCall(ar.Value("lambda_mark", at_.lambda_mark));
  PetscCall(ar.Value("increment_mark", at_.inc_mark));
  const size_t stages = at_.started.size();
  PetscCall(ar.Values("started", at_.started));
  PetscCheck(at_.started.size() == stages, comm_, PETSC_ERR_USER_INPUT,
             "-restart %s: the checkpoint's load path has %d stages, this run's %d (restart with the options of "
             "the run that wrote it)",
             opt_.restart.c_str(), (int)at_.started.size(), (int)stages);
  PetscCall(ar.Value("unsettled", unsettled_));
  PetscCall(ar.Value("unsettled_run", unsettled_run_));
  PetscCall(ar.Value("events_inside", events_inside_));
  PetscCall(ar.Value("inconsistent", inconsistent_));
  PetscCall(ar.Value("worst_error", worst_error_));
  PetscCall(ar.Value("worst_internal", worst_internal_));
  PetscCall(ar.Value("warned", warned_));
  ar.Group("/energy");
  for (auto [name, w] : {std::pair{"w_ext", &energy_.w_ext},
                         {"w_tool", &energy_.w_tool},
                         {"w_int", &energy_.w_int},
                         {"w_plastic", &energy_.w_plastic},
                         {"w_friction", &energy_.w_friction},
                         {"w_inertia", &energy_.w_inertia}})
    PetscCall(ar.Value(name, *w));
  PetscCall(history_.Persist(ar, comm_));
  // The parts' state.
  PetscCall(system_.Persist(ar));
  PetscCall(body_.Persist(ar));
  if (inertia_) PetscCall(inertia_->Persist(ar));
  if (contact_) PetscCall(contact_->Persist(ar));
  PetscCall(scene_->Persist(*model_, ar));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Problem::WriteCheckpoint(ResultWriter &writer, const OutputSchedule &output)
{
  Archive ar;
  CheckpointHeader head{
    kCheckpointVersion, (double)size_, (double)mesh_.num_global_cells, (double)mesh_.num_global_nodes,
    output.written(),   writer.times()};

  PetscFunctionBeginUser;
  PetscCall(writer.Flush()); // the field steps the checkpoint counts on are on disk
  const double items = mesh_.num_global_nodes + mesh_.num_global_cells + (double)history_.rows().size();
  PetscCall(ar.Open(mesh_, opt_.checkpoint, true, "-checkpoint", kBytesPerItem * items + kBytesOverhead));
  PetscCall(Persist(ar, head));
  PetscCall(ar.Close());
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Problem::ReadCheckpoint(ResultWriter &writer, OutputSchedule &output)
{
  Archive ar;
  CheckpointHeader head;

  PetscFunctionBeginUser;
  PetscCall(ar.Open(mesh_, opt_.restart, false, "-restart"));
  PetscCall(Persist(ar, head));
  PetscCall(ar.Close());
  output.Continue(head.output_bin);
  if (head.ranks == size_) {
    PetscCall(writer.Reopen(mesh_, opt_.output, head.times));
  } else {
    // Another number of ranks numbers the nodes of the field series otherwise:
    // the fields start anew (the history is whole), in a file of their own.
    PetscCall(writer.Open(mesh_, opt_.output));
  }
  at_.step = (PetscInt)writer.times().size();
  if (head.ranks != size_) PetscCall(WriteFields(writer, at_.step++, at_.lambda));
  PetscCall(EndForces(at_.lambda));
  PetscCall(PetscPrintf(comm_, "tubeform: restarting from %s after increment %d (lambda %.6g, stroke %g)\n",
                        opt_.restart.c_str(), (int)at_.inc, at_.lambda, history_.rows().back().stroke));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Problem::CheckHeader(const CheckpointHeader &head) const
{
  PetscFunctionBeginUser;
  PetscCheck(head.version == kCheckpointVersion, comm_, PETSC_ERR_USER_INPUT,
             "-restart %s: a checkpoint of layout version %d, this tubeform reads version %d", opt_.restart.c_str(),
             (int)head.version, (int)kCheckpointVersion);
  PetscCheck(head.cells == mesh_.num_global_cells && head.nodes == mesh_.num_global_nodes, comm_, PETSC_ERR_USER_INPUT,
             "-restart %s: the checkpoint's mesh has %d cells and %d nodes, this run's %d and %d (restart with the "
             "options of the run that wrote it)",
             opt_.restart.c_str(), (int)head.cells, (int)head.nodes, (int)mesh_.num_global_cells,
             (int)mesh_.num_global_nodes);
  const double ranks = head.ranks;
  // The field series stores nodes in the order of the ranks' partition: it
  // continues only on as many ranks as wrote it. On others a new -output
  // starts, so that the earlier fields are not replaced.
  if (ranks != size_) {
    int taken = 0;
    std::error_code ec;
    if (rank_ == 0)
      taken = std::filesystem::exists(opt_.output, ec) || std::filesystem::exists(opt_.output + ".partial", ec);
    PetscCallMPI(MPI_Bcast(&taken, 1, MPI_INT, 0, comm_));
    PetscCheck(!taken, comm_, PETSC_ERR_USER_INPUT,
               "-restart %s: written on %d ranks, continued on %d: the fields cannot continue in -output %s (their "
               "node order is the %d-rank partition's); give a new -output (the history continues whole)",
               opt_.restart.c_str(), (int)ranks, (int)size_, opt_.output.c_str(), (int)ranks);
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

} // namespace tf
