#include "tubeform/core/option_reader.hpp"

#include <algorithm>
#include <cctype>
#include <cstdlib>

#include "tubeform/core/core.hpp"

namespace tf {

namespace {

// The lower-case word before the first underscore (PETSc's option names ignore case).
std::string FirstWord(const std::string &name)
{
  std::string w = name.substr(0, name.find('_'));
  for (char &c : w) c = (char)std::tolower((unsigned char)c);
  return w;
}

// A misspelling is at most this many edits from the option meant (-tube_r, -frction_mu).
constexpr size_t kTypoEdits = 2;
// Words shorter than this say nothing of what an option means (-die_r_apex's "r").
constexpr size_t kMinWord = 3;

// The lower-case words of a text (letters only; a plural's s dropped).
std::vector<std::string> Words(const std::string &text)
{
  std::vector<std::string> words;
  std::string w;
  for (size_t i = 0; i <= text.size(); ++i) {
    const char c = i < text.size() ? (char)std::tolower((unsigned char)text[i]) : ' ';
    if (c >= 'a' && c <= 'z') {
      w += c;
      continue;
    }
    if (w.size() > kMinWord && w.back() == 's') w.pop_back();
    if (w.size() >= kMinWord) words.push_back(w);
    w.clear();
  }
  return words;
}

} // namespace

std::string OneOfGroup(const std::string &name, const std::vector<KnownOption> &known)
{
  const auto k = std::find_if(known.begin(), known.end(), [&](const KnownOption &o) { return o.name == name; });
  if (k == known.end() || k->reader.empty()) return "";
  const std::string own = "tubeform: ";
  return ", one of the " + (k->reader.rfind(own, 0) == 0 ? k->reader.substr(own.size()) : k->reader) + " options";
}

std::string OptionHint(const std::string &given, const std::vector<KnownOption> &known)
{
  std::string name = given; // (PETSc's option names ignore case)
  for (char &c : name) c = (char)std::tolower((unsigned char)c);
  size_t best = kTypoEdits + 1;
  std::string hint;
  for (const auto &k : known) {
    const size_t d = EditDistance(name, k.name);
    if (d > 0 && d < best) best = d, hint = k.name; // (itself: no hint)
  }
  if (!hint.empty()) return hint;
  const std::vector<std::string> asked = Words(name);
  if (asked.empty()) return "";
  for (const auto &k : known) {
    if (k.name == name) continue;
    const std::vector<std::string> has = Words(k.name + " " + k.help);
    if (std::all_of(asked.begin(), asked.end(),
                    [&](const std::string &w) { return std::find(has.begin(), has.end(), w) != has.end(); }))
      return k.name;
  }
  return "";
}

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
  Note(name, help, PetscOptionsObject->title);
  PetscCall(PetscStrncpy(buf, value.c_str(), sizeof(buf)));
  PetscCall(PetscOptionsString(name, help, "tubeform", buf, buf, sizeof(buf), &set));
  if (set) value = buf;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode OptionReader::Real(PetscOptionItems *PetscOptionsObject, const char *name, const char *help,
                                  double &value)
{
  PetscFunctionBeginUser;
  Note(name, help, PetscOptionsObject->title);
  PetscCall(CheckNumber(PetscOptionsObject->comm, name, false));
  PetscCall(PetscOptionsReal(name, help, "tubeform", value, &value, nullptr));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode OptionReader::Int(PetscOptionItems *PetscOptionsObject, const char *name, const char *help,
                                 PetscInt &value)
{
  PetscFunctionBeginUser;
  Note(name, help, PetscOptionsObject->title);
  PetscCall(CheckNumber(PetscOptionsObject->comm, name, true));
  PetscCall(PetscOptionsInt(name, help, "tubeform", value, &value, nullptr));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode OptionReader::Bool(PetscOptionItems *PetscOptionsObject, const char *name, const char *help,
                                  PetscBool &value)
{
  PetscFunctionBeginUser;
  Note(name, help, PetscOptionsObject->title);
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
    std::string lower = name;
    for (char &c : lower) c = (char)std::tolower((unsigned char)c);
    const bool same_word = std::any_of(names_.begin(), names_.end(),
                                       [&](const KnownOption &s) { return FirstWord(s.name) == FirstWord(name); });
    near = OptionHint(name, names_);
    if (same_word && near.empty()) {
      size_t best = ~size_t(0);
      for (const auto &known : names_) {
        const size_t d = EditDistance(lower, known.name);
        if (d < best) best = d, near = known.name;
      }
    }
    if (same_word || (!near.empty() && EditDistance(lower, near) <= kTypoEdits)) bad = name;
  }
  PetscCall(PetscOptionsLeftRestore(nullptr, &n, &left, &values));
  PetscCheck(bad.empty(), comm, PETSC_ERR_USER_INPUT,
             "%s: unknown option; did you mean %s%s? (build/tubeform -help lists them; -allow_unused runs anyway)",
             bad.c_str(), near.c_str(), OneOfGroup(near, names_).c_str());
  PetscFunctionReturn(PETSC_SUCCESS);
}

// A list of at most `max` numbers; `value` is kept when the option is not given.
PetscErrorCode RealList(PetscOptionItems *PetscOptionsObject, OptionReader &read, const char *name, const char *help,
                        PetscInt max, std::vector<double> &value)
{
  std::vector<PetscReal> buf(max, 0.0); // -help prints the first entry as the default
  PetscInt n = max;
  PetscBool set;

  PetscFunctionBeginUser;
  read.Note(name, help, PetscOptionsObject->title);
  PetscCall(PetscOptionsRealArray(name, help, "tubeform", buf.data(), &n, &set));
  if (set) value.assign(buf.begin(), buf.begin() + n);
  PetscFunctionReturn(0);
}

} // namespace tf
