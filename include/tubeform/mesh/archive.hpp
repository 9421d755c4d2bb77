// A checkpoint file: the state of a run written or read through PETSc's HDF5
// viewer. Node and cell data are stored in the input mesh's numbering, so a
// run may continue on another number of ranks; numbers every rank holds alike
// (the load path position, the history) are stored once. Each part of a run
// lists its state in one Persist(Archive &) that both writes and reads, so a
// member added to the state is written and read by the same line.
#pragma once

#include <petscviewer.h>

#include <string>
#include <vector>

#include "tubeform/core/core.hpp"
#include "tubeform/mesh/mesh.hpp"

namespace tf {

class Archive {
public:
  Archive() = default;
  Archive(const Archive &) = delete;
  Archive &operator=(const Archive &) = delete;
  ~Archive();

  // Collective. Writing goes to `path`.tmp, renamed onto `path` by Close, so a
  // failed write leaves an earlier checkpoint at `path` as it was. `option`
  // names the file in errors (-checkpoint, -restart).
  // Writing needs `bytes` free on the file system (else an error before any write).
  PetscErrorCode Open(const Mesh &mesh, const std::string &path, bool write, const char *option, double bytes = 0);
  // Collective: closes the file (writing: renames it into place).
  PetscErrorCode Close();
  bool reading() const { return !write_; }
  const std::string &path() const { return path_; }
  // The group the following names are in ("/body").
  void Group(const std::string &group) { group_ = group; }

  // Numbers every rank holds alike (read: v is resized).
  PetscErrorCode Values(const char *name, std::vector<double> &v);
  PetscErrorCode Value(const char *name, double &v);
  PetscErrorCode Value(const char *name, PetscInt &v);
  PetscErrorCode Value(const char *name, bool &v);
  // A text every rank holds alike (an attribute of the current group).
  PetscErrorCode Text(const char *name, std::string &text);
  // Data of the local nodes (ghosts included; `comps` per node). Written from
  // the owned nodes; read into every local node, or with `owned_only` into the
  // owned ones (ghosts 0: per-rank contributions that sum over the ranks).
  PetscErrorCode NodeData(const char *name, std::vector<double> &v, int comps, bool owned_only = false);
  // Data of the local cells, `comps` per cell.
  PetscErrorCode CellData(const char *name, std::vector<double> &v, int comps);

  // Node data of other types (char, int, double: one number; Vec2: two).
  template <class T>
  PetscErrorCode Nodes(const char *name, std::vector<T> &v, bool owned_only = false)
  {
    constexpr int c = Width(T{});
    std::vector<double> flat(c * v.size());
    PetscFunctionBeginUser;
    if (!reading())
      for (size_t i = 0; i < v.size(); ++i) Put(v[i], &flat[c * i]);
    PetscCall(NodeData(name, flat, c, owned_only));
    if (reading())
      for (size_t i = 0; i < v.size(); ++i) Get(&flat[c * i], v[i]);
    PetscFunctionReturn(PETSC_SUCCESS);
  }

private:
  const Mesh *mesh_ = nullptr;
  PetscViewer viewer_ = nullptr;
  bool write_ = false;
  std::string path_, group_ = "/";
  const char *option_ = "";

  // Entities (nodes or cells) with input ids `orig` of nglobal, `comps` numbers each.
  PetscErrorCode Entities(const char *name, std::vector<double> &v, int comps, const std::vector<PetscInt> &orig,
                          PetscInt nglobal, const std::vector<char> *owned, bool owned_only);
  // Collective: the vector g (input numbering) as the 1-D dataset `path`.
  PetscErrorCode WriteVector(Vec g, const std::string &path) const;
  // Collective: a write that failed on any rank fails on every rank (PETSC_ERR_FILE_WRITE).
  PetscErrorCode Agree(bool ok, const std::string &path) const;
  std::string Path(const char *name) const { return group_ == "/" ? "/" + std::string(name) : group_ + "/" + name; }

  template <class T>
  static constexpr int Width(const T &)
  {
    return 1;
  }
  static constexpr int Width(const Vec2 &) { return 2; }
  template <class T>
  static void Put(const T &x, double *d)
  {
    d[0] = static_cast<double>(x);
  }
  static void Put(const Vec2 &x, double *d) { d[0] = x[0], d[1] = x[1]; }
  template <class T>
  static void Get(const double *d, T &x)
  {
    x = static_cast<T>(d[0]);
  }
  static void Get(const double *d, Vec2 &x) { x = {d[0], d[1]}; }
};

} // namespace tf
