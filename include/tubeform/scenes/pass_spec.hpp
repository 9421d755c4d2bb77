// A pass of the press and its dies as the options give them (ToolSceneParams::passes; docs/passes.md): the upper die's
// shape and motion, the lower and side dies' shapes, the side dies' force, the pass's stroke and turn. The tool scenes
// read them under the pass's prefix (-die_*, -lower_die, -side_die; -pass<N>_*: tool_options.hpp) and take them
// through tool_scene.hpp (DiesOfPass, UpperDie, ...).
#pragma once

#include <cstddef>
#include <iterator>
#include <optional>
#include <string>
#include <vector>

#include "tubeform/io/press_params.hpp"
#include "tubeform/tool/motion.hpp"
#include "tubeform/tool/shape.hpp"

namespace tf {

// The word of an option's enum value among its words (the enumerators in their words' order: kUnloadWords, ...).
template <class E, size_t N>
constexpr const char *WordOf(const char *const (&words)[N], E value)
{
  return words[static_cast<size_t>(value)];
}
// The enumerator a word names among an enum's words (its enumerators' order), `otherwise` for a word not listed.
template <class E, size_t N>
E EnumOfWord(const char *const (&words)[N], const std::string &word, E otherwise)
{
  for (size_t k = 0; k < N; ++k)
    if (word == words[k]) return static_cast<E>(k);
  return otherwise;
}

// The most strokes a pass's path of strokes takes (-stroke_path, -pass<N>_stroke_path: a press's path, not a cycle
// test: a few dozen).
constexpr PetscInt kMaxPathPoints = 32;

// How a pass lets the tube go after its press (-unload, -pass<N>_unload): its contact forces reversed and the dies
// removed (the paper's), the dies moved back, or not at all. The words of the option in the enumerators' order.
enum class Unload { Reverse, Withdraw, None };
inline constexpr const char *kUnloadWords[] = {"reverse", "withdraw", "none"};

// The most passes a press takes (-pass2_* to -pass9_*): one digit in the options' names, and a press line's
// stations are a handful.
constexpr int kMaxPasses = 9;

// The upper die's motion (-die_motion; docs/motions.md): the name of a kind of the motion registry (tool/motion.hpp)
// that offers the upper die a word (MotionKind::upper_word: stroke, path, force), and what its options (-die_path,
// -die_path_turn, -die_pivot; -die_force) give it, read by the kind (scenes/options/die_motion_options.cpp). The scenes
// read it through UpperDie.
struct DieMotion {
  std::string kind = kStrokeMotion; // stroke: down by the stroke U (2 U over a fixed lower die)
  MotionSpec spec;                  // path: its points, turns, pivot; force: its punch load (N/mm)
  std::string stray; // an option of another of its words' kinds, given: its refusal (CheckMotionStrays), "" none

  // The die's stroke goes along a path of its own (its kind's MotionKind::path: path), which gives the pass's
  // stroke path and its end.
  bool OwnPath() const { return MotionOwnsPath(kind); }
};

// How the lower die's motion goes with the upper die's (-lower_die_motion): it mirrors it (mirror: up by the stroke
// U), it stays (fixed: the upper die travels 2 U), or it moves as a motion of its own says (any other word: path, or
// a kind registered after the built-in ones; the upper die travels U). The words of the enumerators before Own, in
// order (Own has the words of its kinds); each names a kind of the motion registry (MotionKind::lower_word).
enum class LowerDieMove { Mirror, Fixed, Own };
inline constexpr const char *kLowerDieMoveWords[] = {"mirror", "fixed"};
static_assert(std::size(kLowerDieMoveWords) == static_cast<size_t>(LowerDieMove::Own),
              "a word for each enumerator before Own, in order");
// The move a -lower_die_motion word says: its enumerator's, Own for a word not listed.
inline LowerDieMove LowerDieMoveOf(const std::string &word)
{
  return EnumOfWord(kLowerDieMoveWords, word, LowerDieMove::Own);
}

// The lower die's motion (-lower_die_motion; docs/motions.md): its word (mirror, fixed, path, or a kind registered
// after the built-in ones: scenes/options/die_motion_options.cpp), how it goes with the upper die's (LowerDieMoveOf the
// word), and as a DieMotion the kind of the motion registry that word names (mirror: a stroke), what its options
// (-lower_die_*) give it, read by the kind, and its stray. The scenes read it through LowerDie.
struct LowerDieSpec : DieMotion {
  std::string word = WordOf(kLowerDieMoveWords, LowerDieMove::Mirror);
  LowerDieMove move = LowerDieMove::Mirror;
};

// The paper's die: 90 degrees between the flanks, an apex fillet of 3 mm, no parting face.
inline ShapeSpec PaperVDie()
{
  ShapeSpec v;
  v.r_apex = 3.0;
  return v;
}
// The upper die's shape (docs/dies.md): a kind of the shape registry (tool/shape.hpp), the V-die unless -die_profile
// names a file (then profile, or dxf for *.dxf: DrawingKind), and its spec: the V-die's numbers, read and checked
// by the V kind under the prefix die_ (-die_angle, -die_r_apex, -die_u_close, -die_r_edge; read with a file too), and
// the file (scenes/options/die_shape_options.cpp). The scenes read it through UpperDieShape.
struct DieShape {
  std::string kind = kVShape;
  ShapeSpec spec = PaperVDie(); // (ro: the tube's, set by UpperDieShape)
  bool VDie() const { return kind == kVShape; }
};
// What a lower or side die is (docs/dies.md), as its word chose it (ShapeChoice): the upper die's mirror image
// (mirror: a relation between the tools, not a kind), a plate (flat: the flat kind, a floor below the tube or a plate
// at its side), no die (none: the side dies' only), a drawing (a file drawn as an upper die) or a shape of its own (a
// kind of the shape registry that reads options, named by its word: v, its numbers under the die's prefix,
// -lower_die_angle, ...). The words of the enumerators before Drawing, in order (a drawing's word is its file, a
// shape's its kind). Unset: a later pass's, not given (the first pass's then: DiesOfPass).
enum class DieFrom { Mirror, Plate, None, Drawing, Shape, Unset };
inline constexpr const char *kDieFromWords[] = {"mirror", "flat", "none"};
static_assert(std::size(kDieFromWords) == static_cast<size_t>(DieFrom::Drawing),
              "a word for each enumerator before Drawing, in order");
// A lower or side die's shape: what it is, and for a plate, a drawing or a shape of its own the kind of the shape
// registry that draws it (flat; the kind for a file's name, DrawingKind: profile or dxf, the file in spec.file; the
// kind its word names, its numbers in spec, read by the kind under the die's prefix: ReadDieShapeOptions). The scenes
// place and size the flat plate, read the file and draw the shape on the tube (scenes/die.cpp).
struct DieChoice {
  explicit DieChoice(DieFrom f = DieFrom::Unset) : from(f) {}
  DieFrom from;
  std::string kind; // (none for mirror and none)
  ShapeSpec spec;
  std::string stray; // a number of a shape it is not, given: its refusal (CheckDieShapes), "" none
  bool Is(DieFrom f) const { return from == f; }
  bool Given() const { return from != DieFrom::Unset; }
};
// The shape a word names (-lower_die, -side_die and their passes'): mirror, flat, none where `none` (the side dies),
// a kind of the shape registry that reads options (v: the paper's die its numbers until its options change them),
// else a file. (pass_spec.cpp)
DieChoice ShapeChoice(const std::string &word, bool none = false);
// The word back (the messages name it): its enumerator's, the file, the kind, or none ("") where unset.
std::string ShapeWord(const DieChoice &shape);
// The upper die's drawing a file names (-die_profile, -pass<N>_die_profile): its kind by the file's name
// (DrawingKind: profile, or dxf for *.dxf), the file in spec.file; unset for no file. (die_shape_options.cpp)
DieChoice DrawingChoice(const std::string &file);

// A pass's dies, the first's and a later one's alike (DiesOfPass): the upper one's shape, motion (with its path or
// force) and place off the axis, the lower and the side dies' shapes and the side dies' force. (The lower die's motion
// is the pass's: PassSpec::lower_motion, LowerDieOfPass.)
struct DieSet {
  DieShape upper;   // -die_profile, -die_angle, ... (UpperDieShape); -pass<N>_die_profile
  DieMotion motion; // -die_motion (UpperDie); -pass<N>_die_motion (ReadPassMotions)
  DieChoice lower{DieFrom::Mirror}, side{DieFrom::None}; // -lower_die, -side_die (ShapeChoice); their passes
  DieMotion side_motion; // -side_motion, -pass<N>_side_motion (stroke, fixed, path, pulse, force: each a kind of the
                         // motion registry offering a side_word), its options -side_path, -side_force, ... read by the
                         // kind; a later pass's its own (default: by the stroke), not the first pass's

  double offset = 0; // -die_offset, -pass<N>_die_offset: the upper die off its press's y axis along the press's x
                     // (mm; the full model); a later pass's its own (0: on the axis), not the first pass's

  // The force each side die presses with (N/mm, on the whole tube; -side_motion force) where they press by one, their
  // travel an unknown; 0 where they move by their motion.
  double SideForce() const { return MotionStrokeUnknown(side_motion.kind) ? side_motion.spec.force : 0.0; }
};

// A pass of the press (ToolSceneParams::passes: the first, then each after the springback of the one before): its
// stroke, its path of strokes, its turn, its dies, its lower die's motion and its release, read under the pass's
// prefix (the first's -stroke_path, -die_*, -lower_die*, -side_*, -unload; a later one's -pass<N>_*). The first pass's
// are all set; a later pass's shapes, release and lower die's motion where given, each chosen as the first pass's is
// (DrawingChoice, ShapeChoice), else unset (an upper die of kind "", a lower or side die Unset, no release or lower
// motion: the first pass's, DiesOfPass, ReleaseOfPass, LowerDieOfPass).
struct PassSpec {
  double stroke = 0; // where its upper die ends (mm, from the same zero as -stroke; 0: no such pass, or one pressed
                     // by a force: PassExtent); the first pass's is -stroke (Options::stroke, shared), 0 here
  std::vector<double> stroke_path; // its upper die's strokes in turn (mm, from the same zero), the last its stroke
                                   // (-stroke_path, -pass<N>_stroke_path; none: straight to its stroke)
  double corner_radius = 0; // the first pass's only (-stroke_corner_radius): > 0, its stroke from the paper's rule
  double turn = 0;          // the tube turned counter-clockwise before it (degrees, from the pass before's press; 0
                            // the first)
  DieSet dies;              // its dies; its upper die's motion by the stroke, or a path of its own (ReadPassMotions)
  std::optional<Unload> release; // how it lets the tube go after its press (-unload, -pass<N>_unload; ReleaseOfPass)
  std::optional<LowerDieSpec> lower_motion; // its lower die's motion (-lower_die_motion, -pass<N>_lower_die_motion;
                                            // LowerDieOfPass)
};
// The passes before any option is read: the first with the default dies, release and lower die's motion, the later
// ones with none given (unset).
inline std::vector<PassSpec> DefaultPasses()
{
  std::vector<PassSpec> passes(kMaxPasses);
  passes[0].release = Unload::Reverse, passes[0].lower_motion = LowerDieSpec{};
  for (int k = 1; k < kMaxPasses; ++k)
    passes[k].dies.upper.kind = "", passes[k].dies.lower = passes[k].dies.side = DieChoice();
  return passes;
}

} // namespace tf
