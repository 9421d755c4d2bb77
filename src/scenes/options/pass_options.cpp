// The later passes' options (include/tubeform/scenes/tool_options.hpp); checked in passes_check.cpp.
#include "tubeform/scenes/tool_options.hpp"

namespace tf {

namespace {
// A later pass's release (-pass<N>_unload): unset where not given (the first pass's -unload then: ReleaseOfPass).
PetscErrorCode ReadPassRelease(PetscOptionItems *PetscOptionsObject, OptionReader &read, const char *name,
                               const char *help, std::optional<Unload> &release)
{
  PetscBool set;
  Unload value = Unload::Reverse;
  PetscFunctionBeginUser;
  PetscCall(PetscOptionsHasName(nullptr, nullptr, name, &set));
  PetscCall(ChooseWord(PetscOptionsObject, read, name, help, kUnloadWords, value));
  if (set) release = value;
  PetscFunctionReturn(PETSC_SUCCESS);
}

// A later pass's lower die's motion (-pass<N>_lower_die_motion): mirror or fixed; unset where not given (the first
// pass's -lower_die_motion then: LowerDieOfPass).
PetscErrorCode ReadPassLowerMotion(PetscOptionItems *PetscOptionsObject, OptionReader &read, const char *name,
                                   const char *help, std::optional<LowerDieSpec> &motion)
{
  PetscBool set;
  LowerDieMove move = LowerDieMove::Mirror;
  PetscFunctionBeginUser;
  PetscCall(PetscOptionsHasName(nullptr, nullptr, name, &set));
  PetscCall(ChooseWord(PetscOptionsObject, read, name, help, kLowerDieMoveWords, move));
  if (set) motion = LowerDieOfWord(WordOf(kLowerDieMoveWords, move));
  PetscFunctionReturn(PETSC_SUCCESS);
}

// The second pass: its stroke, dies and turn (the help's text; a later pass's options read by the same names).
PetscErrorCode ReadSecondPass(PetscOptionItems *PetscOptionsObject, OptionReader &read, PassSpec &pass)
{
  PetscFunctionBeginUser;
  PetscCall(read.Real(PetscOptionsObject, "-pass2_stroke",
                      "squaring: a second pass after the springback: press again until the upper die is at this "
                      "stroke (mm, from the same zero as -stroke: the die touching the round tube; it starts where it "
                      "touches the tube; 0: one pass), then spring back; a third pass and more (up to 9) by the same "
                      "options with their number: -pass3_stroke, -pass3_turn, ... (docs/dies.md)",
                      pass.stroke));
  PetscCall(ReadDrawingChoice(PetscOptionsObject, read, "-pass2_die_profile",
                              "squaring: the second pass's upper die from a profile file (default: the first pass's "
                              "die)",
                              pass.dies.upper));
  PetscCall(ReadDieChoice(PetscOptionsObject, read, "-pass2_lower_die",
                          "squaring: the second pass's lower die: mirror, flat or a profile file (default: the first "
                          "pass's -lower_die)",
                          false, pass.dies.lower));
  PetscCall(ReadDieChoice(PetscOptionsObject, read, "-pass2_side_die",
                          "squaring: the second pass's side dies: none, mirror, flat or a profile file (default: the "
                          "first pass's -side_die)",
                          true, pass.dies.side));
  PetscCall(read.Real(PetscOptionsObject, "-pass2_turn",
                      "squaring: the tube turned counter-clockwise by this many degrees (-360 to 360) before the "
                      "second pass: its dies press along the turned axis (not a multiple of 90: the full model, "
                      "held by the rotation hold; a later pass's -pass<N>_turn turns it on from the pass before's; "
                      "docs/dies.md)",
                      pass.turn));
  PetscCall(read.Real(PetscOptionsObject, "-pass2_die_offset",
                      "squaring: the second pass's upper die moved off its press's y axis by this along the press's x "
                      "(mm; the full model, held by the rotation hold; default 0: on the axis, whatever -die_offset "
                      "says; docs/dies.md)",
                      pass.dies.offset));
  PetscCall(read.Real(PetscOptionsObject, "-pass2_side_force",
                      "squaring: the second pass's side dies pressing with a force rising from 0 to this (N/mm, on "
                      "the whole tube) over its press, their travel an unknown of each increment (default 0: by the "
                      "stroke, whatever -side_force says; docs/dies.md)",
                      pass.dies.side_force));
  PetscCall(ReadPassRelease(PetscOptionsObject, read, "-pass2_unload",
                            "squaring: how the second pass lets the tube go: reverse, withdraw (the quarter model) "
                            "or none (the last pass only: the run ends loaded) (default: the first pass's -unload; "
                            "docs/dies.md)",
                            pass.release));
  PetscCall(ReadPassLowerMotion(PetscOptionsObject, read, "-pass2_lower_die_motion",
                                "squaring: how the second pass's lower die moves: mirror (up by the stroke, the upper "
                                "die's mirror) or fixed (it stays; the upper die travels 2 U) (default: the first "
                                "pass's -lower_die_motion; docs/dies.md)",
                                pass.lower_motion));
  PetscFunctionReturn(PETSC_SUCCESS);
}

// Pass `number` (3 to kMaxPasses): -pass<number>_stroke, _die_profile, _lower_die, _side_die, _turn, _die_offset,
// _side_force, _unload, _lower_die_motion, as the second pass's. Read (and listed by -help) where one of them is given;
// named for the hints on a misspelt option always.
PetscErrorCode ReadLaterPass(PetscOptionItems *PetscOptionsObject, OptionReader &read, int number, PassSpec &pass)
{
  const std::string pre = "-pass" + std::to_string(number) + "_";
  const std::string stroke = pre + "stroke", profile = pre + "die_profile", lower = pre + "lower_die",
                    side = pre + "side_die", turn = pre + "turn", offset = pre + "die_offset",
                    side_force = pre + "side_force", unload = pre + "unload", lower_motion = pre + "lower_die_motion";
  const std::string help = "squaring: pass " + std::to_string(number) + "'s, as -pass2_";
  bool given = false;
  PetscFunctionBeginUser;
  for (const std::string *name :
       {&stroke, &profile, &lower, &side, &turn, &offset, &side_force, &unload, &lower_motion}) {
    PetscBool set;
    PetscCall(PetscOptionsHasName(nullptr, nullptr, name->c_str(), &set));
    given = given || set;
  }
  if (!given) {
    for (const std::string *name :
         {&stroke, &profile, &lower, &side, &turn, &offset, &side_force, &unload, &lower_motion})
      read.Note(name->c_str(), (help + name->substr(pre.size()) + "'s").c_str(), PetscOptionsObject->title);
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  PetscCall(read.Real(PetscOptionsObject, stroke.c_str(), (help + "stroke").c_str(), pass.stroke));
  PetscCall(
    ReadDrawingChoice(PetscOptionsObject, read, profile.c_str(), (help + "die_profile").c_str(), pass.dies.upper));
  PetscCall(
    ReadDieChoice(PetscOptionsObject, read, lower.c_str(), (help + "lower_die").c_str(), false, pass.dies.lower));
  PetscCall(ReadDieChoice(PetscOptionsObject, read, side.c_str(), (help + "side_die").c_str(), true, pass.dies.side));
  PetscCall(
    read.Real(PetscOptionsObject, turn.c_str(), (help + "turn (from the pass before's press)").c_str(), pass.turn));
  PetscCall(read.Real(PetscOptionsObject, offset.c_str(), (help + "die_offset").c_str(), pass.dies.offset));
  PetscCall(read.Real(PetscOptionsObject, side_force.c_str(), (help + "side_force").c_str(), pass.dies.side_force));
  PetscCall(ReadPassRelease(PetscOptionsObject, read, unload.c_str(), (help + "unload").c_str(), pass.release));
  PetscCall(ReadPassLowerMotion(PetscOptionsObject, read, lower_motion.c_str(), (help + "lower_die_motion").c_str(),
                                pass.lower_motion));
  PetscFunctionReturn(PETSC_SUCCESS);
}

} // namespace

PetscErrorCode ReadToolOptions(PetscOptionItems *PetscOptionsObject, OptionReader &read, Options &opt)
{
  PetscFunctionBeginUser;
  PetscCall(ReadSecondPass(PetscOptionsObject, read, ToolsOf(opt).passes[1]));
  for (int number = 3; number <= kMaxPasses; ++number)
    PetscCall(ReadLaterPass(PetscOptionsObject, read, number, ToolsOf(opt).passes[number - 1]));
  PetscFunctionReturn(PETSC_SUCCESS);
}

} // namespace tf
