// The solve of an assembled increment: loads into the node frames, the
// friction correction rows, the prescribed dofs, the factorization, the
// reactions. With an iterate (docs/theory.md, "Equilibrium iterations") the
// system is solved for the correction of that iterate, and an iterate
// already in balance is taken without factoring.
#include <algorithm>
#include <cmath>

#include "tubeform/assembly/linear_solver.hpp"
#include "tubeform/assembly/solve_failure.hpp"
#include "tubeform/assembly/system.hpp"
#include "tubeform/core/core.hpp"
#include "tubeform/core/log.hpp"

namespace tf {

PetscErrorCode System::LocalToNodeFrames(Vec v_local, Vec v_global, InsertMode mode)
{
  PetscScalar *f;
  PetscFunctionBeginUser;
  PetscCall(VecCopy(v_local, work_local_));
  PetscCall(VecGetArray(work_local_, &f));
  for (PetscInt n = 0; n < mesh_->num_nodes; ++n)
    if (has_frame_[n]) Rotate(n, f[mesh_->node_dof[n]], f[mesh_->node_dof[n] + 1], true);
  PetscCall(VecRestoreArray(work_local_, &f));
  if (mode == ADD_VALUES) PetscCall(VecZeroEntries(v_global));
  PetscCall(DMLocalToGlobal(mesh_->dm, work_local_, mode, v_global));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode System::AddCouplings()
{
  // Friction correction rows: row l += c row n (owned rows; same pattern).
  // All rows n are read first: the matrix is unassembled once values are added.
  struct RowAdd {
    PetscInt row;
    std::vector<PetscInt> cols;
    std::vector<PetscScalar> vals;
  };
  std::vector<RowAdd> adds;
  PetscInt lo;
  PetscScalar *b;
  PetscFunctionBeginUser;
  PetscCall(VecGetOwnershipRange(rhs_, &lo, nullptr));
  PetscCall(VecGetArray(rhs_, &b));
  for (const auto &cp : couplings_) {
    if (!mesh_->node_owned[cp.node] || cp.value == 0) continue;
    PetscInt local[2] = {mesh_->node_dof[cp.node], mesh_->node_dof[cp.node] + 1}, global[2], ncols;
    const PetscInt *cols;
    const PetscScalar *vals;
    PetscCall(ISLocalToGlobalMappingApply(ltog_, 2, local, global));
    PetscCall(MatGetRow(k_, global[1], &ncols, &cols, &vals));
    RowAdd add{global[0], std::vector<PetscInt>(cols, cols + ncols), std::vector<PetscScalar>(ncols)};
    for (PetscInt j = 0; j < ncols; ++j) add.vals[j] = cp.value * vals[j];
    PetscCall(MatRestoreRow(k_, global[1], &ncols, &cols, &vals));
    b[global[0] - lo] += cp.value * b[global[1] - lo];
    adds.push_back(std::move(add));
  }
  PetscCall(VecRestoreArray(rhs_, &b));
  for (const auto &add : adds)
    PetscCall(MatSetValues(k_, 1, &add.row, (PetscInt)add.cols.size(), add.cols.data(), add.vals.data(), ADD_VALUES));
  int any = !adds.empty(), anyg;
  PetscCallMPI(MPI_Allreduce(&any, &anyg, 1, MPI_INT, MPI_LOR, mesh_->comm));
  if (anyg) {
    PetscCall(MatAssemblyBegin(k_, MAT_FINAL_ASSEMBLY));
    PetscCall(MatAssemblyEnd(k_, MAT_FINAL_ASSEMBLY));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode System::Solve(Vec du, std::vector<double> &reactions)
{
  std::vector<PetscInt> rows;
  std::vector<PetscScalar> vals, b_rows;

  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(Log::apply_bc, 0, 0, 0, 0));
  PetscCall(MatAssemblyBegin(k_, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(k_, MAT_FINAL_ASSEMBLY));

  // Loads into the node frames, summed over ranks.
  PetscCall(LocalToNodeFrames(f_local_, rhs_, ADD_VALUES));
  PetscCall(PrescribedRows(rows, vals));

  // An iterate x (node frames): its body forces are in the loads as
  // f_ext - f_int(x) (Controller), so K_body x is added back and the loads
  // become those of the linear model about x. Its residual r = b - K x on the
  // free rows, after the friction correction rows (row l of a contact node
  // then reads the friction law's balance), is what the equilibrium criterion reads.
  solved_ = true, accepted_ = false;
  iterate_residual_ = 0;
  if (iterate_) {
    PetscCall(LocalToNodeFrames(iterate_, x_, INSERT_VALUES));
    PetscCall(MatMultAdd(kb_, x_, rhs_, rhs_));
  }
  PetscCall(AddCouplings());
  bool extra = false;
  PetscCall(PrepareUnitMotion(extra));
  PetscCall(KeepReactionRows(rows));
  b_rows.resize(rows.size());
  if (!rows.empty()) PetscCall(VecGetValues(rhs_, (PetscInt)rows.size(), rows.data(), b_rows.data()));
  if (iterate_) PetscCall(IterateResidual(rows, b_rows, extra, reactions));

  // In balance (or rejected): the iterate is the solution, no factorization.
  const bool taken = iterate_ && (iterate_residual_ <= accept_below_ || iterate_residual_ > reject_above_);
  if (taken) {
    solved_ = false;
    accepted_ = iterate_residual_ <= accept_below_;
    PetscCall(VecCopy(x_, sol_));
  } else
    PetscCall(ApplyPrescribed(rows, vals));
  PetscCall(PetscLogEventEnd(Log::apply_bc, 0, 0, 0, 0));
  if (!taken) PetscCall(FactorAndSolve(rows, b_rows, extra, reactions));

  // Reactions r = K(rows, :) du - f(rows), in the node frames.
  PetscCall(Reactions(sol_, rows, b_rows, reactions));

  // Back to the global frame, ghosts filled.
  PetscCall(DMGlobalToLocal(mesh_->dm, sol_, INSERT_VALUES, du));
  PetscScalar *d;
  PetscCall(VecGetArray(du, &d));
  for (PetscInt n = 0; n < mesh_->num_nodes; ++n)
    if (has_frame_[n]) Rotate(n, d[mesh_->node_dof[n]], d[mesh_->node_dof[n] + 1], false);
  PetscCall(VecRestoreArray(du, &d));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode System::PrescribedRows(std::vector<PetscInt> &rows, std::vector<PetscScalar> &vals)
{
  PetscFunctionBeginUser;
  for (const auto &p : prescribed_) {
    if (!mesh_->node_owned[p.node]) continue;
    PetscInt local = mesh_->node_dof[p.node] + p.comp, global;
    PetscCall(ISLocalToGlobalMappingApply(ltog_, 1, &local, &global));
    rows.push_back(global);
    vals.push_back(p.value);
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode System::KeepReactionRows(const std::vector<PetscInt> &rows)
{
  IS isrow, iscol;
  PetscInt lo, hi;

  PetscFunctionBeginUser;
  int changed = rows != last_rows_, any_changed;
  PetscCallMPI(MPI_Allreduce(&changed, &any_changed, 1, MPI_INT, MPI_LOR, mesh_->comm));
  if (any_changed) PetscCall(MatDestroy(&reaction_rows_));
  PetscCall(MatGetOwnershipRange(k_, &lo, &hi));
  PetscCall(ISCreateGeneral(mesh_->comm, (PetscInt)rows.size(), rows.data(), PETSC_COPY_VALUES, &isrow));
  PetscCall(ISCreateStride(mesh_->comm, hi - lo, lo, 1, &iscol));
  PetscCall(
    MatCreateSubMatrix(k_, isrow, iscol, reaction_rows_ ? MAT_REUSE_MATRIX : MAT_INITIAL_MATRIX, &reaction_rows_));
  PetscCall(ISDestroy(&isrow));
  PetscCall(ISDestroy(&iscol));
  last_rows_ = rows;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode System::IterateResidual(const std::vector<PetscInt> &rows, const std::vector<PetscScalar> &b_rows,
                                       bool extra, std::vector<double> &reactions)
{
  const PetscScalar *r;
  PetscInt lo, n;

  PetscFunctionBeginUser;
  PetscCall(MatGetOwnershipRange(k_, &lo, nullptr));
  PetscCall(MatMult(k_, x_, work_));
  PetscCall(VecAYPX(work_, -1.0, rhs_)); // b - K x
  PetscCall(VecGetArrayRead(work_, &r));
  PetscCall(VecGetLocalSize(work_, &n));
  std::vector<char> fixed(n, 0);
  for (PetscInt row : rows) fixed[row - lo] = 1;
  double local = 0;
  for (PetscInt i = 0; i < n; ++i)
    if (!fixed[i]) local = std::max(local, std::abs(PetscRealPart(r[i])));
  PetscCall(VecRestoreArrayRead(work_, &r));
  PetscCallMPI(MPI_Allreduce(&local, &iterate_residual_, 1, MPI_DOUBLE, MPI_MAX, mesh_->comm));
  if (extra) {
    // The extra unknown's condition at the iterate (its reactions: the forces the body needs there).
    double missing;
    PetscCall(Reactions(x_, rows, b_rows, reactions));
    PetscCall(extra_->Missing(missing));
    iterate_residual_ = std::max(iterate_residual_, std::abs(missing));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode System::ApplyPrescribed(const std::vector<PetscInt> &rows, std::vector<PetscScalar> &vals)
{
  PetscFunctionBeginUser;
  if (iterate_) {
    // The correction d of the iterate: K d = b - K x (coupled rows as K),
    // its prescribed values what the iterate still lacks.
    std::vector<PetscScalar> x_rows(rows.size());
    if (!rows.empty()) PetscCall(VecGetValues(x_, (PetscInt)rows.size(), rows.data(), x_rows.data()));
    for (size_t k = 0; k < rows.size(); ++k) vals[k] -= x_rows[k];
    PetscCall(VecCopy(work_, rhs_));
  }
  PetscCall(VecZeroEntries(fixed_));
  if (!rows.empty()) PetscCall(VecSetValues(fixed_, (PetscInt)rows.size(), rows.data(), vals.data(), INSERT_VALUES));
  PetscCall(VecAssemblyBegin(fixed_));
  PetscCall(VecAssemblyEnd(fixed_));
  PetscCall(MatZeroRowsColumns(k_, (PetscInt)rows.size(), rows.data(), 1.0, fixed_, rhs_));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode System::FactorAndSolve(const std::vector<PetscInt> &rows, const std::vector<PetscScalar> &b_rows,
                                      bool extra, std::vector<double> &reactions)
{
  KSPConvergedReason reason;

  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(Log::solve, 0, 0, 0, 0));
  PetscCall(KSPSetOperators(ksp_, k_, k_));
  const PetscErrorCode solved = KSPSolve(ksp_, rhs_, sol_);
  if (solved) {
    std::string why;
    PetscCall(DescribeSolveError(ksp_, solved, why));
    PetscCheck(why.empty(), mesh_->comm, PETSC_ERR_NOT_CONVERGED, "%s", why.c_str());
    PetscCall(solved);
  }
  PetscCall(KSPGetConvergedReason(ksp_, &reason));
  if (reason < 0) {
    std::string why;
    PetscCall(DescribeSolveFailure(ksp_, why));
    SETERRQ(mesh_->comm, PETSC_ERR_NOT_CONVERGED, "%s (KSP: %s)", why.c_str(), KSPConvergedReasons[reason]);
  }
  if (iterate_) PetscCall(VecAXPY(sol_, 1.0, x_));
  if (extra) PetscCall(CombineUnitMotion(rows, b_rows, reactions));
  ++nsolves_;
  PetscCall(PetscLogEventEnd(Log::solve, 0, 0, 0, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode System::Reactions(Vec sol, const std::vector<PetscInt> &rows, const std::vector<PetscScalar> &b_rows,
                                 std::vector<double> &reactions)
{
  Vec r;
  const PetscScalar *ra;
  PetscFunctionBeginUser;
  PetscCall(MatCreateVecs(reaction_rows_, nullptr, &r));
  PetscCall(MatMult(reaction_rows_, sol, r));
  PetscCall(VecGetArrayRead(r, &ra));
  reactions.assign(prescribed_.size(), 0.0);
  PetscCall(VecZeroEntries(reactions_global_));
  size_t k = 0;
  for (size_t q = 0; q < prescribed_.size(); ++q)
    if (mesh_->node_owned[prescribed_[q].node]) {
      reactions[q] = PetscRealPart(ra[k]) - PetscRealPart(b_rows[k]);
      PetscCall(VecSetValue(reactions_global_, rows[k], reactions[q], INSERT_VALUES));
      ++k;
    }
  PetscCall(VecRestoreArrayRead(r, &ra));
  PetscCall(VecDestroy(&r));
  PetscCall(VecAssemblyBegin(reactions_global_));
  PetscCall(VecAssemblyEnd(reactions_global_));
  PetscCall(DMGlobalToLocal(mesh_->dm, reactions_global_, INSERT_VALUES, reactions_local_));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode System::DeterminantSign(int &sign) const
{
  PetscFunctionBeginUser;
  PetscCall(tf::DeterminantSign(ksp_, sign));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode System::FreeNorms(Vec f_local, double &norm2, double &norm_max)
{
  PetscScalar *f;
  PetscReal nrm;

  PetscFunctionBeginUser;
  PetscCall(VecCopy(f_local, f_local_));
  PetscCall(VecGetArray(f_local_, &f));
  for (PetscInt n = 0; n < mesh_->num_nodes; ++n)
    if (has_frame_[n]) Rotate(n, f[mesh_->node_dof[n]], f[mesh_->node_dof[n] + 1], true);
  for (const auto &p : prescribed_) f[mesh_->node_dof[p.node] + p.comp] = 0;
  PetscCall(VecRestoreArray(f_local_, &f));
  PetscCall(VecZeroEntries(rhs_));
  PetscCall(DMLocalToGlobal(mesh_->dm, f_local_, ADD_VALUES, rhs_));
  // A prescribed dof zeroed on one rank may carry a share from another: zero the owned rows too.
  PetscInt lo;
  PetscCall(VecGetOwnershipRange(rhs_, &lo, nullptr));
  PetscCall(VecGetArray(rhs_, &f));
  for (const auto &p : prescribed_)
    if (mesh_->node_owned[p.node]) {
      PetscInt local = mesh_->node_dof[p.node] + p.comp, global;
      PetscCall(ISLocalToGlobalMappingApply(ltog_, 1, &local, &global));
      f[global - lo] = 0;
    }
  PetscCall(VecRestoreArray(rhs_, &f));
  PetscCall(VecNorm(rhs_, NORM_2, &nrm));
  norm2 = nrm;
  PetscCall(VecNorm(rhs_, NORM_INFINITY, &nrm));
  norm_max = nrm;
  PetscFunctionReturn(PETSC_SUCCESS);
}

} // namespace tf
