// The error estimate's companions beside the run (docs/accuracy.md, "The error estimate"): where every rank would
// factor the run's whole matrix (a system of at most kDistributedDofs), a second rank buys the run little, and the
// companions cost no wall time if they run on it from the start. The run then takes the first half of the ranks
// and the companions, one after the other, the second half; their histories reach the run when its results are
// final (its companion callback), level after level (accuracy on demand). The run's ranks and results are those
// of a run on half the ranks, bit for bit.
#pragma once

#include <petscsys.h>

#include <functional>

#include "tubeform/driver/problem.hpp"
#include "tubeform/driver/refine.hpp"
#include "tubeform/io/options.hpp"

namespace tf {

// After each level of a run: what follows it (Refinement::follows false after the last).
using LevelHook = std::function<PetscErrorCode(const Refinement &next)>;
// Collective on comm: a run's levels (the first of `opt`, then the finer ones while one follows), each with the
// companion callback `companion`; `after` (if any) told what follows each.
using LevelRunner = std::function<PetscErrorCode(MPI_Comm comm, const Options &opt,
                                                 const Problem::CompanionRun &companion, const LevelHook &after)>;

// Whether a run of `opt` with its estimate on `size` ranks runs its companions beside it: 2 ranks or more, a
// generated mesh whose system every rank factors whole, and neither a checkpoint nor a restart (a checkpoint
// continues on the ranks that wrote it: the run keeps them all).
bool CompanionsBeside(const Options &opt, PetscMPIInt size);

// Collective on world: the run's levels by `levels` on the first half of the ranks, their companions on the
// second. The run's error comes back on every rank (the companions' ranks end with it); the companions' own
// failure reaches the run as "no error estimate", their stop signal as the run's.
PetscErrorCode RunBeside(MPI_Comm world, const Options &opt, const LevelRunner &levels);

} // namespace tf
