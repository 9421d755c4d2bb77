#include "tubeform/io/output.hpp"

#include <petscviewerhdf5.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "tubeform/core/core.hpp"
#include "tubeform/core/job_end.hpp"
#include "tubeform/core/log.hpp"
#include "tubeform/io/series.hpp"
#include "tubeform/step/rmin.hpp"

namespace tf {

PetscErrorCode CheckWritable(MPI_Comm comm, const std::string &path, const char *option)
{
  PetscMPIInt rank;
  int ok = 1;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (rank == 0) {
    // Missing parent directories are created (like results/ in a fresh clone).
    std::error_code ec;
    const auto parent = std::filesystem::path(path).parent_path();
    if (!parent.empty()) std::filesystem::create_directories(parent, ec);
    const std::string probe = path + ".probe";
    std::FILE *f = std::fopen(probe.c_str(), "w");
    ok = f != nullptr;
    if (f) {
      std::fclose(f);
      std::remove(probe.c_str());
    }
  }
  PetscCallMPI(MPI_Bcast(&ok, 1, MPI_INT, 0, comm));
  PetscCheck(ok, comm, PETSC_ERR_USER_INPUT,
             "%s %s: cannot create the file (does the directory exist and is it writable?)", option, path.c_str());
  PetscFunctionReturn(PETSC_SUCCESS);
}

ResultWriter::~ResultWriter()
{
  // (an error ended the run: the reserve makes room for closing the file, whatever filled the disk)
  FreeReserve();
  // (a close that fails too, on the disk that stopped the run, keeps the run's error: KeepErrorText)
  if (viewer_) KeepErrorText([this] { (void)PetscViewerDestroy(&viewer_); });
}

PetscErrorCode ResultWriter::Open(const Mesh &mesh, const std::string &path)
{
  PetscFunctionBeginUser;
  mesh_ = &mesh;
  path_ = path;
  PetscCall(CheckWritable(mesh.comm, path, "-output"));
  PetscCall(CheckRoom(mesh.comm, path, "-output",
                      kBytesPerValue * (2.0 * mesh.num_global_nodes + 4.0 * mesh.num_global_cells) + kRoomMargin,
                      "the mesh"));
  PetscCall(Reserve());
  PetscCall(PetscViewerHDF5Open(mesh.comm, (path + ".partial").c_str(), FILE_MODE_WRITE, &viewer_));
  PetscCall(PetscViewerPushFormat(viewer_, PETSC_VIEWER_HDF5_XDMF));
  PetscCall(DMView(mesh.dm, viewer_));
  hid_t file;
  PetscCall(PetscViewerHDF5GetFileId(viewer_, &file));
  for (const char *group : {"/vertex_fields", "/cell_fields"}) {
    hid_t g = H5Gcreate2(file, group, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    TF_CHECK_HDF5(g);
    TF_CHECK_HDF5(H5Gclose(g));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode ResultWriter::Reopen(const Mesh &mesh, const std::string &path, const std::vector<double> &times)
{
  PetscMPIInt rank;
  int found = 0; // 1: the .partial file, 2: the finished file (copied), 0: neither
  hid_t file;

  PetscFunctionBeginUser;
  mesh_ = &mesh;
  path_ = path;
  times_ = times;
  PetscCallMPI(MPI_Comm_rank(mesh.comm, &rank));
  const std::string partial = path + ".partial";
  if (rank == 0) {
    std::error_code ec;
    // (H5Fis_hdf5 prints an error stack for a missing file.)
    if (std::filesystem::exists(partial, ec) && H5Fis_hdf5(partial.c_str()) > 0)
      found = 1;
    else if (std::filesystem::exists(path, ec) && H5Fis_hdf5(path.c_str()) > 0 &&
             std::filesystem::copy_file(path, partial, std::filesystem::copy_options::overwrite_existing, ec))
      found = 2;
  }
  PetscCallMPI(MPI_Bcast(&found, 1, MPI_INT, 0, mesh.comm));
  PetscCheck(found, mesh.comm, PETSC_ERR_USER_INPUT,
             "-restart: the results of the interrupted run are not in -output %s (nor %s): give the -output of the "
             "run that wrote the checkpoint",
             path.c_str(), partial.c_str());
  PetscCall(Reserve());
  PetscCall(PetscViewerHDF5Open(mesh.comm, partial.c_str(), FILE_MODE_APPEND, &viewer_));
  PetscCall(PetscViewerPushFormat(viewer_, PETSC_VIEWER_HDF5_XDMF));
  PetscCall(PetscViewerHDF5GetFileId(viewer_, &file));
  // The field steps the checkpoint counts on must be there (later ones are
  // overwritten as the run goes on); a finished file's history goes.
  hsize_t steps = 0;
  if (H5Lexists(file, "/time", H5P_DEFAULT) > 0) {
    const hid_t dset = H5Dopen2(file, "/time", H5P_DEFAULT);
    TF_CHECK_HDF5(dset);
    const hid_t space = H5Dget_space(dset);
    TF_CHECK_HDF5(space);
    TF_CHECK_HDF5(H5Sget_simple_extent_dims(space, &steps, nullptr));
    TF_CHECK_HDF5(H5Sclose(space));
    TF_CHECK_HDF5(H5Dclose(dset));
  }
  PetscCheck(steps >= times.size(), mesh.comm, PETSC_ERR_USER_INPUT,
             "-restart: %s holds %d field steps, fewer than the %d of the checkpoint (not the results of the run "
             "that wrote it?)",
             (found == 1 ? partial : path).c_str(), (int)steps, (int)times.size());
  // A finished file's history and options go (the options attribute keeps its
  // length when rewritten: a longer string would be cut).
  if (H5Lexists(file, "/history", H5P_DEFAULT) > 0) TF_CHECK_HDF5(H5Ldelete(file, "/history", H5P_DEFAULT));
  if (H5Aexists(file, "options") > 0) TF_CHECK_HDF5(H5Adelete(file, "options"));
  PetscCall(ReadTools());
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode ResultWriter::ReadTools()
{
  hid_t file;
  PetscFunctionBeginUser;
  PetscCall(PetscViewerHDF5GetFileId(viewer_, &file));
  tools_.clear();
  if (!PathExists(file, "/tools")) PetscFunctionReturn(PETSC_SUCCESS);
  const hid_t group = H5Gopen2(file, "/tools", H5P_DEFAULT);
  TF_CHECK_HDF5(group);
  H5G_info_t info;
  TF_CHECK_HDF5(H5Gget_info(group, &info));
  std::vector<std::string> names, stale;
  for (hsize_t i = 0; i < info.nlinks; ++i) {
    const ssize_t length = H5Lget_name_by_idx(group, ".", H5_INDEX_NAME, H5_ITER_INC, i, nullptr, 0, H5P_DEFAULT);
    TF_CHECK_HDF5(length);
    std::string name(length + 1, '\0');
    TF_CHECK_HDF5(H5Lget_name_by_idx(group, ".", H5_INDEX_NAME, H5_ITER_INC, i, &name[0], name.size(), H5P_DEFAULT));
    name.resize(length);
    names.push_back(name);
  }
  for (const std::string &name : names) {
    const std::string base = "/tools/" + name;
    hsize_t rows[3] = {0, 0, 0};
    const auto extent = [&](const std::string &path, int at) -> PetscErrorCode {
      hsize_t dims[3] = {0, 0, 0};
      PetscFunctionBeginUser;
      const hid_t dset = H5Dopen2(file, path.c_str(), H5P_DEFAULT);
      TF_CHECK_HDF5(dset);
      const hid_t space = H5Dget_space(dset);
      TF_CHECK_HDF5(space);
      TF_CHECK_HDF5(H5Sget_simple_extent_dims(space, dims, nullptr));
      rows[at] = dims[0];
      TF_CHECK_HDF5(H5Sclose(space));
      TF_CHECK_HDF5(H5Dclose(dset));
      PetscFunctionReturn(PETSC_SUCCESS);
    };
    PetscCall(extent(base + "/vertices", 0));
    PetscCall(extent(base + "/lines", 1));
    PetscCall(extent(base + "/displacement", 2));
    int first = 0;
    const hid_t dset = H5Dopen2(file, (base + "/displacement").c_str(), H5P_DEFAULT);
    TF_CHECK_HDF5(dset);
    if (H5Aexists(dset, "first_step") > 0) {
      const hid_t attr = H5Aopen(dset, "first_step", H5P_DEFAULT);
      TF_CHECK_HDF5(attr);
      TF_CHECK_HDF5(H5Aread(attr, H5T_NATIVE_INT, &first));
      TF_CHECK_HDF5(H5Aclose(attr));
    }
    TF_CHECK_HDF5(H5Dclose(dset));
    // Steps past the checkpoint's are written again as the run goes on.
    const PetscInt last = std::min<PetscInt>((PetscInt)rows[2], (PetscInt)times_.size()) - 1;
    if (first <= last)
      tools_.push_back({name, rows[0], rows[1], first, last});
    else
      stale.push_back(name); // first written after the checkpoint: written again as the run goes on
  }
  for (const std::string &name : stale) TF_CHECK_HDF5(H5Ldelete(group, name.c_str(), H5P_DEFAULT));
  TF_CHECK_HDF5(H5Gclose(group));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode ResultWriter::Flush()
{
  hid_t file;

  PetscFunctionBeginUser;
  PetscCall(PetscViewerHDF5GetFileId(viewer_, &file));
  // Collective, and a failure is every rank's (one rank returning alone would leave the others waiting).
  int mine = H5Fflush(file, H5F_SCOPE_GLOBAL) < 0, any = 0;
  PetscCallMPI(MPI_Allreduce(&mine, &any, 1, MPI_INT, MPI_MAX, mesh_->comm));
  PetscCheck(!any, mesh_->comm, PETSC_ERR_FILE_WRITE, "-output %s: flushing %s.partial failed (HDF5; a full disk?)",
             path_.c_str(), path_.c_str());
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode ResultWriter::NameWriteFailure(PetscErrorCode code, const char *what) const
{
  if (code != PETSC_ERR_LIB) return code;
  return PetscError(PETSC_COMM_SELF, __LINE__, PETSC_FUNCTION_NAME, __FILE__, PETSC_ERR_FILE_WRITE, PETSC_ERROR_INITIAL,
                    "-output %s: writing %s into %s.partial failed (%s; a full disk?); nothing is renamed into place",
                    path_.c_str(), what, path_.c_str(), ErrorText(code).c_str());
}

PetscErrorCode ResultWriter::WriteStep(PetscInt step, double time, const std::vector<NodeField> &nodes,
                                       const std::vector<CellField> &cells, const std::vector<ToolShape> &tools)
{
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(Log::output, 0, 0, 0, 0));
  {
    // Room first: HDF5 does not recover from a write that finds the disk full.
    double values = 1;
    for (const auto &f : nodes) values += (double)f.components * mesh_->num_global_nodes;
    values += (double)cells.size() * mesh_->num_global_cells;
    for (const auto &t : tools) values += (double)t.xy.size();
    PetscCall(CheckRoom(mesh_->comm, path_, "-output", kBytesPerValue * values, "the next field step"));
  }
  PetscCall(NameWriteFailure(WriteStepValues(step, time, nodes, cells, tools), "a field step"));
  PetscCall(PetscLogEventEnd(Log::output, 0, 0, 0, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode ResultWriter::WriteStepValues(PetscInt step, double time, const std::vector<NodeField> &nodes,
                                             const std::vector<CellField> &cells, const std::vector<ToolShape> &tools)
{
  Vec local, global;
  PetscScalar *a;
  hid_t file;
  PetscMPIInt rank;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(mesh_->comm, &rank));
  PetscCall(PetscViewerHDF5GetFileId(viewer_, &file));
  times_.push_back(time);
  PetscCall(WriteSeriesValue(file, "/time", time, step, rank == 0));
  // Node fields, in the global vector's order, which is the order of
  // /geometry/vertices: 2 components on the displacement DM, 1 on its
  // one-dof clone (whose offsets are the displacement DM's halved).
  node_names_.clear();
  for (const auto &field : nodes) {
    node_names_.emplace_back(field.name, field.components);
    DM dm = field.components == 2 ? mesh_->dm : mesh_->node_dm;
    const int c = field.components;
    PetscCall(DMGetLocalVector(dm, &local));
    PetscCall(DMGetGlobalVector(dm, &global));
    PetscCall(VecGetArray(local, &a));
    for (PetscInt n = 0; n < mesh_->num_nodes; ++n)
      for (int k = 0; k < c; ++k) a[mesh_->node_dof[n] / (2 / c) + k] = field.values[c * n + k];
    PetscCall(VecRestoreArray(local, &a));
    PetscCall(DMLocalToGlobal(dm, local, INSERT_VALUES, global));
    PetscCall(WriteSeriesStep(file, ("/vertex_fields/" + field.name).c_str(), global, c, step));
    PetscCall(DMRestoreGlobalVector(dm, &global));
    PetscCall(DMRestoreLocalVector(dm, &local));
  }

  // Cell fields: one scalar per cell.
  cell_names_.clear();
  for (const auto &field : cells) {
    cell_names_.push_back(field.name);
    PetscCall(DMGetGlobalVector(mesh_->cell_dm, &global));
    PetscCall(VecGetArray(global, &a));
    for (PetscInt c = 0; c < mesh_->num_cells; ++c) a[c] = field.values[c];
    PetscCall(VecRestoreArray(global, &a));
    PetscCall(WriteSeriesStep(file, ("/cell_fields/" + field.name + "_c").c_str(), global, 1, step));
    PetscCall(DMRestoreGlobalVector(mesh_->cell_dm, &global));
  }
  // Tools: every rank holds the same outline, rank 0 writes it.
  for (const auto &t : tools) {
    const std::string base = "/tools/" + t.name;
    auto entry = std::find_if(tools_.begin(), tools_.end(), [&](const ToolEntry &e) { return e.name == t.name; });
    if (entry == tools_.end())
      tools_.push_back({t.name, t.xy.size() / 2, t.lines.size() / 2, step, step});
    else
      entry->last = step;
    std::vector<double> moved(t.xy.size());
    for (size_t i = 0; i < t.xy.size(); ++i) moved[i] = t.xy[i] - t.xy0[i];
    PetscCall(
      WritePairsOnce(file, (base + "/lines").c_str(), H5T_NATIVE_INT, t.lines.data(), t.lines.size() / 2, rank == 0));
    PetscCall(
      WritePairsOnce(file, (base + "/vertices").c_str(), H5T_NATIVE_DOUBLE, t.xy0.data(), t.xy0.size() / 2, rank == 0));
    PetscCall(
      WriteSeriesPairs(file, (base + "/displacement").c_str(), moved.data(), moved.size() / 2, step, rank == 0));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode ResultWriter::WriteHistory(const History &history,
                                          const std::vector<std::pair<std::string, double>> &metrics,
                                          const std::string &stop_reason)
{
  hid_t file, group;
  PetscMPIInt rank;
  char *all_options;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(mesh_->comm, &rank));
  // /history: one 1-D dataset per column. Dataset creation is collective;
  // every rank holds the same history, rank 0 writes the values.
  PetscCall(PetscViewerHDF5GetFileId(viewer_, &file));
  const hsize_t n = history.rows().size();
  group = H5Gcreate2(file, "/history", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  TF_CHECK_HDF5(group);
  std::vector<double> column(n);
  for (const auto &col : history.columns()) {
    hid_t space, dset;
    for (hsize_t r = 0; r < n; ++r) column[r] = col.Of(history.rows()[r]);
    space = H5Screate_simple(1, &n, nullptr);
    TF_CHECK_HDF5(space);
    dset = H5Dcreate2(group, col.name, H5T_NATIVE_DOUBLE, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    TF_CHECK_HDF5(dset);
    if (rank == 0 && n > 0)
      TF_CHECK_HDF5(H5Dwrite(dset, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, column.data()));
    TF_CHECK_HDF5(H5Dclose(dset));
    TF_CHECK_HDF5(H5Sclose(space));
  }
  TF_CHECK_HDF5(H5Gclose(group));
  const PetscInt nrows = (PetscInt)n;
  PetscCall(PetscViewerHDF5WriteAttribute(viewer_, "/history", "rows", PETSC_INT, &nrows));
  std::string names;
  for (int k = 0; k < kNumLimiters; ++k) names += std::string(k ? "," : "") + LimiterName(k);
  PetscCall(PetscViewerHDF5WriteAttribute(viewer_, "/history", "limiter_names", PETSC_STRING, names.c_str()));
  for (const auto &m : metrics)
    PetscCall(PetscViewerHDF5WriteAttribute(viewer_, "/history", m.first.c_str(), PETSC_DOUBLE, &m.second));
  if (!stop_reason.empty())
    PetscCall(PetscViewerHDF5WriteAttribute(viewer_, "/history", "stop_reason", PETSC_STRING, stop_reason.c_str()));
  PetscCall(PetscOptionsGetAll(nullptr, &all_options));
  PetscCall(PetscViewerHDF5WriteAttribute(viewer_, "/", "options", PETSC_STRING, all_options));
  PetscCall(PetscFree(all_options));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode ResultWriter::Close(const History &history, const std::vector<std::pair<std::string, double>> &metrics,
                                   const std::string &stop_reason)
{
  PetscMPIInt rank;

  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(Log::output, 0, 0, 0, 0));
  PetscCallMPI(MPI_Comm_rank(mesh_->comm, &rank));
  {
    const double index = (double)times_.size() * (node_names_.size() + cell_names_.size() + tools_.size() + 4);
    PetscCall(CheckRoom(mesh_->comm, path_, "-output",
                        kBytesPerValue * history.columns().size() * history.rows().size() + kXdmfBytesPerEntry * index,
                        "the history and the ParaView index"));
  }
  PetscCall(NameWriteFailure(WriteHistory(history, metrics, stop_reason), "the history"));
  PetscCall(PetscViewerPopFormat(viewer_));
  FreeReserve(); // (its room for the metadata the file's close writes)
  // As Flush: a close that fails (the disk filled by another writer) is every rank's, and names the file.
  int mine = PetscViewerDestroy(&viewer_) != PETSC_SUCCESS, any = 0;
  PetscCallMPI(MPI_Allreduce(&mine, &any, 1, MPI_INT, MPI_MAX, mesh_->comm));
  PetscCheck(!any, mesh_->comm, PETSC_ERR_FILE_WRITE,
             "-output %s: closing %s.partial failed (HDF5; a full disk?); nothing is renamed into place", path_.c_str(),
             path_.c_str());

  // The ParaView index beside it, written by rank 0 as <name>.xmf.partial;
  // every rank learns how that went before any raises it (one rank returning
  // alone would leave the others waiting).
  int xdmf = rank == 0 ? WriteXdmf() : 1;
  if (!xdmf) std::remove((XdmfPath() + ".partial").c_str());
  PetscCallMPI(MPI_Bcast(&xdmf, 1, MPI_INT, 0, mesh_->comm));
  PetscCheck(xdmf, mesh_->comm, PETSC_ERR_FILE_WRITE,
             "-output %s: its ParaView index %s.partial cannot be written (a full disk?); nothing is renamed into "
             "place (the results stay in %s.partial)",
             path_.c_str(), XdmfPath().c_str(), path_.c_str());
  PetscCall(PetscLogEventEnd(Log::output, 0, 0, 0, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

std::string ResultStem(const std::string &path)
{
  return path.size() > 3 && path.substr(path.size() - 3) == ".h5" ? path.substr(0, path.size() - 3) : path;
}

std::string ResultWriter::XdmfPath() const { return ResultStem(path_) + ".xmf"; }

} // namespace tf
