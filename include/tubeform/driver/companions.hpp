// One run of a case, as tubeform's main runs it, and the error estimate's
// companion runs (driver/answer.hpp, Companions): on 2 ranks or more the two
// companions run side by side, each on its half of the ranks.
#pragma once

#include <petscsys.h>

#include <string>
#include <type_traits>
#include <vector>

#include "tubeform/driver/answer.hpp"
#include "tubeform/driver/problem.hpp"
#include "tubeform/driver/refine.hpp"
#include "tubeform/io/options.hpp"

namespace tf {

// Collective on comm: one run of `opt` (quiet: a companion's, whose options nothing reads are not checked); rows:
// its history, refinement: what follows it (accuracy on demand), when it ends. Its error comes back with the
// message it raised, taken before the run's clean-up (a result file closed on a full disk) can raise errors of
// its own whose messages would replace it.
PetscErrorCode RunOnce(MPI_Comm comm, const Options &opt, bool quiet, const Problem::CompanionRun &companion,
                       std::vector<HistoryRow> *rows, Refinement *refinement = nullptr);

// Collective on comm: the estimate's two companions of the run that ran with `ran` (its element and friction
// regularization fixed), once its results are final: `mesh` on half the cells through the wall and around at the
// run's increment limits (a mesh file is kept: it would be the run itself, and is not run), `steps` on the cells
// of `mesh` at twice those limits. Their histories in `out` on every rank. With `ran.accuracy.steps_only` (a level
// that the next takes as its mesh companion, driver/refine.hpp) only `steps`, on the cells of `ran` itself: the
// increments' part read where the cells are the finest the estimate has, not on a quarter of the coarsest level's.
// Their line ("companion runs for the error estimate: ...") is printed, or with `line` returned in it.
PetscErrorCode RunCompanions(MPI_Comm comm, const Options &ran, Companions &out, std::string *line = nullptr);

// A companion's options: `ran`'s, writing no file, quiet, estimating nothing.
Options CompanionQuiet(const Options &ran);

// A history as doubles (what MPI sends of it).
static_assert(std::is_trivially_copyable_v<HistoryRow> && sizeof(HistoryRow) % sizeof(double) == 0,
              "a history row travels as doubles");
inline int RowDoubles(const std::vector<HistoryRow> &rows)
{
  return (int)(rows.size() * sizeof(HistoryRow) / sizeof(double));
}
// Collective on comm: the rows of rank `root` on every rank.
PetscErrorCode BroadcastRows(MPI_Comm comm, int root, std::vector<HistoryRow> &rows);

} // namespace tf
