// Options nothing reads: every option given must be read by tubeform
// (ReadOptions), or by PETSc for the objects of this run (its start, the mesh,
// the solver), or be one PETSc reads later in every run (kReadLater:
// at a solve, when the result file opens, at the end). The solver's factor
// reads its options (MUMPS's -[redundant_]mat_mumps_*) only when it first
// factors: a stand-in is factored first (ReadFactorizationOptions), so that
// the verdict comes before any result is written.
#pragma once

#include <petscsys.h>

#include <string>
#include <vector>

#include "tubeform/io/options.hpp"

namespace tf {

// Collective, once the run is set up (its mesh and its solver for `ndofs` dofs)
// and before it writes anything: an option nothing reads is an error naming it,
// with the option it likely means (OptionHint: tubeform's and the PETSc options
// the docs name), or the factorization that would read it (-mat_mumps_* on a
// run that factors on every rank, -redundant_* on a distributed one). With
// opt.allow_unused: one warning line instead. The same verdict on every rank.
// `redundant`: the run's solver factors on every rank (its options prefix redundant_).
PetscErrorCode CheckOptionsLeft(MPI_Comm comm, const Options &opt, PetscInt ndofs, bool redundant);

// The options PETSc reads only after that check, in every run (with the dash).
const std::vector<std::string> &OptionsReadLater();

} // namespace tf
