// The answer of a run, as a forming engineer reads it at its end, pass by pass
// (a press's pass is its loading stage 2p and its release 2p + 1): the load at
// the end of loading and the largest, the load and C/t at the reported
// strokes, C/t and the half-extents C1 (across the press) and C2 (along it)
// loaded and after springback; and the run's estimate of its own error in
// them, its mesh's part and its increments' apart, from two companion runs of
// the same case (docs/accuracy.md, "The error estimate").
#pragma once

#include <petscsys.h>

#include <string>
#include <utility>
#include <vector>

#include "tubeform/io/history.hpp"

namespace tf {

// The strokes the answer reports besides the end of loading (mm): the paper's.
constexpr double kReportedStrokes[] = {1.0, 2.0, 3.0, 4.2};
// The error estimate, from two companion runs that keep the run's element and
// friction law and change one thing each: `mesh` has half the cells through
// the wall and around at the run's increments, `steps` has the cells of
// `mesh` at twice the run's increment limits. Each difference is taken as the
// run's error (Richardson at first order, refinement 2): the increments'
// error is proportional to -rmin_deps, and the mesh's is dominated by the
// wall's bending through a few cells, where qm6 is stiff by about 1/n and
// qm6bar's companion (half the cells, 4 on the accurate preset) is soft
// beyond its element's second order, so that no higher order is confirmed
// (Roache: where the order is not observed, the conservative one). With a
// mesh file, which cannot be coarsened, `mesh` is the run itself and the
// estimate covers the increments alone. Measured on the presets of five
// study tubes against converged references and of four against CalculiX
// (studies/estimate_levels.py, tools/against_ccx; docs/accuracy.md, "The
// error estimate"): qm6bar's mesh part at second order (a third) missed
// three of the six qm6bar cells of the accurate preset against CalculiX.
constexpr double kStepShare = 1.0; // of |steps - mesh|: the increments' error at the run's limits
constexpr double kMeshShare = 1.0; // of |mesh - run|: the mesh's error at the run's cells
// A loading row whose kinetic energy exceeds this fraction of the external
// work is a dynamic transient, not a point of the quasi-static curve: the
// median row of the validation runs carries 1e-8 to 1e-7 of the work, the rows
// where a local snap is resolved inside inertia's shortest step 3-5e-4, their
// punch load 2-5 x the curve's (docs/results.md, "The largest load of a thin tube").
constexpr double kQuasiStaticKinetic = 1e-5;

// The tube's shape in one state: C/t and the outer half-extents in the press's frame, C1 = x_max across the
// press and C2 = y_max along it (the deviation ratio is C1 / C2).
struct ShapeAt {
  double c_over_t = 0, c1 = 0, c2 = 0;
  double Ratio() const { return c2 > 0 ? c1 / c2 : 1.0; }
};

// An estimated error, its mesh's part and its increments' apart.
struct ErrorParts {
  double mesh = 0, steps = 0;
  double Total() const { return mesh + steps; }
};

// One pass: its loading's end, curve and shapes, and their estimated errors.
struct PassAnswer {
  bool springback = false; // the run went on past the pass's end of loading
  std::string release;     // what released the tube (a tool scene's springback: Scene::ReleaseOf)
  double start = 0;        // the stroke (die position) the pass's loading starts from
  double stroke = 0;       // at the end of loading
  double load = 0;
  // The largest load of the quasi-static rows, and the largest of the dynamic
  // transients' rows where it is above that (else 0) and its stroke.
  double load_max = 0, transient_max = 0, transient_stroke = 0;
  std::vector<double> strokes, loads, c_over_t; // the reported strokes (with the end of loading last)
  ShapeAt loaded, unloaded;
  // The estimate (estimated = false without a companion's pass): relative load error and absolute C/t error at
  // each reported stroke, C/t's after springback.
  bool estimated = false;
  std::vector<double> load_error, ct_error;
  std::vector<ErrorParts> load_parts, ct_parts;
  double ct_unloaded_error = 0;
  ErrorParts ct_unloaded_parts;
};

// The estimate's mesh companion keeps at least 2 cells through the wall: with one, a bending wall's answer is off by
// an order more than the run's (the fast preset's 2 x 64 case: a load difference of 4 % for a 4 % error, 0.09 in C/t
// for 0.01). A run of 2 cells through the wall has its wall's part out of the estimate (Answer::wall_covered).
constexpr PetscInt kCompanionMinNt = 2;
// The mesh companion's cells through the wall for a run of run_nt.
constexpr PetscInt CompanionNt(PetscInt run_nt) { return run_nt / 2 > kCompanionMinNt ? run_nt / 2 : kCompanionMinNt; }

struct Answer {
  bool tool = false;                                 // a tool scene: C/t, C1/C2 and springback mean something
  std::string stroke_name = "U", load_unit = "N/mm"; // the scene's, for the printed summary
  std::vector<PassAnswer> passes;                    // one, or each of a press's passes
  // The largest estimated errors over the passes (estimated: any pass has an estimate). With a mesh file the
  // companion keeps the mesh: the estimate then covers the increments alone (mesh_covered false).
  bool estimated = false, mesh_covered = true;
  bool wall_covered = true; // the mesh companion (or the last level) has other cells through the wall than the run
  double worst_load_error = 0, worst_ct_error = 0;
  ErrorParts worst_load, worst_ct;       // the largest's parts
  double target_load = 0, target_ct = 0; // the accuracy held to (0: none)
  bool demanded = false;                 // by -target_load or -target_c_over_t, not the preset's expectation
  int estimate_level = 0;                // the level whose run is the estimate's mesh companion (0: companion runs)
  double estimate_ratio = 2;             // that companion's cell size over the run's (Companions::mesh_ratio)
  // The estimate passes a target.
  bool ErrorOver() const
  {
    return (target_load > 0 && worst_load_error > target_load) || (tool && target_ct > 0 && worst_ct_error > target_ct);
  }
  // A demanded accuracy that the estimate cannot confirm, since it does not read the wall's cells (a finer level
  // can: driver/refine.cpp).
  bool WallUnread() const { return demanded && (target_load > 0 || (tool && target_ct > 0)) && !wall_covered; }
  // The run cannot confirm the accuracy it is held to (with a mesh file, whose error the estimate does not cover, it
  // is held to none).
  bool Over() const { return estimated && mesh_covered && (ErrorOver() || WallUnread()); }
};

// The estimate's companions' histories (see kStepShare); `mesh` empty when the run's mesh is kept (a mesh file).
// The mesh's part is |mesh - run| / (mesh_ratio - 1), Richardson at first order for `mesh`'s cells mesh_ratio
// times the run's in size; the increments' part |steps - steps_base| (steps_base empty: `mesh`). A finer level of
// accuracy on demand that keeps the last level's increments takes that level as its `mesh` and as its `steps_base`,
// `steps` the last level's cells at twice its increment limits (driver/refine.hpp, Refinement::reuse): one
// companion run, on the finest cells the estimate has.
struct Companions {
  std::vector<HistoryRow> mesh, steps, steps_base;
  double mesh_ratio = 2;
  int level = 0; // the level whose run is `mesh` (0: companion runs)
  bool Ran() const { return !steps.empty(); }
  // The rows the mesh's part is taken against (the run's own, `run`, with a mesh file), and those the increments'
  // part is.
  const std::vector<HistoryRow> &MeshRows(const std::vector<HistoryRow> &run) const
  {
    return mesh.empty() ? run : mesh;
  }
  const std::vector<HistoryRow> &BaseRows(const std::vector<HistoryRow> &run) const
  {
    return steps_base.empty() ? MeshRows(run) : steps_base;
  }
};

// The answer of a history (companions: the estimate's, or null; `trial` the run's trial increment as a fraction of a
// pass's loading, over whose last one the end of loading's estimate is read).
Answer Summarize(const std::vector<HistoryRow> &rows, bool tool, const Companions *companions, double trial);
// The estimate row by row, as /history columns error_load (relative) and error_c_over_t: a loading row's from the
// companions at its stroke; a release's rows the estimate of the loaded state they release (its load's, and the
// larger of its C/t's and the sprung-back C/t's); kNoEstimate where a companion did not reach.
constexpr double kNoEstimate = -1; // (no error is negative: the value says "none" without a NaN in the results)
std::vector<std::pair<std::string, std::vector<double>>> ErrorColumns(const std::vector<HistoryRow> &rows,
                                                                      const Companions &companions, const Answer &a);
// As HDF5 attributes of /history (a later pass's prefixed pass2_, pass3_, ...).
std::vector<std::pair<std::string, double>> AnswerAttributes(const Answer &a);
// Collective: the answer's lines on rank 0. An estimate over its targets is
// a warning, unless a finer level follows (driver/refine.hpp); `why` says
// which level follows, or why none does.
PetscErrorCode PrintAnswer(MPI_Comm comm, const Answer &a, bool finer_follows, const std::string &why);

} // namespace tf
