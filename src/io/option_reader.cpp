#include "tubeform/io/option_reader.hpp"

#include <algorithm>
#include <cstdlib>

#include "tubeform/core/core.hpp"

namespace tf {

namespace {

std::string FirstWord(const std::string &name) { return name.substr(0, name.find('_')); }

// A misspelling is at most this many edits from the option meant (-tube_r, -frction_mu).
constexpr size_t kTypoEdits = 2;

} // namespace

size_t EditDistance(const std::string &a, const std::string &b)
{
  std::vector<size_t> row(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    size_t diag = row[0];
    row[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      const size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (a[i - 1] != b[j - 1])});
      diag = up;
    }
  }
  return row[b.size()];
}

PetscErrorCode OptionReader::CheckNumber(MPI_Comm comm, const char *name, bool integer) const
{
  char buf[256];
  PetscBool set;
  PetscFunctionBeginUser;
  PetscCall(PetscOptionsGetString(nullptr, nullptr, name, buf, sizeof(buf), &set));
  if (!set) PetscFunctionReturn(PETSC_SUCCESS);
  char *end = nullptr;
  if (integer)
    (void)std::strtol(buf, &end, 10);
  else
    (void)std::strtod(buf, &end);
  PetscCheck(buf[0] && end && *end == 0, comm, PETSC_ERR_USER_INPUT, "%s %s: not %s", name, buf,
             integer ? "a whole number" : "a number");
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode OptionReader::String(PetscOptionItems *PetscOptionsObject, const char *name, const char *help,
                                    std::string &value)
{
  char buf[PETSC_MAX_PATH_LEN];
  PetscBool set;

  PetscFunctionBeginUser;
  Note(name);
  PetscCall(PetscStrncpy(buf, value.c_str(), sizeof(buf)));
  PetscCall(PetscOptionsString(name, help, "tubeform", buf, buf, sizeof(buf), &set));
  if (set) value = buf;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode OptionReader::Real(PetscOptionItems *PetscOptionsObject, const char *name, const char *help,
                                  double &value)
{
  PetscFunctionBeginUser;
  Note(name);
  PetscCall(CheckNumber(PetscOptionsObject->comm, name, false));
  PetscCall(PetscOptionsReal(name, help, "tubeform", value, &value, nullptr));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode OptionReader::Int(PetscOptionItems *PetscOptionsObject, const char *name, const char *help,
                                 PetscInt &value)
{
  PetscFunctionBeginUser;
  Note(name);
  PetscCall(CheckNumber(PetscOptionsObject->comm, name, true));
  PetscCall(PetscOptionsInt(name, help, "tubeform", value, &value, nullptr));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode OptionReader::Bool(PetscOptionItems *PetscOptionsObject, const char *name, const char *help,
                                  PetscBool &value)
{
  PetscFunctionBeginUser;
  Note(name);
  PetscCall(PetscOptionsBool(name, help, "tubeform", value, &value, nullptr));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode OptionReader::CheckUnknown(MPI_Comm comm) const
{
  PetscInt n;
  char **left, **values;
  PetscFunctionBeginUser;
  PetscCall(PetscOptionsLeftGet(nullptr, &n, &left, &values));
  std::string bad, near;
  for (PetscInt k = 0; k < n && bad.empty(); ++k) {
    const std::string name = std::string("-") + left[k];
    size_t best = ~size_t(0);
    for (const auto &known : names_) {
      const size_t d = EditDistance(name, known);
      if (d < best) best = d, near = known;
    }
    const bool same_word =
      std::any_of(names_.begin(), names_.end(), [&](const std::string &s) { return FirstWord(s) == FirstWord(name); });
    if (best <= kTypoEdits || same_word) bad = name;
  }
  PetscCall(PetscOptionsLeftRestore(nullptr, &n, &left, &values));
  PetscCheck(bad.empty(), comm, PETSC_ERR_USER_INPUT,
             "%s: unknown option; did you mean %s? (build/tubeform -help lists them; -allow_unused runs anyway)",
             bad.c_str(), near.c_str());
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode ChooseWord(PetscOptionItems *PetscOptionsObject, OptionReader &read, const char *name, const char *help,
                          std::initializer_list<const char *> words, std::string &value)
{
  const char *const *list = words.begin();
  const PetscInt n = (PetscInt)words.size();
  PetscInt choice = 0;

  PetscFunctionBeginUser;
  read.Note(name);
  for (PetscInt k = 0; k < n; ++k)
    if (value == list[k]) choice = k;
  PetscCall(PetscOptionsEList(name, help, "tubeform", list, n, list[choice], &choice, nullptr));
  value = list[choice];
  PetscFunctionReturn(0);
}

// A list of at most `max` numbers; `value` is kept when the option is not given.
PetscErrorCode RealList(PetscOptionItems *PetscOptionsObject, OptionReader &read, const char *name, const char *help,
                        PetscInt max, std::vector<double> &value)
{
  std::vector<PetscReal> buf(max, 0.0); // -help prints the first entry as the default
  PetscInt n = max;
  PetscBool set;

  PetscFunctionBeginUser;
  read.Note(name);
  PetscCall(PetscOptionsRealArray(name, help, "tubeform", buf.data(), &n, &set));
  if (set) value.assign(buf.begin(), buf.begin() + n);
  PetscFunctionReturn(0);
}

} // namespace tf
