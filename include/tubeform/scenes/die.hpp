// The squaring scene's upper die from the options: the V-die of -die_angle,
// -die_r_apex, -die_u_close, -die_r_edge, or the profile of -die_profile
// (tool/profile.hpp), with the segments the shape metrics use.
#pragma once

#include "tubeform/io/options.hpp"
#include "tubeform/tool/tool.hpp"

namespace tf {

struct Die {
  Tool tool;
  int flank = 0; // the straight segment C/t is measured against
  int apex = -1; // the fillet before it, -1 if none
};

// Collective: the die, or an error on every rank (a profile is read on rank 0 and parsed on each).
PetscErrorCode BuildDie(MPI_Comm comm, const Options &opt, Die &die);

} // namespace tf
