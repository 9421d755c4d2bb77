// The tool scenes' own parameters (squaring, flattening; docs/dies.md) as their options give them: the part of the
// tube modelled, the lower die's motion and the passes with their dies; and what the scenes, their options' checks and
// the driver ask of them (the passes' dies, extents and turns, the model the passes' tools choose). Read and checked
// by the tool scenes (scenes/tool_options.hpp); Options carries them opaque (Options::tools), read back with ToolsOf.
#pragma once

#include <any>
#include <cmath>
#include <string>
#include <vector>

#include "tubeform/io/options.hpp"
#include "tubeform/scenes/pass_extent.hpp"
#include "tubeform/scenes/pass_spec.hpp"

namespace tf {

// The part of the tube the tool scenes model (-model): the quarter where it is exact (auto: ModelOf, which picks
// the half or the full otherwise), or the one asked for.
enum class TubeModel { Auto, Quarter, Half, Full };
inline constexpr const char *kModelWords[] = {"auto", "quarter", "half", "full"};
// The full model's support (-full_hold): auto (ModelChoice::HeldByRotation), its axis pins, or the rotation hold.
enum class FullHold { Auto, Pins, Rotation };
inline constexpr const char *kFullHoldWords[] = {"auto", "pins", "rotation"};

// The model (-model, -full_hold): the part of the tube modelled and the full model's support. A die off the axis
// (DieSet::offset, a sideways path), which only the full model takes, held by the rotation hold, chooses them with the
// passes' turns (ModelOf).
struct ModelParams {
  TubeModel part = TubeModel::Auto;    // quarter, half, full, or auto: the quarter where it is exact
  FullHold full_hold = FullHold::Auto; // the full model's support: pins, rotation (the rotation hold), auto
};

// The tool scenes' own parameters (squaring, flattening; docs/dies.md), read and checked by them
// (scenes/tool_options.hpp): the model and the passes (each with its dies, their motions and its release).
struct ToolSceneParams {
  ModelParams model; // the part modelled, its support
  // The passes: the first (-stroke, -stroke_path, -die_*, -lower_die*, -side_*, -unload), then each after the
  // springback of the one before (-pass2_* to -pass9_*; a stroke of 0: no such pass). FirstPass, LaterPass, DiesOfPass.
  std::vector<PassSpec> passes = DefaultPasses();
};

// The run's tool scenes' parameters (Options::tools), or the built-in ones where the options hold none (options built
// in code); the writable one makes them first where they are not there yet (their readers).
inline const ToolSceneParams &ToolsOf(const Options &opt) { return HeldOr<ToolSceneParams>(opt.tools); }
inline ToolSceneParams &ToolsOf(Options &opt)
{
  if (!std::any_cast<ToolSceneParams>(&opt.tools)) opt.tools = ToolSceneParams{};
  return *std::any_cast<ToolSceneParams>(&opt.tools);
}

// The first pass (-stroke, -die_*, -lower_die, -side_die) and its dies as given; pass `pass` (1 the second, ...) of
// the passes after it: its -pass<pass + 1>_* options.
inline const PassSpec &FirstPass(const Options &opt) { return ToolsOf(opt).passes[0]; }
inline const DieSet &FirstDies(const Options &opt) { return ToolsOf(opt).passes[0].dies; }
inline const PassSpec &LaterPass(const Options &opt, int pass) { return ToolsOf(opt).passes[pass]; }
// How far pass `pass` presses (scenes/pass_extent.hpp): the first pass's stroke -stroke, a later one's its own.
inline PassExtent Extent(const Options &opt, int pass)
{
  return ExtentOf(ToolsOf(opt).passes[pass], pass, pass == 0 ? opt.stroke.u : ToolsOf(opt).passes[pass].stroke);
}
// Some pass presses with a force (its stroke the outcome).
inline bool AnyPassForced(const Options &opt)
{
  bool forced = false;
  for (int pass = 0; pass < kMaxPasses; ++pass) forced = forced || Extent(opt, pass).Forced();
  return forced;
}

// The first pass's upper die's motion as the scenes take it: its kind and spec, the spec's reach the tube's outer
// radius (a turn counted in the path's length as the arc of a point there).
inline DieMotion UpperDie(const Options &opt)
{
  DieMotion die = FirstDies(opt).motion;
  die.spec.reach = opt.tube_ro;
  return die;
}
// The first pass's upper die's shape as the scenes take it: its kind and spec, drawn on the tube (the spec's ro its
// outer radius). A later pass's takes its numbers (DiesOfPass).
inline DieShape UpperDieShape(const Options &opt)
{
  DieShape die = FirstDies(opt).upper;
  die.spec.ro = opt.tube_ro;
  return die;
}
// It is the V-die (not drawn from a file).
inline bool VDie(const Options &opt) { return FirstDies(opt).upper.VDie(); }
// Pass `pass`'s lower die's motion as the options give it (-lower_die_motion, or a later pass's
// -pass<N>_lower_die_motion where given), read without a copy.
inline const LowerDieSpec &LowerDieAsGiven(const Options &opt, int pass)
{
  const std::optional<LowerDieSpec> &own = ToolsOf(opt).passes[pass].lower_motion;
  return own ? *own : *FirstPass(opt).lower_motion;
}
// As the scenes take it: its word, kind and spec, the spec moving up (y) by the stroke.
inline LowerDieSpec LowerDieOfPass(const Options &opt, int pass)
{
  LowerDieSpec die = LowerDieAsGiven(opt, pass);
  die.spec.direction = {0.0, 1.0};
  return die;
}
// The first pass's.
inline LowerDieSpec LowerDie(const Options &opt) { return LowerDieOfPass(opt, 0); }
// Pass `pass`'s lower die goes with the upper die's motion as `move` says (mirror, fixed or its own).
inline bool LowerDieMoves(const Options &opt, int pass, LowerDieMove move)
{
  return LowerDieAsGiven(opt, pass).move == move;
}
// A pass's upper die's kind is `kind` (`dies`: a pass's, FirstDies(opt), DiesOfPass or the scene's).
inline bool DieMoves(const DieSet &dies, const char *kind) { return dies.motion.kind == kind; }
// A die's motion (a pass's side dies': DieSet::side_motion) is of the kind `kind`.
inline bool DieMoves(const DieMotion &motion, const char *kind) { return motion.kind == kind; }
// The first pass's upper die's own path (-die_path with its turns; none unless -die_motion path).
inline ToolPath DiePath(const Options &opt) { return MotionPathOf(FirstDies(opt).motion.kind, UpperDie(opt).spec); }
// The die's travel over the first pass in units of the stroke U (mm; -output_stroke counts it): along -stroke_path,
// half -die_path's length (ToolPath: a fixed lower die's U is half the upper one's travel), or -stroke.
inline double Travel(const Options &opt)
{
  if (FirstDies(opt).motion.OwnPath()) return DiePath(opt).end();
  const std::vector<double> &path = FirstPass(opt).stroke_path;
  double travel = path.empty() ? opt.stroke.u : 0, at = 0;
  for (double u : path) travel += std::abs(u - at), at = u;
  return travel;
}
// -die_path moves the first pass's die sideways somewhere.
inline bool DiePathSideways(const Options &opt)
{
  if (!FirstDies(opt).motion.OwnPath()) return false;
  for (const Vec2 &p : FirstDies(opt).motion.spec.points)
    if (p[0] != 0) return true;
  return false;
}
// A die motion that leaves its press's y axis, as its kind says (MotionKind::off_axis: a path with a sideways point or
// a turn).
inline bool MotionOffAxis(const DieMotion &m) { return MotionLeavesAxis(m.kind, m.spec); }
// The first pass's upper die leaves the press's y axis: -die_offset, or a -die_path with a sideways motion or a
// turn (PassOffAxis of the first pass).
inline bool DieOffAxis(const Options &opt)
{
  return FirstDies(opt).offset != 0 || MotionOffAxis(FirstDies(opt).motion);
}

// Pass `pass`'s upper die leaves its press's y axis: moved off it (-die_offset, -pass<N>_die_offset), or on a path
// of its own with a sideways point or a turn.
inline bool PassOffAxis(const Options &opt, int pass)
{
  const DieSet &dies = ToolsOf(opt).passes[pass].dies;
  return dies.offset != 0 || MotionOffAxis(dies.motion);
}
// Pass `pass`'s upper die or an earlier pass's leaves its press's axis (the tube is then pressed off its mirror
// symmetry from that pass on). Every pass's options count, given or not, as in ModelOf below.
inline bool OffAxisBy(const Options &opt, int pass)
{
  bool off = false;
  for (int k = 0; k <= pass; ++k) off = off || PassOffAxis(opt, k);
  return off;
}
// The passes: the first and each later one given (a stroke, a path or a force: PassExtent), in turn (the options
// refuse a gap).
inline int PassCount(const Options &opt)
{
  int n = 1;
  while (n < kMaxPasses && Extent(opt, n).Given()) ++n;
  return n;
}
// A pass's turn of the tube from the first pass's press (degrees): the turns before it and its own, summed.
inline double PassTurnDegrees(const Options &opt, int pass)
{
  double turn = 0;
  for (int k = 1; k <= pass; ++k) turn += LaterPass(opt, k).turn;
  return turn;
}
// That turn in quarter turns (rounded), and whether it is whole.
inline int PassQuarters(const Options &opt, int pass) { return (int)std::lround(PassTurnDegrees(opt, pass) / 90.0); }
inline bool QuarterTurn(const Options &opt, int pass)
{
  return PassTurnDegrees(opt, pass) == 90.0 * PassQuarters(opt, pass);
}
// Pass `pass`'s dies (0 the first; the scene's passes are built from these alike): the first pass's (-die_*,
// -lower_die, -side_die), a later one's where its -pass<N>_die_profile, _lower_die, _side_die give them and its
// upper die's motion and offset (its own: 0 where not given); the upper die drawn on the tube (UpperDieShape), its
// motion's reach the tube's outer radius.
inline DieSet DiesOfPass(const Options &opt, int pass)
{
  DieSet dies = FirstDies(opt);
  dies.upper.spec.ro = opt.tube_ro, dies.motion.spec.reach = opt.tube_ro; // (UpperDieShape, UpperDie)
  if (pass == 0) return dies;
  const DieSet &given = LaterPass(opt, pass).dies;
  if (given.upper.kind == kVShape) // (its own V-die: the first pass's numbers and its own, ReadPassShapes)
    dies.upper = given.upper, dies.upper.spec.ro = opt.tube_ro;
  else if (!given.upper.kind.empty())
    dies.upper.kind = given.upper.kind, dies.upper.spec.file = given.upper.spec.file;
  if (given.lower.Given()) dies.lower = given.lower;
  if (given.side.Given()) dies.side = given.side;
  dies.motion = given.motion, dies.motion.spec.reach = opt.tube_ro;
  dies.side_motion = given.side_motion, dies.offset = given.offset;
  return dies;
}
// Pass `pass`'s lower die's word (-lower_die, -pass<N>_lower_die: the first pass's where not given).
inline std::string PassLowerDie(const Options &opt, int pass) { return ShapeWord(DiesOfPass(opt, pass).lower); }
// Pass `pass`'s strokes in turn (-stroke_path, -pass<N>_stroke_path; none: straight to its stroke).
inline const std::vector<double> &StrokePathOf(const Options &opt, int pass)
{
  return ToolsOf(opt).passes[pass].stroke_path;
}
// Pass `pass`'s release after its press (-unload, -pass<N>_unload: the first pass's where not given).
inline Unload ReleaseOfPass(const Options &opt, int pass)
{
  return ToolsOf(opt).passes[pass].release.value_or(*FirstPass(opt).release);
}
// The option that gives pass `pass`'s release: its own -pass<N>_unload, or the first pass's -unload it takes.
inline std::string ReleaseOption(const Options &opt, int pass)
{
  return pass > 0 && LaterPass(opt, pass).release ? PassOptionName(pass, "unload") : "-unload";
}
// What the choice of the model reads of a pass's tools (ModelOf; every pass's, given or not: a pass given without
// its stroke is refused after the model is chosen). Side dies press both sides alike: they choose nothing.
struct PassSymmetry {
  bool mirrored = true;     // its lower die mirrors the upper one in shape and motion (its press symmetric about x)
  bool off_axis = false;    // its upper die or an earlier pass's leaves its press's y axis (OffAxisBy)
  int quarters = 0;         // its turn from the first pass's press in quarter turns, rounded (PassQuarters)
  bool quarter_turn = true; // that turn is whole quarter turns (QuarterTurn)
};
// The part of the tube the tool scenes model and how the full model is held, from every pass's dies and turns
// (ModelOf: the options check and the scenes' set-up read it alike).
struct ModelChoice {
  std::vector<PassSymmetry> passes; // every pass's (kMaxPasses)
  TubeModel part = TubeModel::Auto; // -model's, or the one auto picks: the quarter where exact, else the half where
                                    // exact, else the full (never Auto)
  FullHold hold = FullHold::Auto;   // -full_hold
  // Every pass's lower die mirrors the upper one in shape and motion (what -model quarter needs).
  bool Mirrored() const;
  // The quarter is exact: mirrored, every die on its press's axis, every pass turned by whole quarter turns.
  bool QuarterExact() const;
  // The half (x >= 0) is exact: every die on its press's axis, every pass turned by an even number of quarter turns
  // (its plane x = 0 a symmetry plane of each press).
  bool HalfExact() const;
  // Pass `pass` (0 the first) of the full model held by the rotation hold (scenes/hold.hpp) rather than its pins:
  // asked, or (auto) where the pins would hold the tube's slide against the dies: a pass with a die off the axis,
  // and every pass after it; a pass turned by an angle that is no quarter turn, or turned by an odd number of quarter
  // turns from an earlier pass not symmetric about its press's x axis (a lower die that does not mirror the upper
  // one).
  bool HeldByRotation(int pass) const;
  // The tube in pass `pass`'s press is not mirrored about the press's y axis (what makes the auto hold the rotation
  // hold): a die off the axis in it or before it, a turn that is no quarter turn, an odd number of quarter turns from
  // an earlier pass not mirrored top to bottom.
  bool OffSymmetry(int pass) const;
  // Pass `pass`'s two side dies meet the tube alike (their forces and travels equal: side dies pressed by a force,
  // each travelling its own way, need it): the tube mirrored about the press's y axis, or the same under a half turn
  // (every pass up to it mirrored top to bottom, no die off the axis).
  bool SidesAlike(int pass) const;
};
// The model the options and the passes' tools choose (model_options.cpp).
ModelChoice ModelOf(const Options &opt);
// The tool scenes model a quarter of the tube: -model quarter, or auto where it is exact.
inline bool QuarterModel(const Options &opt) { return ModelOf(opt).part == TubeModel::Quarter; }
// The whole tube: -model full, or auto where neither the quarter nor the half is exact.
inline bool FullModel(const Options &opt) { return ModelOf(opt).part == TubeModel::Full; }
// Pass `pass` of the full model is held by the rotation hold (ModelChoice::HeldByRotation).
inline bool HeldByRotation(const Options &opt, int pass) { return ModelOf(opt).HeldByRotation(pass); }
} // namespace tf
