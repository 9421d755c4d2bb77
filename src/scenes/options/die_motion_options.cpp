// The dies' motions, each die's in its own options block under its prefix (include/tubeform/scenes/tool_options.hpp):
// -<prefix>motion names a kind of the motion registry (tool/motion.hpp) by one of the die's words, and the kind
// reads its own options, -<prefix>*, refusing what it cannot move by; an option of another of the die's words'
// kinds given is kept as the die's stray (its refusal, naming it: CheckMotionStrays, in a press; a scene without
// tools leaves it to the check of options only other scenes read, -allow_unused lets it go). The lower die:
// -lower_die_motion (mirror, fixed, path: the schedule, and the kinds registered after the built-in ones); the upper
// die: -die_motion (stroke, path, force: each its kind's own name). Combinations with the scene's other options are
// each kind's check (scenes/motion_checks.hpp) and the scene's.
#include <algorithm>
#include <iterator>

#include "tubeform/scenes/tool_options.hpp"

namespace tf {

namespace {
// The lower die's motion's -help block (its options' reader in an unknown option's hint).
constexpr const char *kLowerMotionTitle = "tubeform: lower die motion";
// A die's word for its motion and the kind of the registry it names.
struct MotionWord {
  std::string word, kind;
};

// The first -<prefix><name> of the words' kinds other than `chosen`'s given, as its refusal into an empty `stray`
// (left empty where none is): one line naming it, the word it belongs to and the word chosen (refused by
// CheckMotionStrays, in a press only). `spared`: an option the old spellings give with the chosen word (none: "").
PetscErrorCode StrayOption(const char *prefix, const std::vector<MotionWord> &words, const MotionWord &chosen,
                           const std::string &spared, std::string &stray)
{
  PetscFunctionBeginUser;
  const std::vector<std::string> mine = FindMotionKind(chosen.kind)->options;
  for (const MotionWord &w : words)
    for (const std::string &name : FindMotionKind(w.kind)->options) {
      PetscBool given;
      PetscCall(PetscOptionsHasName(nullptr, prefix, ("-" + name).c_str(), &given));
      const bool other = std::find(mine.begin(), mine.end(), name) == mine.end() && name != spared;
      if (given && other && stray.empty())
        stray = Formatted("-%s%s: an option of -%smotion %s, not of -%smotion %s", prefix, name.c_str(), prefix,
                          w.word.c_str(), prefix, chosen.word.c_str());
    }
  PetscFunctionReturn(PETSC_SUCCESS);
}

// A die's words for its motion: each kind of the registry that offers it one (`word`: MotionKind::lower_word,
// upper_word or side_word), in the registry's order.
std::vector<MotionWord> WordsOf(const char *MotionKind::*word)
{
  std::vector<MotionWord> words;
  for (const std::string &kind : MotionKinds())
    if (const char *w = FindMotionKind(kind)->*word) words.push_back({w, kind});
  return words;
}
// The lower die's (-lower_die_motion), the upper die's (-die_motion, -pass<N>_die_motion) and the side dies'
// (-side_motion, -pass<N>_side_motion).
std::vector<MotionWord> LowerWords() { return WordsOf(&MotionKind::lower_word); }
std::vector<MotionWord> UpperWords() { return WordsOf(&MotionKind::upper_word); }
std::vector<MotionWord> SideWords() { return WordsOf(&MotionKind::side_word); }

// A lower die's -<prefix>motion help (`die`: "the lower die", "the second pass's lower die"): what it does under each
// word (a kind's lower_help, or its options under the prefix).
std::string LowerHelp(const std::vector<MotionWord> &words, const std::string &prefix, const std::string &die)
{
  std::string help = "tool scenes: " + die + " ";
  for (size_t k = 0; k < words.size(); ++k) {
    const MotionKind *kind = FindMotionKind(words[k].kind);
    help += k == 0 ? "" : k + 1 < words.size() ? ", " : " or ";
    if (kind->lower_help) {
      help += kind->lower_help;
      continue;
    }
    help += "moves as its motion " + words[k].word + " says (";
    for (const std::string &name : kind->options) help += "-" + prefix + name + ", ";
    help += "docs/motions.md)";
  }
  return help + "; the upper die travels U but with fixed";
}

// Where the word `word` is among `words` (-1: not there).
PetscInt WordAt(const std::vector<MotionWord> &words, const char *word)
{
  for (size_t k = 0; k < words.size(); ++k)
    if (words[k].word == word) return (PetscInt)k;
  return -1;
}

// A die's word where -<prefix>motion is not given, from the old spellings: path where an option of the kind the word
// path names is given (-<prefix>path; the upper die's -<prefix>path_turn, -<prefix>pivot too); force (a word of
// `words`) where -<prefix>force is given other than 0; else the stroke. `zero_force`: -<prefix>force 0 given without
// -<prefix>motion (the old "not by force", allowed with any word).
PetscErrorCode OldSpelling(MPI_Comm comm, OptionReader &read, const std::string &prefix,
                           const std::vector<MotionWord> &words, PetscInt &choice, bool &zero_force)
{
  PetscBool motion, force = PETSC_FALSE;
  PetscReal f = 0;
  bool path = false; // (one of the options of the kind the word path names: the upper die's path, turns, pivot)
  const PetscInt path_at = WordAt(words, kPathMotion), force_at = WordAt(words, kForceMotion);
  PetscFunctionBeginUser;
  PetscCall(PetscOptionsHasName(nullptr, prefix.c_str(), "-motion", &motion));
  for (size_t k = 0; path_at >= 0 && k < FindMotionKind(words[path_at].kind)->options.size(); ++k) {
    PetscBool set;
    PetscCall(PetscOptionsHasName(nullptr, prefix.c_str(),
                                  ("-" + FindMotionKind(words[path_at].kind)->options[k]).c_str(), &set));
    path = path || set;
  }
  if (force_at >= 0) {
    PetscCall(read.CheckNumber(comm, ("-" + prefix + "force").c_str(), false));
    PetscCall(PetscOptionsGetReal(nullptr, prefix.c_str(), "-force", &f, &force));
  }
  zero_force = !motion && force && f == 0;
  if (!motion && path)
    choice = path_at;
  else if (!motion && force && f != 0)
    choice = force_at;
  PetscFunctionReturn(PETSC_SUCCESS);
}
// A die's motion's block: its options prefix (die_: -die_motion, -die_path, ...), its title in -help, the help of
// -<prefix>motion, and the die's words (the registry's kinds that offer it one, in the registry's order).
struct MotionBlock {
  std::string prefix, title, help;
  std::vector<MotionWord> words;
  bool old_spellings = true; // -<prefix>path, -<prefix>force alone choose their words (not the lower die's)
};

// A die's motion read in its own block: -<prefix>motion, one of the block's words, or an old spelling
// (-<prefix>path, its turns or pivot: path; -<prefix>force other than 0: force); that kind's options read by the kind
// (all the words' under `help`, refusing nothing), an option of another word's kind kept in die.stray, naming it
// (refused by CheckMotionStrays, in a press only). die.spec.tool names the die in the kinds' refusals.
PetscErrorCode ReadWordMotion(MPI_Comm comm, OptionReader &read, const MotionBlock &block, bool help, DieMotion &die)
{
  const std::vector<MotionWord> &words = block.words;
  const std::string &prefix = block.prefix;
  std::vector<const char *> list;
  PetscInt choice = 0;
  bool zero_force = false;

  PetscFunctionBeginUser;
  for (const MotionWord &w : words) {
    if (w.kind == die.kind) choice = (PetscInt)list.size();
    list.push_back(w.word.c_str());
    for (const std::string &name : FindMotionKind(w.kind)->options)
      read.Note(("-" + prefix + name).c_str(), "", block.title.c_str());
  }
  read.Note(("-" + prefix + "motion").c_str(), block.help.c_str(), block.title.c_str());
  if (block.old_spellings) PetscCall(OldSpelling(comm, read, prefix, words, choice, zero_force));
  PetscOptionsBegin(comm, prefix.c_str(), block.title.c_str(), "tubeform");
  OptionsBlock end(PetscOptionsObject);
  PetscCall(PetscOptionsEList("-motion", block.help.c_str(), "tubeform", list.data(), (PetscInt)list.size(),
                              list[choice], &choice, nullptr));
  die.kind = words[choice].kind;
  if (help)
    for (const MotionWord &w : words) PetscCall(ReadMotion(PetscOptionsObject, w.kind, die.spec));
  else
    PetscCall(ReadMotion(PetscOptionsObject, words[choice].kind, die.spec));
  end.Release();
  PetscOptionsEnd();
  die.stray.clear(); // (a later pass's block starts from a copy of the first pass's die)
  if (!help) PetscCall(StrayOption(prefix.c_str(), words, words[choice], zero_force ? kForceMotion : "", die.stray));
  PetscFunctionReturn(PETSC_SUCCESS);
}

// A lower die's motion read in its block (ReadWordMotion, without old spellings): its word (mirror, fixed, path, ...)
// and how it goes with the upper die's from the kind chosen.
PetscErrorCode ReadLowerMotion(MPI_Comm comm, OptionReader &read, const MotionBlock &block, bool help,
                               LowerDieSpec &die)
{
  PetscFunctionBeginUser;
  PetscCall(ReadWordMotion(comm, read, block, help, die));
  for (const MotionWord &w : block.words)
    if (w.kind == die.kind) die.word = w.word;
  die.move = LowerDieMoveOf(die.word);
  PetscFunctionReturn(PETSC_SUCCESS);
}

// Whether a later pass's block is read: one of its options given (-<prefix>motion, its words' kinds' options), or
// `listed` (its -help); where not, they are noted (known to the check of unknown options, listed by -help).
PetscErrorCode BlockGiven(OptionReader &read, const MotionBlock &block, bool listed, bool &given)
{
  std::vector<std::string> names = {"motion"};
  for (const MotionWord &w : block.words)
    for (const std::string &name : FindMotionKind(w.kind)->options) names.push_back(name);
  PetscFunctionBeginUser;
  given = listed;
  for (const std::string &name : names) {
    PetscBool set;
    PetscCall(PetscOptionsHasName(nullptr, block.prefix.c_str(), ("-" + name).c_str(), &set));
    given = given || set;
  }
  for (const std::string &name : names)
    if (!given) read.Note(("-" + block.prefix + name).c_str(), block.help.c_str(), block.title.c_str());
  PetscFunctionReturn(PETSC_SUCCESS);
}

} // namespace

PetscErrorCode ReadLowerDieMotion(MPI_Comm comm, OptionReader &read, Options &opt)
{
  LowerDieSpec &die = *ToolsOf(opt).passes[0].lower_motion;
  PetscFunctionBeginUser;
  die.spec.tool = "the lower die";
  const MotionBlock block{"lower_die_", kLowerMotionTitle, LowerHelp(LowerWords(), "lower_die_", "the lower die"),
                          LowerWords(), false};
  PetscCall(ReadLowerMotion(comm, read, block, opt.help, die));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode ReadPassLowerMotions(MPI_Comm comm, OptionReader &read, Options &opt)
{
  PetscFunctionBeginUser;
  for (int pass = 1; pass < kMaxPasses; ++pass) {
    const std::string prefix = Formatted("pass%d_lower_die_", pass + 1);
    const std::string die = "the " + PassOrdinal(pass) + " pass's lower die";
    const MotionBlock block{
      prefix, Formatted("tubeform: pass %d lower die motion", pass + 1),
      pass > 1 ? Formatted("tool scenes: pass %d's, as -pass2_lower_die_motion", pass + 1)
               : LowerHelp(LowerWords(), prefix, die) +
                   "; a motion of its own counts its strokes from where the pass's dies start (default: the first "
                   "pass's -lower_die_motion where that is mirror or fixed; a later pass's by its number: "
                   "-pass3_lower_die_motion, ...)",
      LowerWords(), false};
    bool given;
    PetscCall(BlockGiven(read, block, opt.help && pass == 1, given)); // (the second's listed by -help)
    if (!given) continue;
    LowerDieSpec own = *FirstPass(opt).lower_motion; // (its word the default; its spec its own)
    own.spec = MotionSpec();
    own.spec.tool = die;
    PetscCall(ReadLowerMotion(comm, read, block, opt.help, own));
    ToolsOf(opt).passes[pass].lower_motion = own;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode ReadUpperDieMotion(MPI_Comm comm, OptionReader &read, Options &opt)
{
  const MotionBlock block{
    "die_", "tubeform: upper die motion",
    "tool scenes: the upper die moves down by the stroke U (stroke; 2 U over a fixed lower die), along a path of its "
    "own (path: -die_path, -die_path_turn, -die_pivot) or presses with a force (force: -die_force); without it, "
    "-die_path (or its turns or pivot) means path, -die_force other than 0 force (docs/motions.md)",
    UpperWords()};
  PetscFunctionBeginUser;
  DieMotion &motion = ToolsOf(opt).passes[0].dies.motion;
  motion.spec.tool = "the " + opt.scene + " scene's upper die";
  PetscCall(ReadWordMotion(comm, read, block, opt.help, motion));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode ReadPassMotions(MPI_Comm comm, OptionReader &read, Options &opt)
{
  PetscFunctionBeginUser;
  for (int pass = 1; pass < kMaxPasses; ++pass) {
    PassSpec &p = ToolsOf(opt).passes[pass];
    const MotionBlock block{
      Formatted("pass%d_die_", pass + 1), Formatted("tubeform: pass %d upper die motion", pass + 1),
      pass > 1 ? Formatted("tool scenes: pass %d's, as -pass2_die_motion", pass + 1)
               : "tool scenes: the second pass's upper die moves by its stroke (stroke: -pass2_stroke), along a path "
                 "of its own from where it starts (path: -pass2_die_path, -pass2_die_path_turn, -pass2_die_pivot, as "
                 "-die_path's; over a lower die that stays, -lower_die_motion fixed; in place of -pass2_stroke: the "
                 "pass ends at U = -y / 2 of its last point; off the axis: the full model under the rotation hold, "
                 "which -model auto and -full_hold auto choose) or presses with a force from where it starts (force: "
                 "-pass2_die_force, as -die_force's; in place of -pass2_stroke: the pass ends at that punch load, its "
                 "stroke the outcome); without it, -pass2_die_path (or its turns or pivot) means path, "
                 "-pass2_die_force other than 0 force; a later pass's by its number: -pass3_die_path, ... "
                 "(docs/passes.md)",
      UpperWords()};
    bool given;
    PetscCall(BlockGiven(read, block, pass == 1, given)); // (the second's read always, and listed by -help)
    if (!given) continue;
    p.dies.motion.spec.tool = "the " + PassOrdinal(pass) + " pass's upper die";
    PetscCall(ReadWordMotion(comm, read, block, opt.help, p.dies.motion));
    if (opt.help || !p.dies.motion.OwnPath()) continue;
    // Its stroke: where its path ends (U = -y / 2 of its last point, from where it starts).
    const std::string path = "-" + block.prefix + "path";
    MotionSpec own = p.dies.motion.spec;
    own.reach = opt.tube_ro; // (its turns counted at the tube's outer radius, as DiesOfPass takes them)
    const double y = MotionPathOf(p.dies.motion.kind, own).Last()[1];
    PetscCheck(p.stroke == 0, comm, PETSC_ERR_USER_INPUT,
               "%s: in place of %s (the pass ends at U = -y / 2 of its last point); give one of them", path.c_str(),
               PassOptionName(pass, "stroke").c_str());
    PetscCheck(y < 0, comm, PETSC_ERR_USER_INPUT,
               "%s: the last point's y %g must be below the start: the press ends pressing (U = -y / 2)", path.c_str(),
               y);
    p.stroke = -0.5 * y;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

namespace {
// -<prefix>side_motion's help (`pass`: 0 the first pass's, 1 the second's): the side dies' words, each with its
// kind's options under the prefix.
std::string SideHelp(const std::string &prefix, int pass)
{
  const std::vector<MotionWord> words = SideWords();
  std::string help = "tool scenes: how " + std::string(pass == 0 ? "the" : "the second pass's") +
                     " side dies move towards the tube's centre (a motion of the registry, as the other dies'): ";
  for (size_t k = 0; k < words.size(); ++k) {
    help += (k == 0 ? "" : k + 1 < words.size() ? ", " : " or ") + words[k].word;
    const std::vector<std::string> &options = FindMotionKind(words[k].kind)->options;
    for (size_t j = 0; j < options.size(); ++j) help += (j == 0 ? " (-" : ", -") + prefix + options[j];
    help += options.empty() ? "" : ")";
  }
  return help + "; stroke: in by the stroke U, force: each pressing with a force on the whole tube (N/mm), its " +
         "travel an unknown; without it, -" + prefix + "path means path, -" + prefix + "force other than 0 force" +
         (pass == 0 ? "" : " (default: by the stroke, whatever the first pass's say)") + " (docs/dies.md)";
}
} // namespace

PetscErrorCode ReadSideMotions(MPI_Comm comm, OptionReader &read, Options &opt)
{
  PetscFunctionBeginUser;
  for (int pass = 0; pass < kMaxPasses; ++pass) {
    const std::string prefix = pass == 0 ? "side_" : Formatted("pass%d_side_", pass + 1);
    const MotionBlock block{
      prefix, pass == 0 ? "tubeform: side die motion" : Formatted("tubeform: pass %d side die motion", pass + 1),
      pass > 1 ? Formatted("tool scenes: pass %d's, as -pass2_side_motion", pass + 1) : SideHelp(prefix, pass),
      SideWords()};
    bool given = true; // (the first pass's always read; a later one's where one of them is given)
    if (pass > 0) PetscCall(BlockGiven(read, block, pass == 1 && opt.help, given));
    if (!given) continue;
    DieMotion &motion = ToolsOf(opt).passes[pass].dies.side_motion;
    motion.spec.tool = pass == 0 ? "each side die" : "each of the " + PassOrdinal(pass) + " pass's side dies";
    PetscCall(ReadWordMotion(comm, read, block, opt.help, motion));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

} // namespace tf
