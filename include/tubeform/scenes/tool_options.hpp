// The tool scenes' own options (squaring, flattening): the model of the tube, the passes, each die's shape and
// motion, read and checked here in the scenes layer (src/scenes/options/) and handed to io's ReadOptions by the scene
// registry (ToolSceneOptions). The stroke and the release are the loading's: io/loading_options.hpp.
#pragma once

#include <petscsys.h>

#include "tubeform/core/option_reader.hpp"
#include "tubeform/io/options.hpp"
#include "tubeform/scenes/tool_scene.hpp"

namespace tf {

// The tool scenes' options, read for every scene (given to a scene without tools, they are refused by name): the
// model and the later passes in their block of -help, then each die's shape and motion in its own block
// (press_options.cpp). The registry hands these two to ReadOptions (SceneReaders).
PetscErrorCode ReadToolSceneOptions(MPI_Comm comm, OptionReader &read, Options &opt);
// Collective: refuses what the dies, the passes, the model and the release cannot take together, in one line naming
// the option, and settles what they derive (a -die_path's end is the stroke U) before the loading's checks read it.
PetscErrorCode CheckToolSceneOptions(MPI_Comm comm, Options &opt);
// -model, -full_hold into the tools' model, -die_offset into their first pass's dies (model_options.cpp).
PetscErrorCode ReadModelOptions(PetscOptionItems *PetscOptionsObject, OptionReader &read, ToolSceneParams &tools);
// Collective: refuses a model the dies cannot take (the quarter without mirrored dies, a die off the axis without the
// full model), the die's offset out of range and a support the model or the forces cannot take (after the passes'
// turns).
PetscErrorCode CheckModelOptions(MPI_Comm comm, const Options &opt);
// Collective: refuses a later pass's stroke, dies and turns out of range or that do not go together with the others'
// options (passes_check.cpp).
PetscErrorCode CheckPassStrokesAndDies(MPI_Comm comm, const Options &opt);
// Collective: pass `pass`'s strokes in turn (-stroke_path, -pass<N>_stroke_path; its last the pass's stroke): each a
// non-negative number of mm other than the one before (from 0), the last positive, by its upper die's stroke, over a
// lower die that mirrors or stays (a motion of its own follows the stroke as it rises); the first pass's not with the
// corner-radius rule, which gives its stroke too (passes_check.cpp).
PetscErrorCode CheckPassStrokePath(MPI_Comm comm, const Options &opt, int pass);
PetscErrorCode CheckPassTurns(MPI_Comm comm, const Options &opt);
// Collective: a pass's upper die moved off its press's axis by `offset` (`name`: -die_offset, -pass<N>_die_offset): a
// number of mm, the squaring scene's die (model_options.cpp).
PetscErrorCode CheckDieOffset(MPI_Comm comm, const Options &opt, const std::string &name, double offset);
// Collective: pass `pass`'s side dies (`name`: -side_die, -pass<N>_side_die; none or a shape) go with the other
// options and the pass's release.
PetscErrorCode CheckSideDies(MPI_Comm comm, const Options &opt, int pass, const std::string &name,
                             const DieChoice &side);
// The passes after the first (-pass<N>_*), between PetscOptionsBegin and PetscOptionsEnd (it needs their
// PetscOptionsObject).
PetscErrorCode ReadToolOptions(PetscOptionItems *PetscOptionsObject, OptionReader &read, Options &opt);
// The lower die's motion, its own block under the options prefix lower_die_ (-lower_die_motion: a word naming a
// kind of tool/motion.hpp; that kind's options, -lower_die_*, read by the kind): ToolsOf(opt).lower_motion
// (LowerDieSpec). An option of another of its words' kinds given is kept in its stray, refused naming it by
// CheckMotionStrays in a press (motion_checks.hpp).
PetscErrorCode ReadLowerDieMotion(MPI_Comm comm, OptionReader &read, Options &opt);
// A later pass's lower die's motion, each its own block under the prefix pass<N>_lower_die_ (-pass<N>_lower_die_motion:
// any word of -lower_die_motion; its kind's options, -pass<N>_lower_die_path, ..., read by the kind, its strokes from
// where the pass's dies start): PassSpec::lower_motion where one of them is given (unset: the first pass's). Pass 2's
// listed by -help.
PetscErrorCode ReadPassLowerMotions(MPI_Comm comm, OptionReader &read, Options &opt);
// The upper die's motion, its own block under the options prefix die_ (-die_motion: stroke, path or force, each a kind
// of tool/motion.hpp; that kind's options, -die_path, -die_path_turn, -die_pivot, -die_force, read by the kind):
// the first pass's dies' motion (ToolsOf(opt).passes[0].dies). Without -die_motion the old spellings choose: -die_path
// (or its turns or pivot) path, -die_force other than 0 force (-die_force 0 is allowed with any word). An option of
// another word's kind is kept in its stray, refused naming it by CheckMotionStrays in a press (motion_checks.hpp).
PetscErrorCode ReadUpperDieMotion(MPI_Comm comm, OptionReader &read, Options &opt);
// A later pass's upper die's motion, each its own block under the prefix pass<N>_die_ (as the first pass's: the stroke,
// or a path of its own, -pass<N>_die_path, _die_path_turn, _die_pivot, read by the path kind; in place of its
// -pass<N>_stroke, which it sets to where the path ends). Pass 2's listed by -help; a later one's where given. An
// option of another word's kind is kept in its stray (CheckMotionStrays), as the first pass's.
PetscErrorCode ReadPassMotions(MPI_Comm comm, OptionReader &read, Options &opt);
// Each pass's side dies' motion, its own block under the prefix side_ (the first pass's) or pass<N>_side_:
// -side_motion stroke (by the stroke U), fixed, path (-side_path), pulse (-side_pulse_*) or force (-side_force), each
// a kind of tool/motion.hpp offering the side dies a word (MotionKind::side_word), its options read by the kind;
// without it -side_path means path, -side_force other than 0 force. A later pass's where one of its options is given
// (default: by the stroke). An option of another word's kind is kept in its stray (CheckMotionStrays).
PetscErrorCode ReadSideMotions(MPI_Comm comm, OptionReader &read, Options &opt);
// (both in die_motion_options.cpp)
// The upper die's shape, its own block under the options prefix die_: the V-die, its options -die_angle, -die_r_apex,
// -die_u_close, -die_r_edge read by the V kind of tool/shape.hpp (and checked by it in CheckToolSceneOptions), unless
// -die_profile names a file: the first pass's dies' upper (ToolsOf(opt).passes[0].dies; die_shape_options.cpp).
PetscErrorCode ReadUpperDieShape(MPI_Comm comm, OptionReader &read, Options &opt);
// A later pass's own V-die numbers, each pass's block under the prefix pass<N>_die_ (-pass2_die_angle, _r_apex,
// _u_close, _r_edge, read by the V kind; the first pass's numbers their defaults): where one is given the pass's upper
// die is a V-die of its numbers (its -pass<N>_die_profile, where given too, the die, as the first pass's). Pass 2's
// listed by -help; a later one's where given (die_shape_options.cpp).
PetscErrorCode ReadPassShapes(MPI_Comm comm, OptionReader &read, Options &opt);
// The first pass's lower die's and side dies' shapes (ToolsOf(opt).passes[0].dies), each its own block: -lower_die
// (mirror, flat, v or a file) into its lower, -side_die (none, mirror, flat, v or a file) into its side (ShapeChoice;
// both in die_shape_options.cpp, refused where they do not go with the other options by CheckToolSceneOptions; their
// motion: ReadSideMotions). Collective: CheckSideDieOptions refuses -side_die and the side dies' motion where they do
// not go with the other options, one line naming the option (CheckToolSceneOptions).
PetscErrorCode CheckSideDieOptions(MPI_Comm comm, const Options &opt);
// Collective: pass `pass`'s side dies' motion (-side_motion, -pass<N>_side_motion; a force: -side_force, ...) other
// than the stroke only with the pass's side dies (die_shape_options.cpp).
PetscErrorCode CheckSideMotion(MPI_Comm comm, const Options &opt, int pass);
PetscErrorCode ReadLowerDieShape(MPI_Comm comm, OptionReader &read, Options &opt);
PetscErrorCode ReadSideDieShape(MPI_Comm comm, OptionReader &read, Options &opt);
// A lower or side die whose shape of its own is read (ReadDieShapeOptions): its numbers' options prefix (lower_die_,
// pass2_side_die_), its block's title in -help, the option whose word chooses the shape (-lower_die), and whether
// -help lists the block where the shape is not chosen (the first and second passes').
struct DieOwnShape {
  std::string prefix, title, word;
  bool list = false;
};
// Collective: the numbers of a die's shape of its own (a kind of the shape registry that reads options, chosen by its
// word: v) into `shape`, read by the kind in its own block under the die's prefix. A later pass's die (`first`: the
// first pass's, which it takes where its word is not given) takes its numbers as the upper die's do: the first
// pass's where that die is of the kind, else the paper's die; numbers alone give the pass the first pass's shape
// with them. A number of a shape the die is not is kept in `shape.stray` for CheckDieShapes (die_shape_options.cpp).
PetscErrorCode ReadDieShapeOptions(MPI_Comm comm, OptionReader &read, const DieOwnShape &die, const DieChoice *first,
                                   DieChoice &shape);
// The later passes' lower and side dies' numbers of their own (-pass<N>_lower_die_angle, ...; pass 2's listed by
// -help), after the first pass's dies are read (die_shape_options.cpp).
PetscErrorCode ReadPassOwnShapes(MPI_Comm comm, OptionReader &read, Options &opt);
// Collective, in a press: every pass's lower and side dies' numbers of a shape the die is not refused (naming the word
// that chooses it), and of its shape of its own refused by the kind's check against the tube, one line naming the
// option (die_shape_options.cpp).
PetscErrorCode CheckDieShapes(MPI_Comm comm, const Options &opt);
// Inside a block (its PetscOptionsObject): a die's shape by the word of `option` (ShapeChoice: mirror, flat, none where
// `none`, or a file; kept where the word is the shape's own), and the upper die's drawing by the file of `option`
// (DrawingChoice; kept where the file is its own): the first pass's dies and a later one's alike
// (die_shape_options.cpp).
PetscErrorCode ReadDieChoice(PetscOptionItems *PetscOptionsObject, OptionReader &read, const char *option,
                             const char *help, bool none, DieChoice &shape);
PetscErrorCode ReadDrawingChoice(PetscOptionItems *PetscOptionsObject, OptionReader &read, const char *option,
                                 const char *help, DieShape &shape);

} // namespace tf
