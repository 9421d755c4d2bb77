// Checkpoints of a run (docs/reliability.md, "Checkpoint and restart"): after
// an increment the whole state is written to -checkpoint (atomically: a
// scratch file renamed into place) and read back by -restart, which goes on
// with the next increment as the run would have. Everything an increment
// reads from the increments before is in it: the body's point states and
// coordinates, inertia's motion, the contact set, the scene's stage loads,
// the history and the energy accounts, the position on the load path; the
// forces at the end of the last increment are recomputed from that state by
// the same calls that computed them, so they come back bit for bit.
#include <cctype>
#include <cmath>
#include <filesystem>
#include <map>
#include <set>
#include <sstream>
#include <string>

#include "tubeform/driver/problem.hpp"

namespace tf {

namespace {
// The layout of a checkpoint; a file of another version is refused (4: several tools; 5: a force-controlled one;
// 6: the second pass's dies moved back to the tube; 7: the side dies' travel, the scene read before the contacts;
// 8: the rotation hold's columns; 9: die_x; 10: the hold's pins of the slide; 11: die_turn; 12: the springback's
// law and its measure at the yield surface; 13: the symmetry planes' walls and whether the dies were removed; 14:
// whether the corrections take their iterate's tangent; 15: the self-checks' peaks of work; 16: the side dies'
// travel in the second pass).
constexpr double kCheckpointVersion = 16;
// Room a checkpoint is given before it is written: 8-byte numbers, fewer than
// 64 per node, per cell and per history row (the state holds about 30, 48 and
// 49), and 1 MB for HDF5's own.
constexpr double kBytesPerItem = 8 * 64, kBytesOverhead = 1e6;
// Options a restart may change: where results and checkpoints go, how the
// run is watched and stopped, and PETSc's solver and diagnostics (prefixes).
// Every other option (geometry, mesh, material, path, tools, the r_min
// limits) shapes the state the checkpoint holds and must be the same.
const char *const kRunControl[] = {"restart",
                                   "checkpoint",
                                   "checkpoint_every",
                                   "output",
                                   "output_every",
                                   "output_stroke",
                                   "history_csv",
                                   "time_limit",
                                   "progress",
                                   "monitor",
                                   "allow_unused",
                                   "max_energy_error",
                                   "rmin_max_increments",
                                   "rmin_stall_increments",
                                   "friction_max_unsettled"};
const char *const kSolverPrefixes[] = {"ksp_", "pc_",  "mat_",     "redundant_", "log",    "malloc", "options_",
                                       "info", "help", "on_error", "fp_trap",    "check_", "memory", "objects_"};

bool RunControl(const std::string &name)
{
  for (const char *c : kRunControl)
    if (name == c) return true;
  for (const char *p : kSolverPrefixes)
    if (name.rfind(p, 0) == 0) return true;
  return false;
}

// The options of PetscOptionsGetAll ("-a 1 -b -c x") by name, without the dash.
std::map<std::string, std::string> ParseOptions(const std::string &all)
{
  std::map<std::string, std::string> m;
  std::istringstream in(all);
  std::string word, name;
  while (in >> word) {
    if (word.size() > 1 && word[0] == '-' && !std::isdigit((unsigned char)word[1]) && word[1] != '.')
      m[name = word.substr(1)] = "";
    else if (!name.empty())
      m[name] += (m[name].empty() ? "" : " ") + word;
  }
  return m;
}
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
  PetscCall(ar.Text("options", head.options));
  if (ar.reading()) PetscCall(CheckHeader(head));
  PetscCall(ar.Value("lambda", at_.lambda));
  PetscCall(ar.Value("increments", at_.inc));
  PetscCall(ar.Value("lambda_mark", at_.lambda_mark));
  PetscCall(ar.Value("increment_mark", at_.inc_mark));
  PetscCall(ar.Value("iterate_tangent", at_.iterate_tangent));
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
  PetscCall(ar.Value("q_sum", q_sum_)); // the time-averaged force of the equilibrium criterion
  PetscCall(ar.Value("q_count", q_count_));
  PetscCall(ar.Value("warned", warned_));
  ar.Group("/energy");
  for (auto [name, w] : {std::pair{"w_ext", &energy_.w_ext},
                         {"w_tool", &energy_.w_tool},
                         {"w_int", &energy_.w_int},
                         {"w_plastic", &energy_.w_plastic},
                         {"w_friction", &energy_.w_friction},
                         {"w_inertia", &energy_.w_inertia},
                         {"ext_peak", &energy_.ext_peak},
                         {"int_peak", &energy_.int_peak}})
    PetscCall(ar.Value(name, *w));
  PetscCall(history_.Persist(ar, comm_));
  // The parts' state.
  PetscCall(system_.Persist(ar));
  PetscCall(body_.Persist(ar));
  if (inertia_) PetscCall(inertia_->Persist(ar));
  // (the scene first: a restart inside a later pass gets that pass's tools, whose strokes the contact set reads)
  PetscCall(scene_->Persist(*model_, ar));
  if (contact_) PetscCall(contact_->Persist(ar));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Problem::WriteCheckpoint(ResultWriter &writer, const OutputSchedule &output)
{
  Archive ar;
  CheckpointHeader head;
  head.version = kCheckpointVersion, head.ranks = size_, head.output_bin = output.written(),
  head.times = writer.times();
  head.cells = mesh_.num_global_cells, head.nodes = mesh_.num_global_nodes;
  char *all;

  PetscFunctionBeginUser;
  PetscCall(PetscOptionsGetAll(nullptr, &all));
  head.options = all;
  PetscCall(PetscFree(all));
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
  {
    // The options that shape the state must be the run's that wrote it.
    char *all;
    PetscCall(PetscOptionsGetAll(nullptr, &all));
    const auto now = ParseOptions(all), then = ParseOptions(head.options);
    PetscCall(PetscFree(all));
    std::set<std::string> names;
    for (const auto *m : {&now, &then})
      for (const auto &kv : *m) names.insert(kv.first);
    for (const auto &n : names) {
      if (RunControl(n)) continue;
      const auto a = now.find(n), b = then.find(n);
      const std::string here = a == now.end() ? "not given" : "'" + a->second + "'",
                        there = b == then.end() ? "not given" : "'" + b->second + "'";
      PetscCheck(here == there, comm_, PETSC_ERR_USER_INPUT,
                 "-restart %s: -%s is %s here, %s in the run that wrote the checkpoint (restart with its options; "
                 "only where results go and how the run is watched and stopped may change)",
                 opt_.restart.c_str(), n.c_str(), here.c_str(), there.c_str());
    }
  }
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
