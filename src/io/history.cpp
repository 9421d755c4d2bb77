#include "tubeform/io/history.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>

#include "tubeform/step/rmin.hpp"

namespace tf {

namespace {

// The columns of the first histories: the increment, its limiter and solve, the energies and self-checks, the
// tube's shape, the compromises taken, the contacts, the dynamics (the tools declare their own:
// scenes/tool_columns.hpp).
std::vector<HistoryColumn> FirstColumns()
{
  return {
    {"increment", &HistoryRow::increment, "increment number"},
    {"stroke", &HistoryRow::stroke, "tool stroke U (mm), or the scene's load parameter (docs/scenes.md)"},
    {"load", &HistoryRow::load, "punch load, full tube (N/mm), or the scene's conjugate force (docs/scenes.md)"},
    {"rmin", &HistoryRow::rmin, "r_min: the increment's fraction of its trial step"},
    {"limiter", &HistoryRow::limiter, "what limited the increment (code, see attribute limiter_names)"},
    {"limiter_where", &HistoryRow::limiter_where, "element or node (input numbering) of the limiter, -1 if none"},
    {"n_contact", &HistoryRow::n_contact, "contact nodes"},
    {"n_plastic", &HistoryRow::n_plastic, "plastic Gauss points"},
    {"friction_iters", &HistoryRow::friction_iters, "solves of the increment (friction iterations, re-solves)"},
    {"residual", &HistoryRow::residual, "out-of-balance force norm of the free dofs (N/mm)"},
    {"r_max", &HistoryRow::r_max, "largest out-of-balance force on a free dof (N/mm)"},
    {"q_avg", &HistoryRow::q_avg,
     "time-averaged nodal force: the mean magnitude of the cells' nodal forces, averaged over the increments "
     "(N/mm); equilibrium holds when r_max <= -equilibrium_tol x q_avg"},
    {"w_ext", &HistoryRow::w_ext,
     "work put into the model (N mm/mm): w_tool where the scene's load and stroke are "
     "work-conjugate, else the loads' and supports' work + friction dissipation"},
    {"w_int", &HistoryRow::w_int, "internal (stress) work"},
    {"w_plastic", &HistoryRow::w_plastic, "plastic dissipation"},
    {"w_friction", &HistoryRow::w_friction, "friction dissipation (from the contact slips)"},
    {"w_elastic", &HistoryRow::w_elastic, "stored elastic energy (from the stresses)"},
    {"energy_error", &HistoryRow::energy_error,
     "(w_ext - w_int - w_friction - w_kinetic - w_damped) / the largest |w_ext| so far: self-check (a)"},
    {"c_over_t", &HistoryRow::c_over_t, "collapse ratio C/t (loading: gap to the flank; unloading: to the chord)"},
    {"x_max", &HistoryRow::x_max, "C1: the outer half-extent across the press (its x; mm)"},
    {"y_max", &HistoryRow::y_max, "C2: the outer half-extent along the press (its y; mm)"},
    {"deviation_ratio", &HistoryRow::deviation_ratio, "C1 / C2 = x_max / y_max (C1 across the press, C2 along it)"},
    {"redo", &HistoryRow::redo, "re-solves of the increment for loading/unloading switches"},
    {"unsettled", &HistoryRow::unsettled, "trial steps so far taken with unsettled iterations (compromise)"},
    {"events_inside", &HistoryRow::events_inside,
     "re-solved steps so far taken past an event by more than -rmin_event_tol (compromise)"},
    {"inconsistent", &HistoryRow::inconsistent,
     "increments so far taken with Gauss points whose loading state disagrees with the solution (compromise)"},
    {"drift", &HistoryRow::drift, "largest |sbar / sigma_y - 1| of a plastic update (before any drift correction)"},
    {"r_corner_x", &HistoryRow::r_corner_x, "outer corner radius on the x axis (3-node estimate, mm; Inf: flat)", true},
    {"r_corner_y", &HistoryRow::r_corner_y, "outer corner radius on the y axis (3-node estimate, mm; Inf: flat)", true},
    {"penetration", &HistoryRow::penetration, "largest penetration of a node into a tool (mm)"},
    {"tension", &HistoryRow::tension,
     "largest tensile normal force of a contact node at the end of the step, before releases (N/mm)"},
    {"release_force", &HistoryRow::release_force, "largest compressive normal force dropped by a release (N/mm)"},
    {"contact_gap", &HistoryRow::contact_gap, "largest gap of a node in contact after the increment (mm)"},
    {"det_sign", &HistoryRow::det_sign,
     "sign of the determinant of the increment's last factored tangent (0: not computed; with "
     "-redundant_mat_mumps_icntl_33 1): a change of sign is a bifurcation or limit point"},
    {"fn_mismatch", &HistoryRow::fn_mismatch,
     "largest |stored normal force - the normal force the body's nodal forces need| of a contact node (N/mm)"},
    {"stage", &HistoryRow::stage,
     "0 loading, 1 unloading (or the scene's second stage), 2 the slide scene's push back"},
    {"w_kinetic", &HistoryRow::w_kinetic, "kinetic energy (-dynamics implicit; 0 quasi-static)"},
    {"w_inertia", &HistoryRow::w_inertia, "work of the inertia forces (trapezoidal)"},
    {"w_damped", &HistoryRow::w_damped, "energy damped by backward Euler: w_inertia - w_kinetic"},
    {"w_tool", &HistoryRow::w_tool, "work from the reported load and stroke (tool scenes: 1/2 integral of load dU)"},
    {"internal_error", &HistoryRow::internal_error,
     "(w_int - w_plastic - w_elastic) / the largest |w_int| so far: self-check (b)"},
    {"inertia", &HistoryRow::inertia,
     "1 if the increment was solved with inertia (-dynamics implicit, or auto once on)"},
    {"slip", &HistoryRow::slip, "slide scene: mean slip of the contact surface along the floor (mm)"},
    {"fn_sum", &HistoryRow::fn_sum, "sum of the contact nodes' normal forces (N/mm)"},
  };
}

// The springback's columns; 0 outside one.
std::vector<HistoryColumn> SpringbackColumns()
{
  return {
    {"release", &HistoryRow::release,
     "a springback (the release whose law -springback sets: the unloading of a tool scene, the bending scene's "
     "first reversal up to where its moment passes zero): 1 by the material's law, 2 elastic; 0 elsewhere"},
    {"release_yielded", &HistoryRow::release_yielded,
     "a springback: Gauss points that reached the yield surface since it began: that flowed in it "
     "(-springback material), or that it carried past the surface (-springback elastic); 0 outside one"},
    {"release_excess", &HistoryRow::release_excess,
     "-springback elastic: the largest sigma_eq / sigma_y - max(1, the point's own at the springback's start) over "
     "the Gauss points: how far past the yield surface the elastic springback carries a point (> 0: the material "
     "would have yielded there)"},
    {"release_dep", &HistoryRow::release_dep,
     "-springback material: the largest plastic strain a Gauss point took since the springback began"},
  };
}

} // namespace

std::vector<HistoryColumn> History::OwnColumns()
{
  // The springback's after the first: a reader of the CSV by position finds the first columns where they were.
  std::vector<HistoryColumn> all = FirstColumns(), later = SpringbackColumns();
  all.insert(all.end(), later.begin(), later.end());
  return all;
}

PetscErrorCode History::Declare(const std::vector<ToolColumn> &tools, MPI_Comm comm)
{
  std::vector<HistoryColumn> cols = OwnColumns();
  const auto find = [&cols](const char *name) {
    return std::find_if(cols.begin(), cols.end(),
                        [name](const HistoryColumn &c) { return !std::strcmp(c.name, name); });
  };
  std::vector<ToolColumn> left = tools;

  PetscFunctionBeginUser;
  for (size_t a = 0; a < tools.size(); ++a)
    for (size_t b = 0; b < a; ++b) // (two after one column: their order would be the declarations')
      PetscCheck(!tools[a].after || !tools[b].after || std::strcmp(tools[a].after, tools[b].after), comm,
                 PETSC_ERR_PLIB, "history columns %s and %s both follow %s", tools[b].name, tools[a].name,
                 tools[a].after);
  // Each after the column it names, once that one is in (a tool's column may follow another tool's).
  while (!left.empty()) {
    std::vector<ToolColumn> later;
    for (const ToolColumn &t : left) {
      PetscCheck(t.slot >= 0 && t.slot < kToolColumnRoom, comm, PETSC_ERR_PLIB,
                 "history column %s: slot %d outside the room of %d (kToolColumnRoom)", t.name, t.slot,
                 kToolColumnRoom);
      PetscCheck(find(t.name) == cols.end(), comm, PETSC_ERR_PLIB, "history column %s declared twice", t.name);
      const auto at = t.after ? find(t.after) : cols.end() - 1;
      if (at == cols.end())
        later.push_back(t);
      else
        cols.insert(at + 1, HistoryColumn{t.name, nullptr, t.meaning, false, t.slot});
    }
    PetscCheck(later.size() < left.size(), comm, PETSC_ERR_PLIB, "history column %s: no column %s to follow",
               later[0].name, later[0].after);
    left = later;
  }
  columns_ = cols;
  PetscFunctionReturn(PETSC_SUCCESS);
}

History::~History()
{
  if (csv_) std::fclose(csv_);
}

bool History::OpenCsv(const std::string &path, int rank)
{
  csv_path_ = path;
  if (rank != 0 || path.empty()) return true;
  csv_ = std::fopen((path + ".partial").c_str(), "w");
  if (!csv_) return false;
  const auto &cols = columns_;
  for (size_t c = 0; c < cols.size(); ++c) std::fprintf(csv_, "%s%s", c ? "," : "", cols[c].name);
  std::fprintf(csv_, "\n");
  Checked(std::fflush(csv_) == 0);
  return true;
}

void History::Checked(bool ok)
{
  if (!ok && !csv_errno_) csv_errno_ = errno ? errno : EIO; // the first failure's reason
}

void History::Append(const HistoryRow &row)
{
  rows_.push_back(row);
  if (!csv_ || csv_errno_) return; // (a file that failed is not written further: the run stops)
  const auto &cols = columns_;
  bool ok = true;
  for (size_t c = 0; c < cols.size(); ++c) {
    const double v = cols[c].Of(row);
    if (c) ok = ok && std::fputc(',', csv_) != EOF;
    if (cols[c].field == &HistoryRow::limiter)
      ok = ok && std::fprintf(csv_, "%s", LimiterName(static_cast<int>(v))) >= 0;
    else
      ok = ok && std::fprintf(csv_, "%.12g", v) >= 0;
  }
  ok = ok && std::fputc('\n', csv_) != EOF;
  // Flushed row by row: a long run can be watched (tail -f) while it goes, and
  // a full disk is seen at the row it cuts.
  Checked(ok && std::fflush(csv_) == 0);
}

PetscErrorCode History::Persist(Archive &ar, MPI_Comm comm)
{
  const auto &cols = columns_;
  std::vector<std::vector<double>> values(cols.size());

  PetscFunctionBeginUser;
  // Every member of a row is a column, or a tool's slot: a row written column by column comes back whole.
  PetscCheck(OwnColumns().size() * sizeof(double) + sizeof(HistoryRow::tool) == sizeof(HistoryRow), comm,
             PETSC_ERR_PLIB, "HistoryRow has members that are not history columns");
  ar.Group("/history");
  for (size_t c = 0; c < cols.size(); ++c) {
    for (const auto &row : rows_) values[c].push_back(cols[c].Of(row));
    PetscCall(ar.Values(cols[c].name, values[c]));
    PetscCheck(values[c].size() == values[0].size(), comm, PETSC_ERR_USER_INPUT,
               "%s: the history columns have different lengths", ar.path().c_str());
  }
  if (!ar.reading()) PetscFunctionReturn(PETSC_SUCCESS);
  std::vector<HistoryRow> rows(values[0].size());
  for (size_t c = 0; c < cols.size(); ++c)
    for (size_t r = 0; r < rows.size(); ++r) cols[c].Of(rows[r]) = values[c][r];
  rows_.clear();
  for (const auto &row : rows) Append(row); // and into the CSV file
  PetscFunctionReturn(PETSC_SUCCESS);
}

void History::DropCsv()
{
  if (csv_) std::fclose(csv_);
  csv_ = nullptr;
  if (!csv_path_.empty()) std::remove((csv_path_ + ".partial").c_str());
}

int History::CloseCsv()
{
  if (!csv_) return csv_errno_;
  Checked(std::fclose(csv_) == 0);
  csv_ = nullptr;
  return csv_errno_;
}

} // namespace tf
