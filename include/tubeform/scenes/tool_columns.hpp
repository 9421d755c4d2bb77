// The history's columns of the tools and supports (docs/output.md, "History columns"): each tool declares its own
// (ToolColumns: each column's name, meaning and the column it follows) beside the code that fills them, and the
// registry (src/scenes/tool_columns.cpp) lists the declarations once, giving each column its slot in a row. The
// driver hands them to the history (History::Declare), which writes every declared column in every scene's rows,
// 0 where a tool does not act: a file has the same columns whatever the run.
#pragma once

#include <vector>

#include "tubeform/io/history.hpp"

namespace tf {

class ToolColumns {
public:
  struct Column {
    const char *name;
    const char *meaning;
    const char *after = nullptr; // the column it follows in the history (nullptr: after the last)
  };
  explicit ToolColumns(std::vector<Column> columns) : columns_(std::move(columns)) {}
  // The row's value of its k-th column (in the order declared).
  double &operator()(HistoryRow &row, int k) const { return row.tool[Slot(k)]; }
  double operator()(const HistoryRow &row, int k) const { return row.tool[Slot(k)]; }
  const std::vector<Column> &columns() const { return columns_; }

private:
  std::vector<Column> columns_;
  mutable int first_ = -1; // its first column's slot, found in the registry at the first access (it never moves)
  // Its k-th column's slot: its first + k; a declaration missing from the registry aborts.
  int Slot(int k) const { return (first_ < 0 ? First() : first_) + k; }
  int First() const;
};

// The registry's declared columns, each with its slot (History::Declare).
std::vector<ToolColumn> DeclaredToolColumns();

} // namespace tf
