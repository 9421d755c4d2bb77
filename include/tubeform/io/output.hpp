// Results through PETSc's HDF5 viewer: the mesh, vertex and cell fields as a
// time series (ParaView reads them through the .xmf written beside), the
// history in /history (one 1-D dataset per column), the options and metrics
// as attributes. The file is written as <output>.partial and renamed only when
// the run finishes, so a failed run never overwrites an earlier result.
#pragma once

#include <petscviewer.h>

#include <string>
#include <vector>

#include "tubeform/io/history.hpp"
#include "tubeform/mesh/mesh.hpp"

namespace tf {

// Room kept free on the results' file system beyond what a write needs
// (CheckRoom): HDF5's own metadata (a field step adds chunk indices and object
// headers of tens of kB; closing the file flushes its metadata cache) and the
// history CSV's rows written meanwhile (about 1 kB each), many times over.
// Parallel HDF5 does not recover from a write that finds the disk full (a
// 2-rank job then waits in its collective calls for ever; one rank fails
// again in MPI_Finalize), so a write is refused before it starts instead; and
// as much again is held in <output>.partial.room while the file is open, given
// back before it closes, so that even a disk another job filled lets it close.
constexpr double kRoomMargin = 1e6;
// Bytes a double takes in the file.
constexpr double kBytesPerValue = 8;
// The .xmf's lines for one field (or grid) of one step: about 300 bytes.
constexpr double kXdmfBytesPerEntry = 512;

struct CellField {
  std::string name;
  std::vector<double> values; // one per local cell
};

// A node field of 1 or 2 components (scalars, vectors in the global frame).
struct NodeField {
  std::string name;
  int components = 2;
  std::vector<double> values; // `components` per local node
};

// A rigid tool's outline at one field step (the tools in ParaView): its points (x, y) at the start and now,
// and the index pairs of the lines joining them, the same counts at every step.
struct ToolShape {
  std::string name;
  std::vector<double> xy0, xy;
  std::vector<int> lines;
};

class ResultWriter {
public:
  ~ResultWriter();
  // Collective. Checks the path first: a clear error if it cannot be written.
  PetscErrorCode Open(const Mesh &mesh, const std::string &path);
  // Collective: continues the results of an interrupted run at `path` from its
  // first times.size() field steps (those of its checkpoint): in its .partial
  // file, or in a copy of the finished file a stopped run left (the copy is
  // renamed over it only when the run finishes).
  PetscErrorCode Reopen(const Mesh &mesh, const std::string &path, const std::vector<double> &times);
  // Collective: everything written so far reaches the file (before a checkpoint counts on it).
  PetscErrorCode Flush();
  const std::vector<double> &times() const { return times_; }
  // Collective: one time-series entry (the same fields at every step).
  // A tool's outline goes to /tools/<name>/vertices (at the start) and /lines, its motion to
  // /tools/<name>/displacement (step, point, 2), as the body's (ParaView's Warp By Vector moves both).
  PetscErrorCode WriteStep(PetscInt step, double time, const std::vector<NodeField> &nodes,
                           const std::vector<CellField> &cells, const std::vector<ToolShape> &tools = {});
  // The .xmf shows a field step written at load parameter lambda at the time lambda x scale: the load path's
  // seconds (a tool scene's duration is its stroke over the punch speed).
  void SetTimeScale(double scale) { time_scale_ = scale; }
  // Collective: history and attributes into <path>.partial, closed, and the
  // .xmf beside it as <name>.xmf.partial (a failure of either is every rank's);
  // nothing is renamed yet. A run that stopped early keeps why in the string
  // attribute stop_reason of /history (the line it printed, which may not
  // reach anyone: a job whose mpirun has left).
  PetscErrorCode Close(const History &history, const std::vector<std::pair<std::string, double>> &metrics,
                       const std::string &stop_reason);
  // Collective, after Close: the results renamed into place (rank 0), the
  // HDF5 file, the CSV at `csv` (none: empty) and then the .xmf; each replaces
  // an earlier file of its name whole.
  PetscErrorCode Place(const std::string &csv);

private:
  const Mesh *mesh_ = nullptr;
  PetscViewer viewer_ = nullptr;
  std::string path_;
  std::vector<double> times_;
  std::vector<std::string> cell_names_;
  std::vector<std::pair<std::string, int>> node_names_; // name, components
  // A tool in the results, written from field step `first` to `last` (the dies of one pass).
  struct ToolEntry {
    std::string name;
    size_t points, lines;
    PetscInt first, last;
  };
  std::vector<ToolEntry> tools_;
  // WriteStep's and Close's writes once their room is checked.
  PetscErrorCode WriteStepValues(PetscInt step, double time, const std::vector<NodeField> &nodes,
                                 const std::vector<CellField> &cells, const std::vector<ToolShape> &tools);
  PetscErrorCode WriteHistory(const History &history, const std::vector<std::pair<std::string, double>> &metrics,
                              const std::string &stop_reason);
  // `code` of a write: a library (HDF5) call that failed after the write's room was checked (another writer
  // filled the disk since) raised again naming -output, the call's own text kept; any other error stays its own.
  PetscErrorCode NameWriteFailure(PetscErrorCode code, const char *what) const;
  // At a restart: the tools the file holds, up to the checkpoint's steps.
  PetscErrorCode ReadTools();
  double time_scale_ = 1;
  // The room kept for closing the file (kRoomMargin bytes in <path>.partial.room, rank 0).
  PetscErrorCode Reserve();
  void FreeReserve();
  std::string ReservePath() const { return path_ + ".partial.room"; }
  // The .xmf beside the .h5, as <name>.xmf.partial (rank 0 alone; false when it could not be written).
  bool WriteXdmf() const;
  std::string XdmfPath() const;
};

// Collective: an error on every rank unless a file can be created at `path`
// (tested on rank 0 with a scratch file, after creating missing parent directories).
PetscErrorCode CheckWritable(MPI_Comm comm, const std::string &path, const char *option);
// Collective: an error (PETSC_ERR_FILE_WRITE) on every rank unless the file
// system of `path` has room for `bytes` (`what`, for the message) and
// kRoomMargin beside (asked on rank 0).
PetscErrorCode CheckRoom(MPI_Comm comm, const std::string &path, const char *option, double bytes, const char *what);
// Collective: `attributes` and `columns` (one value a row) of /history added
// to the finished result file at `path` in a way that cannot lose it: rank 0
// copies it to <path>.estimate.partial, adds them there and renames the copy
// over it. When that fails, `why` says so (every rank) and the file is as it was.
PetscErrorCode AddResultEstimate(MPI_Comm comm, const std::string &path,
                                 const std::vector<std::pair<std::string, double>> &attributes,
                                 const std::vector<std::pair<std::string, std::vector<double>>> &columns,
                                 std::string &why);
// A result file's path without its .h5 (the name its companions take: <stem>.xmf, <stem>.level<k>.h5).
std::string ResultStem(const std::string &path);
// Collective: the finished result file at `path` copied to `copy` (rank 0), so
// that a finer level may run into `path`; `why` says what failed (every rank;
// no copy is left then).
PetscErrorCode KeepResultCopy(MPI_Comm comm, const std::string &path, const std::string &copy, std::string &why);

} // namespace tf
