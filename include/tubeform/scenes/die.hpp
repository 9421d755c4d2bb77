// The squaring scene's dies from the options: the upper one (the V-die of
// -die_angle, -die_r_apex, -die_u_close, -die_r_edge, or the profile of
// -die_profile, tool/profile.hpp) with the segments the shape metrics use,
// and the lower one of -lower_die.
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

// The flat lower die reaches this far past the axis and past the tube's outer radius (fractions of Ro): a
// tube squared on it widens by less than half its radius.
constexpr double kFloorOverhang = 0.1, kFloorReach = 0.6;
// Collective: the lower die of -lower_die (the upper die's mirror, a flat floor at y = floor_y, or a profile
// file drawn as an upper die and mirrored below the tube) with its motion of -lower_die_motion.
PetscErrorCode BuildLowerDie(MPI_Comm comm, const Options &opt, const Tool &upper, double floor_y, Tool &lower);

} // namespace tf
