// What an upper die's motion cannot do with the other options (docs/dies.md): each kind of the motion registry
// (tool/motion.hpp) that refuses combinations has its check in its own file (src/scenes/options/motion_check_*.cpp: it
// needs the options, which the tool layer cannot see), named by the kind's name in the checks' registry
// (src/scenes/options/motion_checks.cpp). The options' checks ask the registry for each pass's kind (CheckUpperMotion);
// a kind with no entry refuses nothing here. Its own numbers are its reader's (tool/motion_*.cpp).
#pragma once

#include <petscsys.h>

#include "tubeform/scenes/tool_scene.hpp"

namespace tf {

// A kind's check (collective): pass `pass`'s (0 the first) upper die moving by the kind, refused in one line naming
// the option and what goes with it where it does not go with the other options.
using MotionCheck = PetscErrorCode (*)(MPI_Comm comm, const Options &opt, int pass);
// A kind's entry in the checks' registry: the kind's name (MotionKind::name) and its check. Each kind's file defines
// its own (PathCheck(), ForceCheck(); the registry lists them).
struct MotionCheckKind {
  const char *name;
  MotionCheck check;
};

// The check of the kind named `kind`, or nullptr (it refuses nothing).
MotionCheck FindMotionCheck(const std::string &kind);
// Collective: pass `pass`'s upper die's motion checked by its kind's check (DieSet::motion; none: nothing refused).
PetscErrorCode CheckUpperMotion(MPI_Comm comm, const Options &opt, int pass);

} // namespace tf
