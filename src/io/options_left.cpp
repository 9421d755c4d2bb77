#include "tubeform/io/options_left.hpp"

#include <algorithm>
#include <cctype>
#include <cstdio>

#include "tubeform/assembly/linear_solver.hpp"
#include "tubeform/core/core.hpp"
#include "tubeform/core/option_reader.hpp"

namespace tf {

namespace {

// An option given: its name (with the dash) and its value ("" for a flag).
struct Given {
  std::string name, value;
};

std::string Lower(std::string s)
{
  for (char &c : s) c = (char)std::tolower((unsigned char)c);
  return s;
}

std::string Shown(const Given &g) { return g.value.empty() ? g.name : g.name + " " + g.value; }

// PETSc's options the docs name (README.md, docs/options.md, docs/guide.md): the hints for a misspelling of one.
const std::vector<KnownOption> &PetscNames()
{
  static const std::vector<KnownOption> names = [] {
    std::vector<KnownOption> v;
    for (const char *n : {"-ksp_type", "-ksp_view", "-ksp_monitor", "-pc_type", "-pc_factor_mat_solver_type",
                          "-redundant_pc_factor_mat_solver_type", "-log_view", "-malloc_debug", "-malloc_dump",
                          "-memory_view", "-info", "-help", "-options_file"})
      v.push_back({n, "", "", ""});
    for (const auto &n : OptionsReadLater()) v.push_back({n, "", "", ""});
    return v;
  }();
  return names;
}

// Collective: the options no rank has read (rank 0's unread ones, kept where every rank left them unread).
PetscErrorCode Unread(MPI_Comm comm, std::vector<Given> &left)
{
  PetscMPIInt rank;
  std::string packed; // name \0 value \0 ...
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (rank == 0) {
    PetscInt n;
    char **names, **values;
    PetscCall(PetscOptionsLeftGet(nullptr, &n, &names, &values));
    for (PetscInt k = 0; k < n; ++k) packed += std::string("-") + names[k] + '\0' + (values[k] ? values[k] : "") + '\0';
    PetscCall(PetscOptionsLeftRestore(nullptr, &n, &names, &values));
  }
  int bytes = (int)packed.size();
  PetscCallMPI(MPI_Bcast(&bytes, 1, MPI_INT, 0, comm));
  packed.resize(bytes);
  PetscCallMPI(MPI_Bcast(packed.data(), bytes, MPI_CHAR, 0, comm));
  std::vector<Given> all;
  for (size_t at = 0; at < packed.size();) {
    Given g;
    g.name = packed.c_str() + at, at += g.name.size() + 1;
    g.value = packed.c_str() + at, at += g.value.size() + 1;
    all.push_back(g);
  }
  std::vector<int> unread(all.size());
  for (size_t k = 0; k < all.size(); ++k) {
    PetscBool used;
    PetscCall(PetscOptionsUsed(nullptr, all[k].name.c_str() + 1, &used)); // (the name without its dash)
    unread[k] = !used;
  }
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, unread.data(), (int)unread.size(), MPI_INT, MPI_MIN, comm));
  left.clear();
  for (size_t k = 0; k < all.size(); ++k)
    if (unread[k]) left.push_back(all[k]);
  PetscFunctionReturn(PETSC_SUCCESS);
}

// The message for an option `g` of the factorization a run does not use: which it uses, and the name `g` takes there.
std::string OtherPath(const Given &g, PetscMPIInt size, PetscInt ndofs, bool redundant)
{
  const std::string prefix = "-redundant_";
  const std::string name = Lower(g.name);
  const bool redundant_name = name.compare(0, prefix.size(), prefix) == 0;
  char line[512];
  if (!redundant)
    snprintf(line, sizeof line,
             "%s: acts only on the factorization of the whole matrix on every rank (up to %d dofs, or on one rank); "
             "this run (%d dofs, %d ranks) factors it distributed%s%s",
             Shown(g).c_str(), (int)kDistributedDofs, (int)ndofs, (int)size, redundant_name ? ": give -" : "",
             redundant_name ? name.substr(prefix.size()).c_str() : "");
  else
    snprintf(line, sizeof line,
             "%s: acts only on the distributed factorization (MUMPS over several ranks above %d dofs, or -pc_type "
             "lu); this run (%d dofs, %d rank%s) factors the whole matrix on every rank, where the options carry the "
             "prefix redundant_%s%s",
             Shown(g).c_str(), (int)kDistributedDofs, (int)ndofs, (int)size, size > 1 ? "s" : "",
             redundant_name ? "" : ": give ", redundant_name ? "" : (prefix + name.substr(1)).c_str());
  return line;
}

} // namespace

const std::vector<std::string> &OptionsReadLater()
{
  // Each seen unread once a run is set up and read by its end (PETSc 3.18, 1 and 2 ranks; tests/check_bad_input.py
  // gives them all to a run):
  static const std::vector<std::string> names = {
    "-ksp_converged_reason", "-redundant_ksp_converged_reason", // at every solve (KSPSolve)
    "-vec_view", "-vec_view_stash",                             // at a vector's assembly
    "-build_twosided",                                          // at the first exchange between ranks
    // when the result file opens (PetscViewerHDF5Open) and takes the mesh (DMView):
    "-viewer_type", "-viewer_view", "-viewer_hdf5_base_dimension2", "-viewer_hdf5_collective",
    "-viewer_hdf5_default_timestepping", "-viewer_hdf5_sp_output", "-dm_plex_view_hdf5_storage_version",
    "-options_left", "-options_view", "-log", "-citations", "-get_total_flops"}; // at PetscFinalize
  return names;
}

PetscErrorCode CheckOptionsLeft(MPI_Comm comm, const Options &opt, PetscInt ndofs, bool redundant)
{
  std::vector<Given> left;
  PetscMPIInt size;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_size(comm, &size));
  PetscCall(ReadFactorizationOptions(comm, ndofs, opt.driver.factorization, false));
  PetscCall(Unread(comm, left));
  const auto &later = OptionsReadLater();
  const auto read_later = [&](const Given &g) {
    const std::string name = Lower(g.name);
    const bool inner = name.compare(0, 11, "-redundant_") == 0; // a redundant PC's own solver's
    return std::find(later.begin(), later.end(), name) != later.end() && (redundant || !inner);
  };
  left.erase(std::remove_if(left.begin(), left.end(), read_later), left.end());
  if (left.empty()) PetscFunctionReturn(PETSC_SUCCESS);

  // Which of them the factorization the run does not take reads (a failure there: none).
  const std::vector<Given> unread = left;
  const PetscErrorCode failed = ReadFactorizationOptions(comm, ndofs, opt.driver.factorization, true);
  PetscCall(Unread(comm, left));
  const Given &first = unread.front();
  const bool other =
    !failed && std::none_of(left.begin(), left.end(), [&](const Given &g) { return g.name == first.name; });
  std::string msg;
  if (other)
    msg = OtherPath(first, size, ndofs, redundant);
  else {
    std::vector<KnownOption> known = opt.known;
    known.insert(known.end(), PetscNames().begin(), PetscNames().end());
    const std::string hint = OptionHint(first.name, known);
    msg = Shown(first) + ": no scene, tool or PETSc object of this run reads it" +
          (hint.empty() ? "" : "; did you mean " + hint + OneOfGroup(hint, known) + "?");
  }
  if (unread.size() > 1) {
    msg += " (also unread:";
    for (size_t k = 1; k < unread.size(); ++k) msg += " " + unread[k].name;
    msg += ")";
  }
  if (opt.allow_unused) {
    PetscCall(PetscPrintf(comm, "tubeform: warning: %s; -allow_unused: the run goes on\n", msg.c_str()));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  SETERRQ(comm, PETSC_ERR_USER_INPUT, "%s (build/tubeform -help lists the options; -allow_unused runs anyway)",
          msg.c_str());
}

} // namespace tf
