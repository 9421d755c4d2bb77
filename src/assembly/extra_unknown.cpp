// The system's extra unknown (system.hpp, ExtraUnknown): a force-controlled
// tool's motion s. The increment is linear in s: the solution with the motion
// the caller guessed (u_0) plus s times the solution of a unit motion alone
// (u_1: its prescribed values, no loads) on the same factorization. The
// condition on the reactions is affine in them, so its misses m_0 (for u_0)
// and m_1 (for u_0 + u_1) give s = m_0 / (m_0 - m_1).
#include <cmath>
#include <cstdio>

#include <string>

#include "tubeform/assembly/solve_failure.hpp"
#include "tubeform/assembly/system.hpp"

namespace tf {

std::string ExtraUnknown::Stalled(double slope) const
{
  if (slope > 0) return "";
  char why[256];
  std::snprintf(why, sizeof(why),
                "its force does not grow as it advances (%g N/mm per mm of its stroke): the body's resistance under it "
                "has a maximum here (a limit point), or it touches nothing; force control cannot pass it (press by "
                "stroke)",
                slope);
  return why;
}

PetscErrorCode System::PrepareUnitMotion(bool &any)
{
  PetscFunctionBeginUser;
  any = extra_ != nullptr; // (set alike on every rank)
  if (!any) PetscFunctionReturn(PETSC_SUCCESS);
  if (!unit_) {
    PetscCall(VecDuplicate(rhs_, &unit_));
    PetscCall(VecDuplicate(rhs_, &unit_sol_));
  }
  // u_1 on the prescribed rows, then K u_1 with the friction rows coupled and before any row is zeroed: the
  // loads of the unit motion are -K u_1 on the free rows.
  PetscCall(VecZeroEntries(unit_));
  for (const auto &p : prescribed_) {
    if (!mesh_->node_owned[p.node] || p.unit == 0) continue;
    PetscInt local = mesh_->node_dof[p.node] + p.comp, global;
    PetscCall(ISLocalToGlobalMappingApply(ltog_, 1, &local, &global));
    PetscCall(VecSetValue(unit_, global, p.unit, INSERT_VALUES));
  }
  PetscCall(VecAssemblyBegin(unit_));
  PetscCall(VecAssemblyEnd(unit_));
  PetscCall(MatMult(k_, unit_, unit_sol_));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode System::CombineUnitMotion(const std::vector<PetscInt> &rows, const std::vector<PetscScalar> &b_rows,
                                         std::vector<double> &reactions)
{
  std::vector<PetscScalar> units(rows.size(), 0.0);
  double missing[2];
  PetscFunctionBeginUser;
  // The unit motion's right-hand side: -K u_1 on the free rows, u_1 on every prescribed one (0 but the tool's).
  // (Friction rows: their loads on l follow the tool's motion along l too; the friction iterations settle that
  // part, as they settle the friction force in the tool's force: ContactSet::Missing.)
  PetscCall(VecAXPBY(work_, -1.0, 0.0, unit_sol_));
  size_t k = 0;
  for (const auto &p : prescribed_)
    if (mesh_->node_owned[p.node]) units[k++] = p.unit;
  if (!rows.empty()) PetscCall(VecSetValues(work_, (PetscInt)rows.size(), rows.data(), units.data(), INSERT_VALUES));
  PetscCall(VecAssemblyBegin(work_));
  PetscCall(VecAssemblyEnd(work_));
  PetscCall(KSPSolve(ksp_, work_, unit_sol_));
  KSPConvergedReason reason;
  PetscCall(KSPGetConvergedReason(ksp_, &reason));
  if (reason < 0) {
    std::string why;
    PetscCall(DescribeSolveFailure(ksp_, why));
    SETERRQ(mesh_->comm, PETSC_ERR_NOT_CONVERGED, "%s (KSP, %s's unit motion: %s)", why.c_str(), extra_->Name().c_str(),
            KSPConvergedReasons[reason]);
  }
  // The misses of u_0 and u_0 + u_1.
  PetscCall(Reactions(sol_, rows, b_rows, reactions));
  PetscCall(extra_->Missing(missing[0]));
  PetscCall(VecAXPY(sol_, 1.0, unit_sol_));
  PetscCall(Reactions(sol_, rows, b_rows, reactions));
  PetscCall(extra_->Missing(missing[1]));
  const double slope = missing[0] - missing[1];
  // (The unit motion's force, by the condition's sign convention: a tool pushing harder as it advances.)
  const std::string stalled = extra_->Stalled(slope);
  PetscCheck(stalled.empty() && std::isfinite(missing[0] / slope), mesh_->comm, PETSC_ERR_NOT_CONVERGED, "%s: %s",
             extra_->Name().c_str(), stalled.empty() ? "no finite solution" : stalled.c_str());
  const double s = missing[0] / slope;
  PetscCall(VecAXPY(sol_, s - 1.0, unit_sol_));
  extra_->Moved(s);
  PetscFunctionReturn(PETSC_SUCCESS);
}

} // namespace tf
