// The registry of the upper die's motion checks (scenes/motion_checks.hpp): each kind's name and its check, defined in
// the kind's own file. A new motion that refuses combinations is its check's file (motion_check_*.cpp) and a line
// here, beside its kind's file and line in the motion registry (src/tool/motion_registry.cpp).
#include "tubeform/scenes/motion_checks.hpp"

namespace tf {

const MotionCheckKind &PathCheck();  // motion_check_path.cpp
const MotionCheckKind &ForceCheck(); // motion_check_force.cpp

namespace {
const MotionCheckKind &(*const kChecks[])() = {PathCheck, ForceCheck};
} // namespace

MotionCheck FindMotionCheck(const std::string &kind)
{
  for (const auto &k : kChecks)
    if (kind == k().name) return k().check;
  return nullptr;
}

PetscErrorCode CheckUpperMotion(MPI_Comm comm, const Options &opt, int pass)
{
  PetscFunctionBeginUser;
  if (const MotionCheck check = FindMotionCheck(ToolsOf(opt).passes[pass].dies.motion.kind))
    PetscCall(check(comm, opt, pass));
  PetscFunctionReturn(PETSC_SUCCESS);
}

} // namespace tf
