#include "tubeform/assembly/system.hpp"

#include <cmath>

#include "tubeform/assembly/linear_solver.hpp"
#include "tubeform/assembly/solve_failure.hpp"
#include "tubeform/core/core.hpp"
#include "tubeform/core/log.hpp"

namespace tf {

System::~System()
{
  (void)MatDestroy(&k_);
  (void)MatDestroy(&kb_);
  (void)MatDestroy(&reaction_rows_);
  (void)VecDestroy(&rhs_);
  (void)VecDestroy(&sol_);
  (void)VecDestroy(&fixed_);
  (void)VecDestroy(&diag_);
  (void)VecDestroy(&f_local_);
  (void)VecDestroy(&x_);
  (void)VecDestroy(&work_);
  (void)VecDestroy(&work_local_);
  (void)VecDestroy(&unit_);
  (void)VecDestroy(&unit_sol_);
  (void)VecDestroy(&reactions_local_);
  (void)VecDestroy(&reactions_global_);
  (void)KSPDestroy(&ksp_);
}

PetscErrorCode System::Setup(const Mesh &mesh, Factorization factorization)
{
  PetscFunctionBeginUser;
  mesh_ = &mesh;
  PetscCall(DMCreateMatrix(mesh.dm, &k_));
  PetscCall(MatSetOption(k_, MAT_KEEP_NONZERO_PATTERN, PETSC_TRUE));
  PetscCall(MatSetOption(k_, MAT_NEW_NONZERO_ALLOCATION_ERR, PETSC_TRUE));
  PetscCall(MatGetLocalToGlobalMapping(k_, &ltog_, nullptr));
  PetscCall(DMCreateMatrix(mesh.dm, &kb_));
  PetscCall(MatSetOption(kb_, MAT_NEW_NONZERO_ALLOCATION_ERR, PETSC_TRUE));
  target_ = k_;
  PetscCall(DMCreateGlobalVector(mesh.dm, &rhs_));
  PetscCall(VecDuplicate(rhs_, &sol_));
  PetscCall(VecDuplicate(rhs_, &fixed_));
  PetscCall(VecDuplicate(rhs_, &diag_));
  PetscCall(DMCreateLocalVector(mesh.dm, &f_local_));
  PetscCall(DMCreateLocalVector(mesh.dm, &work_local_));
  PetscCall(VecDuplicate(rhs_, &x_));
  PetscCall(VecDuplicate(rhs_, &work_));
  PetscCall(DMCreateLocalVector(mesh.dm, &reactions_local_));
  PetscCall(DMCreateGlobalVector(mesh.dm, &reactions_global_));
  PetscCall(PetscObjectSetName((PetscObject)sol_, "displacement"));

  // LU, redundant or distributed (MUMPS) by the size of the system; options may override.
  PetscCall(VecGetSize(rhs_, &ndofs_));
  PetscCall(KSPCreate(mesh.comm, &ksp_));
  PetscCall(SetupLinearSolver(ksp_, ndofs_, factorization, solver_, redundant_));

  has_frame_.assign(mesh.num_nodes, 0);
  cos_.assign(mesh.num_nodes, 1.0);
  sin_.assign(mesh.num_nodes, 0.0);
  PetscFunctionReturn(PETSC_SUCCESS);
}

void System::SetFrame(PetscInt node, double angle)
{
  const double c = std::cos(angle), s = std::sin(angle);
  if (!has_frame_[node] || c != cos_[node] || s != sin_[node]) kb_valid_ = false;
  has_frame_[node] = 1;
  cos_[node] = c;
  sin_[node] = s;
}

bool System::PrescribeAlong(PetscInt node, double dx, double dy, double value, double unit)
{
  const double dl = cos_[node] * dx + sin_[node] * dy, dn = -sin_[node] * dx + cos_[node] * dy;
  if (std::abs(std::abs(dl) - 1) < kAxisTol)
    Prescribe(node, 0, dl * value, dl * unit);
  else if (std::abs(std::abs(dn) - 1) < kAxisTol)
    Prescribe(node, 1, dn * value, dn * unit);
  else
    return false;
  return true;
}

void System::ClearFrames()
{
  kb_valid_ = false;
  std::fill(has_frame_.begin(), has_frame_.end(), 0);
  std::fill(cos_.begin(), cos_.end(), 1.0);
  std::fill(sin_.begin(), sin_.end(), 0.0);
}

void System::Rotate(PetscInt node, double &a, double &b, bool to_local) const
{
  // Columns of R are l = (c, s) and n = (-s, c); local = R^T global.
  const double c = cos_[node], s = to_local ? sin_[node] : -sin_[node];
  const double x = a, y = b;
  a = c * x + s * y;
  b = -s * x + c * y;
}

Vec System::CreateLocalVector() const
{
  Vec v = nullptr;
  (void)DMCreateLocalVector(mesh_->dm, &v);
  return v;
}

PetscErrorCode System::Begin()
{
  PetscFunctionBeginUser;
  PetscCall(MatZeroEntries(k_));
  PetscCall(VecZeroEntries(f_local_));
  prescribed_.clear();
  couplings_.clear();
  extra_ = nullptr;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode System::BeginBody(bool &rebuild)
{
  int mine = rebuild || !kb_valid_, any;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Allreduce(&mine, &any, 1, MPI_INT, MPI_LOR, mesh_->comm));
  rebuild = any;
  if (rebuild) PetscCall(MatZeroEntries(kb_));
  target_ = kb_;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode System::EndBody()
{
  PetscFunctionBeginUser;
  target_ = k_;
  PetscCall(MatAssemblyBegin(kb_, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(kb_, MAT_FINAL_ASSEMBLY));
  kb_valid_ = true;
  PetscCall(MatCopy(kb_, k_, SAME_NONZERO_PATTERN));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode System::AddDiagonal(Vec d, double scale)
{
  PetscFunctionBeginUser;
  // K is assembled here (EndBody's copy); the diagonal goes in directly.
  PetscCall(VecAXPBY(diag_, scale, 0.0, d));
  PetscCall(MatDiagonalSet(k_, diag_, ADD_VALUES));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode System::AddElement(PetscInt cell, const fe::ElemMat &ke)
{
  PetscFunctionBeginUser;
  PetscCall(AddBlock(&mesh_->cell_nodes[4 * cell], fe::kNodes, &ke[0][0]));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode System::AddBlock(const PetscInt *nodes, int nn, const double *k_in)
{
  constexpr int kMax = 2 * 9; // up to 9-node blocks
  PetscInt idx[kMax];
  PetscScalar k[kMax * kMax];
  const int nd = 2 * nn;

  PetscFunctionBeginUser;
  PetscCheck(nn <= 9, PETSC_COMM_SELF, PETSC_ERR_ARG_SIZ, "AddBlock supports at most 9 nodes");
  for (int i = 0; i < nd * nd; ++i) k[i] = k_in[i];
  // K' = T^T K T for nodes with a rotated frame: rotate their rows, then columns.
  for (int a = 0; a < nn; ++a) {
    if (!has_frame_[nodes[a]]) continue;
    for (int j = 0; j < nd; ++j) Rotate(nodes[a], k[(2 * a) * nd + j], k[(2 * a + 1) * nd + j], true);
    for (int i = 0; i < nd; ++i) Rotate(nodes[a], k[i * nd + 2 * a], k[i * nd + 2 * a + 1], true);
  }
  for (int a = 0; a < nn; ++a) {
    idx[2 * a] = mesh_->node_dof[nodes[a]];
    idx[2 * a + 1] = mesh_->node_dof[nodes[a]] + 1;
  }
  PetscCall(MatSetValuesLocal(target_, nd, idx, nd, idx, k, ADD_VALUES));
  PetscFunctionReturn(PETSC_SUCCESS);
}

void System::AddFrameForce(PetscInt node, double fl, double fn)
{
  Rotate(node, fl, fn, false);
  AddForce(node, fl, fn);
}

PetscErrorCode System::AddFrameStiffness(PetscInt node, double k_ll)
{
  PetscFunctionBeginUser;
  const double c = cos_[node], s = sin_[node];
  const double k[4] = {k_ll * c * c, k_ll * c * s, k_ll * c * s, k_ll * s * s};
  PetscCall(AddBlock(&node, 1, k));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode System::AddFreeForce(Vec f)
{
  const PetscScalar *a;
  std::vector<char> fixed(2 * mesh_->num_nodes, 0);
  PetscFunctionBeginUser;
  for (const auto &p : prescribed_) fixed[2 * p.node + p.comp] = 1;
  PetscCall(VecGetArrayRead(f, &a));
  for (PetscInt n = 0; n < mesh_->num_nodes; ++n) {
    double v[2] = {PetscRealPart(a[mesh_->node_dof[n]]), PetscRealPart(a[mesh_->node_dof[n] + 1])};
    if (has_frame_[n]) Rotate(n, v[0], v[1], true);
    for (int k = 0; k < 2; ++k)
      if (fixed[2 * n + k]) v[k] = 0;
    AddFrameForce(n, v[0], v[1]);
  }
  PetscCall(VecRestoreArrayRead(f, &a));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode System::AddForces(Vec f, double scale)
{
  PetscScalar *a, *b;
  PetscFunctionBeginUser;
  PetscCall(VecGetArrayRead(f, (const PetscScalar **)&a));
  PetscCall(VecGetArray(f_local_, &b));
  for (PetscInt k = 0; k < 2 * mesh_->num_nodes; ++k) b[k] += scale * a[k];
  PetscCall(VecRestoreArray(f_local_, &b));
  PetscCall(VecRestoreArrayRead(f, (const PetscScalar **)&a));
  PetscFunctionReturn(PETSC_SUCCESS);
}

void System::AddForce(PetscInt node, double fx, double fy)
{
  PetscScalar *f;
  (void)VecGetArray(f_local_, &f);
  f[mesh_->node_dof[node]] += fx;
  f[mesh_->node_dof[node] + 1] += fy;
  (void)VecRestoreArray(f_local_, &f);
}

PetscErrorCode System::ExternalWork(Vec f_ext, Vec f_int, Vec du, double &work)
{
  const PetscScalar *fe, *fi = nullptr, *d;
  std::vector<char> fixed(2 * mesh_->num_nodes, 0);
  double local = 0;

  PetscFunctionBeginUser;
  for (const auto &p : prescribed_) fixed[2 * p.node + p.comp] = 1;
  PetscCall(VecGetArrayRead(f_ext, &fe));
  if (f_int) PetscCall(VecGetArrayRead(f_int, &fi));
  PetscCall(VecGetArrayRead(du, &d));
  for (PetscInt n = 0; n < mesh_->num_nodes; ++n) {
    const PetscInt o = mesh_->node_dof[n];
    double e[2] = {PetscRealPart(fe[o]), PetscRealPart(fe[o + 1])},
           i[2] = {fi ? PetscRealPart(fi[o]) : 0.0, fi ? PetscRealPart(fi[o + 1]) : 0.0},
           u[2] = {PetscRealPart(d[o]), PetscRealPart(d[o + 1])};
    if (has_frame_[n]) {
      Rotate(n, e[0], e[1], true);
      Rotate(n, i[0], i[1], true);
      Rotate(n, u[0], u[1], true);
    }
    for (int k = 0; k < 2; ++k) local += (fixed[2 * n + k] ? i[k] : e[k]) * u[k];
  }
  PetscCall(VecRestoreArrayRead(du, &d));
  if (f_int) PetscCall(VecRestoreArrayRead(f_int, &fi));
  PetscCall(VecRestoreArrayRead(f_ext, &fe));
  PetscCall(MPIU_Allreduce(&local, &work, 1, MPIU_REAL, MPIU_SUM, mesh_->comm));
  PetscFunctionReturn(PETSC_SUCCESS);
}

} // namespace tf
