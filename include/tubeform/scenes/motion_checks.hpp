// What an upper die's motion cannot do with the press's other options (docs/motions.md): each kind of the motion
// registry (tool/motion.hpp) that refuses some presses says so in its own file (MotionKind::press_check,
// src/tool/motion_*.cpp), reading the press as a MotionPress; the tool scenes' options' checks describe each pass's
// press to it here. Its own numbers are its reader's.
#pragma once

#include <petscsys.h>

#include "tubeform/scenes/tool_scene.hpp"

namespace tf {

// Pass `pass`'s (0 the first) press as its upper die's motion kind reads it (MotionPress).
MotionPress PressOfPass(const Options &opt, int pass);
// Collective: pass `pass`'s upper die's motion checked by its kind in its press (CheckMotionInPress), refused in one
// line naming the option and what goes with it; a kind with no press check refuses nothing here.
PetscErrorCode CheckUpperMotion(MPI_Comm comm, const Options &opt, int pass);
// Collective, in a press (a scene without tools leaves their names to the check of options only other scenes read,
// or lets them go with -allow_unused): an option of another of a die's motion words' kinds, given, refused in one
// line naming it, the word it belongs to and the word chosen (the die's stray, kept while its block was read:
// die_motion_options.cpp): every pass's lower die, the first pass's upper die, every pass's side dies, the later
// passes' upper dies, in the order their blocks are read.
PetscErrorCode CheckMotionStrays(MPI_Comm comm, const Options &opt);

} // namespace tf
