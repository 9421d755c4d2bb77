// The squaring scene's dies from the options: the upper one (the V-die of
// -die_angle, -die_r_apex, -die_u_close, -die_r_edge, or the profile of
// -die_profile, tool/profile.hpp) with the segments the shape metrics use,
// and the lower one of -lower_die.
#pragma once

#include "tubeform/metrics/shape.hpp"
#include "tubeform/scenes/common.hpp"
#include "tubeform/scenes/tool_scene.hpp"
#include "tubeform/tool/tool.hpp"

namespace tf {

struct Die {
  Tool tool;
  int flank = 0; // the straight segment C/t is measured against
  int apex = -1; // the fillet before it, -1 if none
};

// Collective: the upper die of `shape` (the V-die, or a drawing: -die_profile, -pass<N>_die_profile), or an error on
// every rank (a profile is read on rank 0 and parsed on each).
PetscErrorCode BuildDie(MPI_Comm comm, const DieShape &shape, Die &die);

// The flat lower die reaches this far past the axis and past the tube's outer radius (fractions of Ro): a
// tube squared on it widens by less than half its radius.
constexpr double kFloorOverhang = 0.1, kFloorReach = 0.6;
// Collective: pass `pass`'s lower die of `shape` (its -lower_die: the upper die's mirror, a flat floor at y = floor_y,
// or a profile file drawn as an upper die and mirrored below the tube) with its motion (LowerDieOfPass), the upper
// die's motion with it; in the full model (`part`) on both sides of the y axis.
PetscErrorCode BuildLowerDie(MPI_Comm comm, const Options &opt, int pass, DieChoice shape, Tool &upper, double floor_y,
                             TubePart part, Tool &lower);

// Collective: tool t's motion of the registry's kind `kind` made from `spec` (tool/motion.hpp), or an error on
// every rank naming `option`.
PetscErrorCode SetMotion(MPI_Comm comm, const char *option, const std::string &kind, const MotionSpec &spec, Tool &t);
// Collective: pass `pass`'s lower die's motion (-lower_die_motion, -pass<N>_lower_die_motion: LowerDieOfPass), and
// the upper die's that goes with it (die_motion.cpp).
PetscErrorCode SetLowerMotion(MPI_Comm comm, const Options &o, int pass, Tool &upper, Tool &lower);
// Pass `pass`'s lower die's motion as drawn (up: y), or the mirror's where the options make none (the run refuses
// them: SetLowerMotion); and the upper die's travel per unit U that goes with it (2 over a fixed one).
MotionHandle LowerDieMotion(const Options &o, int pass);
double UpperTravel(const Options &o, int pass);
// Pass `pass`'s lower die's motion keeps the dies closing by 2 U (mirror, fixed): the closed forms of their reach
// hold.
bool LowerDieClosing(const Options &o, int pass);
// The strokes below `until` where a pass's upper die's motion `die` changes piece, as its kind says (Motion::Kinks:
// a path's points; none by the stroke or a force).
std::vector<double> UpperKinks(const DieMotion &die, double until);
// The strokes below `until` (of the pass's tools, from where its dies start) where pass `pass`'s lower die's motion (in
// the half and full models) and its side dies' change piece (Motion::Kinks: a path's points, a pulse's half periods;
// none by the stroke, fixed or a force).
std::vector<double> ToolKinks(const Options &opt, int pass, double until);
// The strokes below `until` where the first pass's dies' motions turn (Motion::Kinks: the upper die's path, the
// lower die's motion in the half and full models): the load path's kinks (an increment ends there).
std::vector<double> PressKinks(const Options &opt, double until);
// Collective: a pass's upper die on its own motion `die` (a path, turning about its pivot; a force), or an error on
// every rank naming `option`; by the stroke, the motion its lower die's gives it (SetLowerMotion).
PetscErrorCode SetUpperMotion(MPI_Comm comm, const char *option, const DieMotion &die, Tool &upper);
// Collective: pass `pass`'s side dies (tools from first_side on) on their motion (-side_motion, -pass<N>_side_motion:
// DiesOfPass), where it is not the stroke they are drawn with; an error on every rank naming the option.
PetscErrorCode SetSideMotions(MPI_Comm comm, const Options &opt, int pass, size_t first_side, std::vector<Tool> &tools);

// The flattening scene's plate reaches past the ring on both sides (fractions of Ro): a crushed ring widens by
// much less than half its radius.
constexpr double kPlateOverhang = 0.1, kPlateReach = 0.5;
// Collective: the dies of a pass (DiesOfPass: the first pass's and a later one's alike): the upper one (the squaring
// scene's die, or the flattening scene's plate) on its own motion and, in the half (and full) model `part`, the lower
// one (a floor at floor_y); in the full model both reaching across the y axis; its side dies; the upper die moved off
// the axis by the pass's offset (after the lower and side dies drawn from it); a later pass's named pass<N>-<name>.
// `flank` and `apex`: the upper die's segments the shape metrics use (of its right half).
PetscErrorCode BuildPassDies(MPI_Comm comm, const Options &opt, int pass, bool squaring, TubePart part, double floor_y,
                             std::vector<Tool> &tools, int &flank, int &apex);
// A later pass's dies start where the first pass's started (on the round tube's circle) or,
// where that is inside the tube's outer surface `outer` as the springback of pass `before` left it (wider than round
// along their motion: an oval, a turned square), moved back along their motion until they touch it (`back`: how far, in
// units of stroke, each tool; with `say`, a line printed for each); an error on every rank for a die that cannot be
// moved back clear of the tube (one that stays: its motion is none). A force-controlled die clear of the tube starts
// ahead, where it touches it (`back` < 0).
PetscErrorCode StartOnTube(MPI_Comm comm, bool say, const std::vector<SurfacePoint> &outer, std::vector<Tool> &tools,
                           std::vector<double> &back, int before);
// Collective: a pass's upper die, drawn `offset` off its press's axis (-die_offset, -pass<N>_die_offset:
// BuildPassDies) and turned with the tube, moved back along its motion until it touches the round tube's outer
// surface `outer` where it is inside it: the pass's zero (with `say`, a line printed); an error on every rank if it
// cannot be moved clear.
PetscErrorCode StartOffAxis(MPI_Comm comm, bool say, const std::vector<SurfacePoint> &outer, double offset, Tool &die);
// Collective: a pass's side dies (`shape`, read from `option`: -side_die or -pass<N>_side_die) appended to
// `tools`: the right one (for mirror the squaring scene's upper die, whose right half is `upper_right`, or the
// flattening scene's plate; a plate; or a profile drawn as an upper die), turned to the side by the reflection
// about y = x, moving along -x by the stroke; whole in the half and full models (`part`); in the full model, its
// mirror on the left too.
PetscErrorCode AddSideDies(MPI_Comm comm, const Options &o, DieChoice shape, const char *option, bool squaring,
                           const Tool &upper_right, TubePart part, std::vector<Tool> &tools);
// The map that draws a pass's dies, built in its press's frame, into the tube's: -pass2_turn turns the tube
// before the second pass, -pass3_turn on from there before the third, ..., so its dies turn the other way about
// the tube's centre by the turns summed (PassTurnDegrees; the full model: by any angle,
// TurnMap::TurnBy, unless a whole number of quarter turns). The quarter and the half model
// draw the turned dies by the reflection that keeps their symmetry planes (the same press, by the tube's
// symmetry): the quarter's quarter turn is the reflection about y = x, the half's half turn y -> -y.
TurnMap PassTurn(const Options &opt, int pass, TubePart part);

// Collective: refuses a stroke the dies `dies` of a pass (DiesOfPass) cannot take, naming `option`: past the parting
// faces, past the point where the cavity between two V-dies is smaller than the tube's cross-section (plane strain
// plasticity keeps the area), or (the flattening plates) past the point where the ring's walls meet (no
// self-contact is modelled). A profile of one's own or another lower die has no closed form of its cavity: a
// stroke that closes it fails in the run.
PetscErrorCode CheckDieReach(MPI_Comm comm, const Options &o, int pass, const DieSet &dies, bool squaring,
                             double stroke, const char *option);
// Collective: CheckDieReach for a press's passes: the first pass's deepest stroke (-stroke, or -stroke_path's) and
// each later one's; not a pass's pressed with a force, whose stroke is its outcome (PassExtent).
PetscErrorCode CheckPressReach(MPI_Comm comm, const Options &opt, bool squaring, double deepest);
// Collective: a warning if pass `pass`'s (0 the first) dies, at its end (stroke mm), touch nothing: its
// stroke was shorter than the way to the tube.
PetscErrorCode WarnUntouched(MPI_Comm comm, const ContactSet &contact, int pass, double stroke);
// Collective: the note of the paper's stroke rule (-stroke_corner_radius): the stroke a corner radius gives.
PetscErrorCode NoteCornerRadius(MPI_Comm comm, double stroke, double corner_radius);
// The first stroke CheckDieReach refuses for pass `pass`'s dies (the dies closing on the tube, their parting faces
// meeting, the ring's walls meeting); kNever where there is no closed form (a profile, another lower die).
double DieReach(const Options &o, int pass, const DieSet &dies, bool squaring);
// Collective: a pass's force-controlled die (-die_force, -pass<N>_die_force; `e` the pass's extent) at `stroke` (its
// U) that has come down to `reach`, its dies' DieReach, stops the run (PETSC_ERR_NOT_CONVERGED: inside an increment,
// the results so far are written).
PetscErrorCode CheckForceReach(MPI_Comm comm, const PassExtent &e, double reach, bool squaring, double stroke);

} // namespace tf
