// The answer of a run, as a forming engineer reads it at its end, pass by pass
// (a press's pass is its loading stage 2p and its release 2p + 1): the load at
// the end of loading and the largest, the load and C/t at the reported
// strokes, C/t and the half-extents C1 (across the press) and C2 (along it)
// loaded and after springback; and the run's estimate of its own error in
// them, from a coarser companion run of the same case (a two-level Richardson
// estimate: the difference of the two levels bounds the finer one's error once
// both are in the asymptotic range; docs/accuracy.md, "The error estimate").
#pragma once

#include <petscsys.h>

#include <string>
#include <utility>
#include <vector>

#include "tubeform/io/history.hpp"

namespace tf {

// The strokes the answer reports besides the end of loading (mm): the paper's.
constexpr double kReportedStrokes[] = {1.0, 2.0, 3.0, 4.2};
// The estimate is this many times the difference between the run and its
// companion of half the resolution: Roache's safety factor for a grid
// convergence index from two grids (with an order p >= 1 the finer run's
// error is at most the difference, 1 / (2^p - 1), once both runs are in the
// asymptotic range; the companion at half the preset's resolution often is
// not). Measured on the fast and default presets of fourteen validation tubes
// (against CalculiX where it ran, our extrapolated references elsewhere):
// with 1 it bounded 20 of 28 load errors and 22 of 28 C/t errors, with 3
// all 56 (scripts/estimate_study.py; docs/accuracy.md, "The error estimate").
constexpr double kEstimateSafety = 3.0;
// A loading row whose kinetic energy exceeds this fraction of the external
// work is a dynamic transient, not a point of the quasi-static curve: the
// median row of the validation runs carries 1e-8 to 1e-7 of the work, the rows
// where a local snap is resolved inside inertia's shortest step 3-5e-4, their
// punch load 2-5 x the curve's (docs/results.md, "The largest load").
constexpr double kQuasiStaticKinetic = 1e-5;

// The tube's shape in one state: C/t and the outer half-extents in the press's frame, C1 = x_max across the
// press and C2 = y_max along it (the deviation ratio is C1 / C2).
struct ShapeAt {
  double c_over_t = 0, c1 = 0, c2 = 0;
  double Ratio() const { return c2 > 0 ? c1 / c2 : 1.0; }
};

// One pass: its loading's end, curve and shapes, and their estimated errors.
struct PassAnswer {
  bool springback = false; // the run went on past the pass's end of loading
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
  double ct_unloaded_error = 0;
};

struct Answer {
  bool tool = false;                                 // a tool scene: C/t, C1/C2 and springback mean something
  std::string stroke_name = "U", load_unit = "N/mm"; // the scene's, for the printed summary
  std::string release;                               // what released the tube (a tool scene's springback)
  std::vector<PassAnswer> passes;                    // one, or a press's two
  // The largest estimated errors over the passes (estimated: any pass has an estimate). With a mesh file the
  // companion keeps the mesh: the estimate then covers the increments alone (mesh_covered false).
  bool estimated = false, mesh_covered = true;
  double worst_load_error = 0, worst_ct_error = 0;
};

// The answer of a history (companion: the coarser run's, or null).
Answer Summarize(const std::vector<HistoryRow> &rows, bool tool, const std::vector<HistoryRow> *companion);
// As HDF5 attributes of /history (the second pass's prefixed pass2_).
std::vector<std::pair<std::string, double>> AnswerAttributes(const Answer &a);
// Collective: the answer's lines on rank 0; `targets` the preset's accuracy
// targets (load relative, C/t absolute; 0: none), whose excess is a warning.
PetscErrorCode PrintAnswer(MPI_Comm comm, const Answer &a, double target_load, double target_ct);

} // namespace tf
