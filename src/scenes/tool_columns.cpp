// The registry of the tools' history columns (scenes/tool_columns.hpp): each tool's declaration, defined in its
// own file. A tool's new columns are its declaration there and a line here.
#include "tubeform/scenes/tool_columns.hpp"

#include "tubeform/scenes/die_columns.hpp"
#include "tubeform/scenes/hold.hpp"

namespace tf {

namespace {
const ToolColumns &(*const kTools[])() = {UpperDieColumns, LowerDieColumns, SideDieColumns, RotationHold::Columns,
                                          DiePathColumns};
} // namespace

int ToolColumns::First() const
{
  int first = 0;
  for (const auto &t : kTools) {
    if (&t() == this) return first_ = first;
    first += (int)t().columns().size();
  }
  PetscCheckAbort(false, PETSC_COMM_SELF, PETSC_ERR_PLIB, "history column %s: its tool is not in the registry",
                  columns_.front().name);
  return 0;
}

std::vector<ToolColumn> DeclaredToolColumns()
{
  std::vector<ToolColumn> all;
  for (const auto &t : kTools)
    for (const ToolColumns::Column &c : t().columns()) all.push_back({c.name, c.meaning, c.after, (int)all.size()});
  return all;
}

} // namespace tf
