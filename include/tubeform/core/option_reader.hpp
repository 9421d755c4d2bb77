// Reading tubeform's options: each reader records the option's name, and a
// number that is not one is refused with a message naming the option
// (PETSc's own says only "Input string abc has no numeric value"). Called
// between PetscOptionsBegin and PetscOptionsEnd, whose PetscOptionsObject
// they take, so that -help lists the options as before.
#pragma once

#include <petscsys.h>

#include <string>
#include <vector>

#include "tubeform/core/core.hpp"

namespace tf {

// An option tubeform reads: its name (with the dash), its -help text, the title of the -help block that reads it
// ("tubeform: upper die shape"; empty where it is noted outside a block) and the scenes that alone read it
// (space-separated names, "squaring flattening"; empty: every scene).
struct KnownOption {
  std::string name, help, reader, scenes;
};

// Edits (insertions, deletions, substitutions) between two words.
size_t EditDistance(const std::string &a, const std::string &b);

// The option among `known` that `name` (with the dash) most likely means, or
// "": one within 2 edits (-tube_r: -tube_ro), else the first whose name and
// help hold every word of `name` (-wall_thickness: -tube_t, "Wall thickness").
std::string OptionHint(const std::string &name, const std::vector<KnownOption> &known);

// ", one of the upper die shape options" for the option `name` among `known`, from its -help block's title
// ("tubeform: upper die shape"); "" where it was noted outside a block or is not among them.
std::string OneOfGroup(const std::string &name, const std::vector<KnownOption> &known);

class OptionReader {
public:
  PetscErrorCode Real(PetscOptionItems *PetscOptionsObject, const char *name, const char *help, double &value);
  PetscErrorCode Int(PetscOptionItems *PetscOptionsObject, const char *name, const char *help, PetscInt &value);
  PetscErrorCode Bool(PetscOptionItems *PetscOptionsObject, const char *name, const char *help, PetscBool &value);
  // A file name or word (kept as it was when the option is not given).
  PetscErrorCode String(PetscOptionItems *PetscOptionsObject, const char *name, const char *help, std::string &value);
  // An option read some other way (a word from a list, a file name); `reader`: the title of the block reading it.
  void Note(const char *name, const char *help = "", const char *reader = "")
  {
    names_.push_back({name, help, reader ? reader : "", scenes_});
  }
  // The scenes that alone read the options noted from here on (space-separated names; "": every scene).
  void ReadBy(const std::string &scenes) { scenes_ = scenes; }
  // Collective, after every tubeform option is read: an option given but not
  // read that is close to one of tubeform's (within 2 edits, or sharing its
  // first word: -tube_*, -rmin_*, ...) is an error naming the nearest (the
  // caller skips it with -allow_unused). The other unread options are judged
  // once the run's PETSc objects have read theirs (io/options_left.hpp).
  PetscErrorCode CheckUnknown(MPI_Comm comm) const;
  const std::vector<KnownOption> &known() const { return names_; }
  // Collective: option `name` (with the dash), where given, a number (a whole one: `integer`), or an error naming it.
  PetscErrorCode CheckNumber(MPI_Comm comm, const char *name, bool integer) const;

private:
  std::vector<KnownOption> names_; // with the dash
  std::string scenes_;             // ReadBy's
};

// One of a list of words for an option whose value is an enum E, `words` its words in its enumerators' order; the
// current value is the default.
template <class E, size_t N>
PetscErrorCode ChooseWord(PetscOptionItems *PetscOptionsObject, OptionReader &read, const char *name, const char *help,
                          const char *const (&words)[N], E &value)
{
  PetscInt choice = static_cast<PetscInt>(value);
  PetscFunctionBeginUser;
  read.Note(name, help, PetscOptionsObject->title);
  PetscCall(PetscOptionsEList(name, help, "tubeform", words, (PetscInt)N, words[choice], &choice, nullptr));
  value = static_cast<E>(choice);
  PetscFunctionReturn(PETSC_SUCCESS);
}
// A list of at most `max` numbers; `value` is kept when the option is not given.
PetscErrorCode RealList(PetscOptionItems *PetscOptionsObject, OptionReader &read, const char *name, const char *help,
                        PetscInt max, std::vector<double> &value);

// Ends a PetscOptionsBegin block that an error leaves early (a PetscCall
// returning from inside it), so that what the block allocated is freed;
// released just before PetscOptionsEnd, which ends it otherwise.
class OptionsBlock {
public:
  explicit OptionsBlock(PetscOptionItems *items) : items_(items) {}
  OptionsBlock(const OptionsBlock &) = delete;
  OptionsBlock &operator=(const OptionsBlock &) = delete;
  ~OptionsBlock()
  {
    if (items_) (void)PetscOptionsEnd_Private(items_); // on the error path: its own error cannot be returned
  }
  void Release() { items_ = nullptr; }

private:
  PetscOptionItems *items_;
};

} // namespace tf

// PetscOptionsBegin / PetscOptionsEnd of a tubeform block, ended on the error path as well.
#define TF_OPTIONS_BEGIN(comm, title)                                                                                  \
  PetscOptionsBegin(comm, "", title, "tubeform");                                                                      \
  tf::OptionsBlock tf_options_block_(PetscOptionsObject)
#define TF_OPTIONS_END()                                                                                               \
  tf_options_block_.Release();                                                                                         \
  PetscOptionsEnd()
