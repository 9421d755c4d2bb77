// The per-increment history of a run (docs/output.md, "History columns"): kept on every
// rank (values are global sums/maxima), written to /history and to CSV.
#pragma once

#include <petscsys.h>

#include <cstdio>
#include <string>
#include <vector>

#include "tubeform/mesh/archive.hpp"

namespace tf {

struct HistoryRow {
  double increment = 0, stroke = 0, load = 0, rmin = 1, limiter = 0, limiter_where = -1;
  double n_contact = 0, n_plastic = 0, friction_iters = 0, residual = 0, r_max = 0, q_avg = 0;
  double w_ext = 0, w_int = 0, w_plastic = 0, w_friction = 0, w_elastic = 0, energy_error = 0;
  double c_over_t = 0, x_max = 0, y_max = 0, deviation_ratio = 1;
  double redo = 0, drift = 0, unsettled = 0, events_inside = 0, inconsistent = 0;
  double r_corner_x = 0, r_corner_y = 0, penetration = 0, tension = 0, stage = 0, n_contact_apex = 0;
  double release_force = 0, contact_gap = 0, fn_mismatch = 0;
  double tool_fx = 0, tool_fy = 0, tool_moment = 0;
  double lower_fx = 0, lower_fy = 0, lower_moment = 0;
  double side_load = 0;   // the side dies' force along their motion, each, on the whole tube (N/mm; 0: none)
  double side_stroke = 0; // the side dies' travel (mm): the stroke, or their own under -side_force (0: no side dies)
  double hold_moment = 0, hold_friction = 0; // the rotation hold's couple, and friction's largest (N mm/mm)
  double die_x = 0;                          // -die_path: the upper die's sideways displacement (mm)
  double die_turn = 0;                       // -die_path_turn: the upper die's turn (degrees, counter-clockwise)
  double w_kinetic = 0, w_inertia = 0, inertia = 0, w_damped = 0, w_tool = 0, internal_error = 0;
  double slip = 0, fn_sum = 0, det_sign = 0;
  // A springback (release 1 by the material's law, 2 elastic): the points that reached the yield surface in it, how far
  // past it an elastic one carried a point (sigma_eq / sigma_y - 1), the largest plastic strain taken in one with the
  // material's law.
  double release = 0, release_yielded = 0, release_excess = 0, release_dep = 0;
};

struct HistoryColumn {
  const char *name;
  double HistoryRow::*field;
  const char *meaning;
  bool may_be_infinite = false; // Inf is a value of the quantity (a flat side's radius), not an overflow
};
const std::vector<HistoryColumn> &HistoryColumns();

class History {
public:
  ~History();
  // Opens `<path>.partial` on rank 0 (renamed to `path` once the results are
  // complete: PlaceResults); false when rank 0 cannot create it. The caller
  // broadcasts the outcome.
  bool OpenCsv(const std::string &path, int rank);
  // A row into the history (every rank) and the CSV file (rank 0): every write
  // is checked; the first that fails is remembered (CsvError) and ends the
  // file's writing.
  void Append(const HistoryRow &row);
  // Rank 0: the errno of the first failed write of the CSV file (0: none, or no file here).
  int CsvError() const { return csv_errno_; }
  // Rank 0: closes the file (its last write checked); returns CsvError().
  int CloseCsv();
  // Rank 0: closes and removes the file of a failed write (a truncated history; on a full disk, its room lets the
  // HDF5 file close).
  void DropCsv();
  // Collective: writes or reads the rows (read: they replace these, and go to
  // the CSV file when one is open).
  PetscErrorCode Persist(Archive &ar, MPI_Comm comm);
  const std::vector<HistoryRow> &rows() const { return rows_; }

private:
  std::vector<HistoryRow> rows_;
  std::FILE *csv_ = nullptr;
  std::string csv_path_;
  int csv_errno_ = 0;
  void Checked(bool ok); // remembers the first failure's errno
};

} // namespace tf
