// The per-increment history of a run (docs/output.md, "History columns"): kept on every
// rank (values are global sums/maxima), written to /history and to CSV.
#pragma once

#include <petscsys.h>

#include <cstdio>
#include <string>
#include <vector>

#include "tubeform/mesh/archive.hpp"

namespace tf {

// Room in a row for the columns the tools declare (scenes/tool_columns.hpp): a row stays a block of doubles, which
// the companions' runs send whole (driver/companions.hpp); four slots to spare over the twelve declared.
constexpr int kToolColumnRoom = 16;

// A history row: the run's own columns (every scene's: its path, controller, energies, contacts, shape) and the
// tools' declared ones, by slot.
struct HistoryRow {
  double increment = 0, stroke = 0, load = 0, rmin = 1, limiter = 0, limiter_where = -1;
  double n_contact = 0, n_plastic = 0, friction_iters = 0, residual = 0, r_max = 0, q_avg = 0;
  double w_ext = 0, w_int = 0, w_plastic = 0, w_friction = 0, w_elastic = 0, energy_error = 0;
  double c_over_t = 0, x_max = 0, y_max = 0, deviation_ratio = 1;
  double redo = 0, drift = 0, unsettled = 0, events_inside = 0, inconsistent = 0;
  double r_corner_x = 0, r_corner_y = 0, penetration = 0, tension = 0, stage = 0;
  double release_force = 0, contact_gap = 0, fn_mismatch = 0;
  double w_kinetic = 0, w_inertia = 0, inertia = 0, w_damped = 0, w_tool = 0, internal_error = 0;
  double slip = 0, fn_sum = 0, det_sign = 0;
  // A springback (release 1 by the material's law, 2 elastic): the points that reached the yield surface in it, how far
  // past it an elastic one carried a point (sigma_eq / sigma_y - 1), the largest plastic strain taken in one with the
  // material's law.
  double release = 0, release_yielded = 0, release_excess = 0, release_dep = 0;
  double tool[kToolColumnRoom] = {}; // the tools' columns (ToolColumn::slot); 0 where a tool does not act
};

// A column a tool declares and fills (scenes/tool_columns.hpp): its name, what it means, the column it follows in
// the history (/history's order and the CSV's: a column declared later than the files that have it keeps its
// place; nullptr: after the last), and its slot in a row's `tool`.
struct ToolColumn {
  const char *name;
  const char *meaning;
  const char *after;
  int slot;
};

struct HistoryColumn {
  const char *name;
  double HistoryRow::*field; // the run's own column; nullptr: a tool's, at `slot` of the row's `tool`
  const char *meaning;
  bool may_be_infinite = false; // Inf is a value of the quantity (a flat side's radius), not an overflow
  int slot = -1;
  double Of(const HistoryRow &row) const { return field ? row.*field : row.tool[slot]; }
  double &Of(HistoryRow &row) const { return field ? row.*field : row.tool[slot]; }
};

class History {
public:
  ~History();
  // Before the first row (every rank): the tools' columns placed among the run's own (each after the column it
  // names); an error (every rank alike) for a name taken twice, a place not found, a slot past the room.
  PetscErrorCode Declare(const std::vector<ToolColumn> &tools, MPI_Comm comm);
  // The columns in the order /history and the CSV have them.
  const std::vector<HistoryColumn> &columns() const { return columns_; }
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
  std::vector<HistoryColumn> columns_ = OwnColumns();
  std::vector<HistoryRow> rows_;
  std::FILE *csv_ = nullptr;
  std::string csv_path_;
  int csv_errno_ = 0;
  void Checked(bool ok);                          // remembers the first failure's errno
  static std::vector<HistoryColumn> OwnColumns(); // the run's own columns, in their order
};

} // namespace tf
