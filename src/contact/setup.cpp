// The contact set's start: its tools and candidate nodes, the nodes touching
// a tool at stroke 0, and which tool a point is nearest to.
#include <algorithm>
#include <cmath>

#include "tubeform/contact/contact.hpp"

namespace tf {

Projection ContactSet::ProjectNearest(PetscInt node, int &k) const
{
  Projection best;
  k = -1;
  for (int t = 0; t < (int)tools_.size(); ++t) {
    if (!MayTouch(node, t)) continue;
    const Projection pr = tools_[t].Project(Position(node));
    if (pr.segment >= 0 && (k < 0 || pr.gap < best.gap)) best = pr, k = t;
  }
  return best;
}

PetscErrorCode ContactSet::Setup(Mesh &mesh, System &system, const std::vector<double> &x, ContactSpec spec)
{
  PetscFunctionBeginUser;
  mesh_ = &mesh;
  system_ = &system;
  x_body_ = &x;
  tools_ = std::move(spec.tools);
  num_dies_ = (int)tools_.size();
  prm_ = spec.params;
  removed_ = dies_removed_ = false;
  const PetscInt n = mesh.num_nodes;
  candidates_ = mesh.node_sets[spec.candidates];
  die_node_.assign(n, 0);
  for (PetscInt node : candidates_) die_node_[node] = 1;
  contact_.assign(n, 0);
  released_.assign(n, 0);
  frozen_.assign(n, 0);
  global_frame_.assign(n, 0);
  sym_dir_.resize(n);
  segment_.assign(n, -1);
  tool_of_.assign(n, 0);
  touch_.assign(n, 0);
  for (auto *v : {&fn_, &x_, &gap_, &kappa_, &dxk_, &fnk_, &rate_, &last_dx_}) v->assign(n, 0.0);
  r4_.assign(n, kNever);
  r5_.assign(n, kNever);
  n_.assign(n, Vec2{0, -1});
  pending_.assign(n, Vec2{0, 0});
  l_.assign(n, Vec2{-1, 0});
  SetSymmetry(spec.symmetry);
  PetscCall(SetupWalls(spec));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode ContactSet::SetupWalls(const ContactSpec &spec)
{
  PetscFunctionBeginUser;
  const PetscInt n = mesh_->num_nodes;
  surfaces_ = spec.surfaces;
  surface_node_.assign(n, 0);
  held_on_.clear();
  double size = 0;
  for (double c : mesh_->x0) size = std::max(size, std::abs(c));
  PetscCallMPI(MPI_Allreduce(&size, &size_, 1, MPI_DOUBLE, MPI_MAX, comm()));
  if (spec.walls.empty()) PetscFunctionReturn(PETSC_SUCCESS);
  // The surfaces' nodes join the candidates (after the scene's, in their order).
  for (const std::string &set : spec.surfaces)
    for (PetscInt node : mesh_->node_sets[set]) {
      if (!die_node_[node] && !surface_node_[node]) candidates_.push_back(node);
      surface_node_[node] = 1;
    }
  for (const std::string &set : spec.walls) {
    const auto held =
      std::find_if(spec.symmetry.begin(), spec.symmetry.end(), [&](const auto &s) { return s.first == set; });
    PetscCheck(held != spec.symmetry.end(), comm(), PETSC_ERR_PLIB, "the symmetry wall %s is no symmetry plane",
               set.c_str());
    // (a line far past the body either way: a node beyond the other plane still finds it)
    tools_.push_back(SymmetryWall(held->second, kWallReach * (1 + size_), "symmetry-" + set));
    held_on_.emplace_back(n, 0);
    for (PetscInt node : mesh_->node_sets[set]) held_on_.back()[node] = 1;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

void ContactSet::SetSymmetry(const std::vector<std::pair<std::string, Vec2>> &symmetry)
{
  std::fill(sym_dir_.begin(), sym_dir_.end(), Vec2{0, 0});
  for (const auto &s : symmetry)
    for (PetscInt node : mesh_->node_sets[s.first]) sym_dir_[node] = s.second;
}

PetscErrorCode ContactSet::Initialize()
{
  PetscFunctionBeginUser;
  // A node already on the surface (within round-off of the coordinates) starts in contact.
  double size = 0, global_size;
  for (double x : mesh_->x0) size = std::max(size, std::abs(x));
  PetscCallMPI(MPI_Allreduce(&size, &global_size, 1, MPI_DOUBLE, MPI_MAX, comm()));
  const double tol = kStartGap * (1 + global_size);
  // The deepest node inside a tool, its place `where` = input number x tools + tool.
  const int ntools = (int)tools_.size();
  struct {
    double depth;
    int where;
  } inside = {0.0, -1}, deepest;
  for (PetscInt node : candidates_)
    for (int k = 0; k < (int)tools_.size(); ++k) {
      if (!MayTouch(node, k)) continue;
      const Projection pr = tools_[k].Project(Position(node));
      if (pr.segment >= 0 && std::abs(pr.gap) <= tol && !contact_[node]) contact_[node] = 1, tool_of_[node] = k;
      if (pr.segment >= 0 && -pr.gap > std::max(tol, inside.depth))
        inside = {-pr.gap, (int)mesh_->node_orig[node] * ntools + k};
    }
  // A tool that starts inside the body would push it out by its overlap in the
  // first increment: a wrong start (a mesh file larger than -tube_ro, say).
  PetscCallMPI(MPI_Allreduce(&inside, &deepest, 1, MPI_DOUBLE_INT, MPI_MAXLOC, comm()));
  PetscCheck(deepest.where < 0, comm(), PETSC_ERR_USER_INPUT,
             "the %s starts inside the body: node %d lies %g mm inside it (does -tube_ro match the mesh?)",
             tools_[deepest.where % ntools].name.c_str(), deepest.where / ntools, deepest.depth);
  // A force-controlled tool moves by what its force needs: it must hold the body from the start.
  for (int k = 0; k < ntools; ++k) {
    if (!tools_[k].Unknown()) continue;
    PetscInt local = 0, touching;
    for (PetscInt node : candidates_) local += contact_[node] && tool_of_[node] == k && mesh_->node_owned[node];
    PetscCall(MPIU_Allreduce(&local, &touching, 1, MPIU_INT, MPI_SUM, comm()));
    PetscCheck(touching > 0, comm(), PETSC_ERR_USER_INPUT,
               "the %s is force-controlled but touches no node of the body at its start (its force would move it "
               "by nothing); start it on the body",
               tools_[k].name.c_str());
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

} // namespace tf
