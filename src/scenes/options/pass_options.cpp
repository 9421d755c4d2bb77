// The first pass's stroke rule, path of strokes and release, and the later passes' options
// (include/tubeform/scenes/tool_options.hpp); checked in passes_check.cpp.
#include "tubeform/scenes/tool_options.hpp"

namespace tf {

namespace {
// A later pass's word option (one of an enum's `words`) into `out` as `make` turns it, where given; unset where not
// (the first pass's then: ReleaseOfPass, LowerDieOfPass).
template <class E, size_t N, class T, class Make>
PetscErrorCode ReadGivenWord(PetscOptionItems *PetscOptionsObject, OptionReader &read, const char *name,
                             const char *help, const char *const (&words)[N], std::optional<T> &out, Make make)
{
  PetscBool set;
  E value = static_cast<E>(0); // (-help's default: the first word)
  PetscFunctionBeginUser;
  PetscCall(PetscOptionsHasName(nullptr, nullptr, name, &set));
  PetscCall(ChooseWord(PetscOptionsObject, read, name, help, words, value));
  if (set) out = make(value);
  PetscFunctionReturn(PETSC_SUCCESS);
}

// What a later pass reads under its prefix (-pass<N>_<name>), in -help's order: the second pass's help says what
// each is, a later pass's points at the second's (with `later`, what differs).
enum class PassValue { Stroke, StrokePath, Profile, Lower, Side, Turn, Offset, Release };
struct PassOption {
  const char *name;
  PassValue value;
  const char *help;       // the second pass's
  const char *later = ""; // said of a later pass's besides "as -pass2_<name>'s"
};
const PassOption kPassOptions[] = {
  {"stroke", PassValue::Stroke,
   "tool scenes: a second pass after the springback: press again until the upper die is at this stroke (mm, from the "
   "same zero as -stroke: the die touching the round tube; it starts where it touches the tube; 0: one pass), then "
   "spring back; a third pass and more (up to 9) by the same options with their number: -pass3_stroke, -pass3_turn, "
   "... (docs/passes.md)"},
  {"stroke_path", PassValue::StrokePath,
   "tool scenes: the second pass's upper die's strokes in turn (mm, >= 0, from the same zero as -stroke), at the "
   "punch speed: press, back off, press again, in place of -pass2_stroke (the last is its final stroke; "
   "docs/passes.md)"},
  {"die_profile", PassValue::Profile,
   "squaring: the second pass's upper die from a profile file (default: the first pass's die)"},
  {"lower_die", PassValue::Lower,
   "tool scenes: the second pass's lower die: mirror, flat, v (its numbers -pass2_lower_die_angle, ...) or a profile "
   "file (default: the first pass's -lower_die)"},
  {"side_die", PassValue::Side,
   "tool scenes: the second pass's side dies: none, mirror, flat, v (its numbers -pass2_side_die_angle, ...) or a "
   "profile file (default: the first pass's -side_die)"},
  {"turn", PassValue::Turn,
   "tool scenes: the tube turned counter-clockwise by this many degrees (-360 to 360) before the second pass: its dies "
   "press along the turned axis (not a multiple of 90: the full model, held by the rotation hold; a later pass's "
   "-pass<N>_turn turns it on from the pass before's; docs/passes.md)",
   " (from the pass before's press)"},
  {"die_offset", PassValue::Offset,
   "squaring: the second pass's upper die moved off its press's y axis by this along the press's x (mm; the full "
   "model, held by the rotation hold; default 0: on the axis, whatever -die_offset says; docs/passes.md)"},
  {"unload", PassValue::Release,
   "tool scenes: how the second pass lets the tube go: reverse, withdraw (the quarter model) or none (the last pass "
   "only: the run ends loaded) (default: the first pass's -unload; docs/passes.md)"},
};

// One of a later pass's options (`name`, with its help) into `pass`.
PetscErrorCode ReadPassValue(PetscOptionItems *PetscOptionsObject, OptionReader &read, PassValue value,
                             const std::string &name, const std::string &help, PassSpec &pass)
{
  const char *n = name.c_str(), *h = help.c_str();
  PetscFunctionBeginUser;
  switch (value) {
  case PassValue::Stroke:
    PetscCall(read.Real(PetscOptionsObject, n, h, pass.stroke));
    break;
  case PassValue::StrokePath: // (after its stroke: in place of it, the last stroke; checked in passes_check.cpp)
    PetscCall(RealList(PetscOptionsObject, read, n, h, kMaxPathPoints, pass.stroke_path));
    PetscCheck(pass.stroke_path.empty() || pass.stroke == 0, PetscOptionsObject->comm, PETSC_ERR_USER_INPUT,
               "%s: in place of %s (the last of its strokes is the pass's final one); give one of them", n,
               name.substr(0, name.size() - 5).c_str());
    if (!pass.stroke_path.empty()) pass.stroke = pass.stroke_path.back();
    break;
  case PassValue::Profile:
    PetscCall(ReadDrawingChoice(PetscOptionsObject, read, n, h, pass.dies.upper));
    break;
  case PassValue::Lower:
    PetscCall(ReadDieChoice(PetscOptionsObject, read, n, h, false, pass.dies.lower));
    break;
  case PassValue::Side:
    PetscCall(ReadDieChoice(PetscOptionsObject, read, n, h, true, pass.dies.side));
    break;
  case PassValue::Turn:
    PetscCall(read.Real(PetscOptionsObject, n, h, pass.turn));
    break;
  case PassValue::Offset:
    PetscCall(read.Real(PetscOptionsObject, n, h, pass.dies.offset));
    break;
  case PassValue::Release:
    PetscCall(
      ReadGivenWord<Unload>(PetscOptionsObject, read, n, h, kUnloadWords, pass.release, [](Unload u) { return u; }));
    break;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

// Pass `number` (2 to kMaxPasses): its options of kPassOptions. The second pass's always read (and listed by -help);
// a later one's where one of them is given, named for the hints on a misspelt option always.
PetscErrorCode ReadPass(PetscOptionItems *PetscOptionsObject, OptionReader &read, int number, PassSpec &pass)
{
  const std::string pre = "-pass" + std::to_string(number) + "_";
  const std::string as = "pass " + std::to_string(number) + "'s, as -pass2_"; // (the scenes: -pass2_<name>'s)
  bool given = number == 2;
  PetscFunctionBeginUser;
  for (const PassOption &o : kPassOptions) {
    PetscBool set;
    PetscCall(PetscOptionsHasName(nullptr, nullptr, (pre + o.name).c_str(), &set));
    given = given || set;
  }
  for (const PassOption &o : kPassOptions) {
    const std::string name = pre + o.name, help = number == 2 ? o.help : as + o.name + "'s" + o.later;
    if (given)
      PetscCall(ReadPassValue(PetscOptionsObject, read, o.value, name, help, pass));
    else
      read.Note(name.c_str(), help.c_str(), PetscOptionsObject->title);
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

// The first pass's own: its stroke by the paper's rule or its strokes in turn (its stroke -stroke is shared with the
// column: io), and how it lets the tube go.
PetscErrorCode ReadFirstPass(PetscOptionItems *PetscOptionsObject, OptionReader &read, PassSpec &pass)
{
  Unload release = *pass.release;
  PetscFunctionBeginUser;
  PetscCall(read.Real(PetscOptionsObject, "-stroke_corner_radius",
                      "tool scenes: the first pass's stroke by the paper's rule: the rounded square's corner (mm)",
                      pass.corner_radius));
  PetscCall(RealList(PetscOptionsObject, read, "-stroke_path",
                     "tool scenes: the die's strokes in turn (mm, >= 0), at the punch speed: press, back off, press "
                     "again (in place of -stroke: the last is the final stroke)",
                     kMaxPathPoints, pass.stroke_path));
  PetscCall(
    ChooseWord(PetscOptionsObject, read, "-unload",
               "tool scenes: how the first pass lets the tube go: reverse (the paper's: contact forces reversed, "
               "tools removed), withdraw (the dies move back), none (the run ends loaded)",
               kUnloadWords, release));
  pass.release = release;
  PetscFunctionReturn(PETSC_SUCCESS);
}

} // namespace

PetscErrorCode ReadToolOptions(PetscOptionItems *PetscOptionsObject, OptionReader &read, Options &opt)
{
  PetscFunctionBeginUser;
  PetscCall(ReadFirstPass(PetscOptionsObject, read, ToolsOf(opt).passes[0]));
  for (int number = 2; number <= kMaxPasses; ++number)
    PetscCall(ReadPass(PetscOptionsObject, read, number, ToolsOf(opt).passes[number - 1]));
  PetscFunctionReturn(PETSC_SUCCESS);
}

} // namespace tf
