// Everything a run is told on the command line / options file, read once and
// validated up front (the names of docs/options-reference.md, which users and scripts rely on).
#pragma once

#include <petscsys.h>

#include <algorithm>
#include <any>
#include <cmath>
#include <string>
#include <vector>

#include "tubeform/body/body.hpp"
#include "tubeform/contact/contact.hpp"
#include "tubeform/contact/friction_params.hpp"
#include "tubeform/core/option_reader.hpp"
#include "tubeform/fe/quad.hpp"
#include "tubeform/io/driver_params.hpp"
#include "tubeform/io/pass_extent.hpp"
#include "tubeform/io/pass_spec.hpp"
#include "tubeform/io/press_params.hpp"
#include "tubeform/material/elastic.hpp"
#include "tubeform/tool/motion.hpp"
#include "tubeform/tool/shape.hpp"

namespace tf {

// What a scene presses the tube with (its entry's in the scene registry, scenes/registry.hpp; Options::press once
// -scene chose it): no tools (pressure, shear, ...), an upper die over a lower one (squaring: -die_offset, -die_path,
// -full_hold rotation and the later passes' -pass<N>_die_profile are its) or a flat plate (flattening).
enum class ScenePress { None, Die, Plate };

// The tool scenes' own parameters (squaring, flattening; docs/dies.md), read and checked by them
// (scenes/tool_options.hpp): the model, the passes and the lower die's motion.
struct ToolSceneParams {
  ModelParams model;         // the part modelled, its support (io/press_params.hpp)
  LowerDieSpec lower_motion; // the lower die's motion, every pass's (-lower_die_motion; LowerDie)
  // The passes: the first (-stroke, -die_*, -lower_die, -side_die), then each after the springback of the one before
  // (-pass2_* to -pass9_*; a stroke of 0: no such pass). FirstPass, LaterPass, DiesOfPass.
  std::vector<PassSpec> passes = DefaultPasses();
};

// What a run is told: the run-wide options (the scene, the tube, its mesh and element, the material, the driver, the
// estimate, the output), the loading's (the stroke, the release; more than one scene's), the friction, the tool
// scenes' own, and the chosen scene's own parameters.
struct Options {
  std::string scene = "pressure";      // a name of the scene registry (scenes/registry.hpp)
  ScenePress press = ScenePress::None; // what it presses with (its SceneOptions', set with it; PressesWithTools)
  // Geometry and mesh
  double tube_ro = 17.5, tube_t = 1.5;
  PetscInt mesh_nt = 4, mesh_ntheta = 48;
  double mesh_density = 0;     // -mesh_ntheta 0: elements around per bending length sqrt(Ro t)
  double mesh_wall_strain = 0; // -mesh_nt 0: largest change of the bending strain t/Ro across a cell
  PetscInt mesh_nt_min = 2;    // -mesh_nt 0: fewest cells through the wall
  std::string mesh_file;
  fe::Formulation element = fe::Formulation::BBar;
  std::string element_name = "bbar";
  bool element_auto = false;   // -element auto: qm6 or qm6bar from the cells through the wall (ChooseElement)
  PetscInt element_bar_nt = 5; // -element auto: qm6bar from this many cells through the wall on
  // Material
  MaterialParams material;
  // The incremental driver's (io/driver_params.hpp; read and checked by the driver).
  DriverParams driver;
  StrokeParams stroke;     // the stroke and its path (io/press_params.hpp; the tool scenes' and the column's)
  ToolSceneParams tools;   // the tool scenes' own (read and checked by them; the driver's answer reads the passes)
  FrictionParams friction; // contact and friction (contact/friction_params.hpp; the tool scenes' and the slide's)
  ReleaseParams release;   // the release after loading (io/press_params.hpp; the tool scenes' and the bending's)
  // The chosen scene's own parameters where it has any (a scene without tools: its struct of scenes/scene_params.hpp,
  // read and checked by the scene, SceneOptions), kept here so that they travel with the run's options to its levels
  // and companions; the scene reads them back with OwnParams.
  std::any scene_params;
  // Output
  std::string output = "results/tubeform.h5";
  std::string history_csv;
  PetscInt output_every = 1;
  std::string checkpoint;        // checkpoint file (empty: none)
  PetscInt checkpoint_every = 0; // increments between checkpoints (0: only when a signal or -time_limit stops the run)
  std::string restart;           // checkpoint to continue from
  double output_stroke = 0;      // > 0: fields every this much stroke (mm) instead of every output_every increments
  // The error estimate and the accuracy held to (io/driver_params.hpp; read and checked by the driver).
  AccuracyParams accuracy;
  PetscInt level = 1;     // (not an option: the level this run is, 1 the first)
  double job_started = 0; // (not an option: MPI_Wtime when the job began)
  double time_limit = 0;  // > 0: stop (results written, non-zero exit) after this many seconds of loading
  double progress = 10;   // s between progress lines on rank 0 (0: none); quiet on shorter runs
  PetscBool monitor = PETSC_FALSE;
  PetscBool allow_unused = PETSC_FALSE; // an option nothing reads is a warning, not an error
  PetscBool help = PETSC_FALSE;
  std::vector<KnownOption> known; // every option ReadOptions read (the hints for options nothing reads)
};

// The scene presses the tube with tools (squaring, flattening: the dies', stroke's and passes' options are its).
inline bool PressesWithTools(const Options &opt) { return opt.press != ScenePress::None; }
// Its upper tool is a die (squaring), not a plate (flattening).
inline bool PressesWithDie(const Options &opt) { return opt.press == ScenePress::Die; }

class OptionReader;
// A scene -scene accepts, and the reader and checker of its own options (null: it has none): the reader lists them
// in -help under "tubeform: <name> scene" (between PetscOptionsBegin and PetscOptionsEnd, whose PetscOptionsObject
// it takes) and puts them in `own` (its parameters' struct), the checker refuses their bad values in one line naming
// the option. Every scene's are read and checked, whichever runs (a bad value is refused all the same); the chosen
// scene's become Options::scene_params. The scene registry lists them.
struct SceneOptions {
  std::string name;
  ScenePress press = ScenePress::None;
  PetscErrorCode (*read)(PetscOptionItems *PetscOptionsObject, OptionReader &read, std::any &own) = nullptr;
  PetscErrorCode (*check)(MPI_Comm comm, const std::any &own) = nullptr;
};

// The reader and checker of the options of a layer above io (the driver's: driver/driver_options.hpp), handed to
// ReadOptions from above as the scenes' are: the reader lists them in -help under "tubeform: <title>" (between
// PetscOptionsBegin and PetscOptionsEnd, whose PetscOptionsObject it takes), the checker refuses their bad values in
// one line naming the option.
struct OptionGroup {
  std::string title;
  PetscErrorCode (*read)(PetscOptionItems *PetscOptionsObject, OptionReader &read, Options &opt) = nullptr;
  PetscErrorCode (*check)(MPI_Comm comm, const Options &opt) = nullptr;
};

// The reader and checker of the tool scenes' options (squaring, flattening: the model, the passes, the dies), the
// scenes layer's (scenes/tool_options.hpp): read for every scene, each block its own in -help; the check also
// settles what they derive (a -die_path's end is the stroke) before the loading's checks read it.
struct ToolSceneReaders {
  PetscErrorCode (*read)(MPI_Comm comm, OptionReader &read, Options &opt) = nullptr;
  PetscErrorCode (*check)(MPI_Comm comm, Options &opt) = nullptr;
};
// What the scene registry hands ReadOptions: the scenes -scene accepts with their own options, and the tool scenes'.
struct SceneOptionReaders {
  std::vector<SceneOptions> scenes;
  ToolSceneReaders tools;
};

// Collective: reads and validates the options; `groups` the driver's own (each its group in -help, in turn), `scenes`
// the scenes -scene accepts, with their own options, and the tool scenes'. Errors are PETSC_ERR_USER_INPUT with a
// message naming the option and what is allowed.
PetscErrorCode ReadOptions(MPI_Comm comm, const std::vector<OptionGroup> &groups, const SceneOptionReaders &scenes,
                           Options &opt);
// Collective: refuses values out of range (called by ReadOptions; `tools` the tool scenes' check, in its turn).
PetscErrorCode CheckOptions(MPI_Comm comm, const ToolSceneReaders &tools, Options &opt);
// The name of pass `pass`'s (1: the second) option `what`: -pass2_stroke, ...
std::string PassOption(int pass, const char *what);

// Elements around the quarter tube for `density` elements per bending length
// sqrt(Ro t): the wall between the die's contacts bends over that length (the
// decay length of a ring's or shell's bending under a line load), so the
// bending and the contact patch are resolved alike on any tube. Even (a node
// on the 45-degree line) and at least 8.
inline PetscInt ElementsAround(double ro, double t, double density)
{
  const double n = density * 0.5 * M_PI * ro / std::sqrt(ro * t);
  return std::max<PetscInt>(8, 2 * (PetscInt)std::ceil(0.5 * n));
}

// Cells through the wall for -mesh_nt 0: straightening the ring strains a
// fibre at y from the mid-surface by about y / R, so a cell of height t / n
// spans a bending strain of t / (n Ro); at most `strain` of it, at least `least` cells.
inline PetscInt ElementsThrough(double ro, double t, double strain, PetscInt least)
{
  return std::max<PetscInt>(least, (PetscInt)std::ceil(t / (ro * strain) - 1e-9));
}

// -element auto: the element follows the wall like its cell count. With n
// cells through a bending wall qm6 is stiff by about 1/n where the wall
// yields through its thickness (the strain through a cell is linear, the
// plastic flow's is not), qm6bar soft by about 1/n^2 where it bends
// elastically (its mean dilatation drops the linear volumetric strain of a
// bent cell); from `bar_nt` cells on the second is the smaller
// (docs/accuracy.md, "The element through the wall"). A mesh file keeps qm6.
inline void ChooseElement(Options &opt)
{
  if (!opt.element_auto) return;
  const bool bar = opt.mesh_file.empty() && opt.mesh_nt >= opt.element_bar_nt;
  opt.element = bar ? fe::Formulation::QM6Bar : fe::Formulation::QM6;
  opt.element_name = bar ? "qm6bar" : "qm6";
}

// The first pass (-stroke, -die_*, -lower_die, -side_die) and its dies as given; pass `pass` (1 the second, ...) of
// the passes after it: its -pass<pass + 1>_* options.
inline const PassSpec &FirstPass(const Options &opt) { return opt.tools.passes[0]; }
inline const DieSet &FirstDies(const Options &opt) { return opt.tools.passes[0].dies; }
inline const PassSpec &LaterPass(const Options &opt, int pass) { return opt.tools.passes[pass]; }
// How far pass `pass` presses (io/pass_extent.hpp): the first pass's stroke -stroke, a later one's its own.
inline PassExtent Extent(const Options &opt, int pass)
{
  return ExtentOf(opt.tools.passes[pass], pass, pass == 0 ? opt.stroke.u : opt.tools.passes[pass].stroke);
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
// The lower die's motion as the scenes take it: its word, kind and spec, the spec moving up (y) by the stroke.
inline LowerDieSpec LowerDie(const Options &opt)
{
  LowerDieSpec die = opt.tools.lower_motion;
  die.spec.direction = {0.0, 1.0};
  return die;
}
// It goes with the upper die's motion as `move` says (mirror, fixed or its own).
inline bool LowerDieMoves(const Options &opt, LowerDieMove move) { return opt.tools.lower_motion.move == move; }
// A pass's upper die's kind is `kind` (`dies`: a pass's, FirstDies(opt), DiesOfPass or the scene's).
inline bool DieMoves(const DieSet &dies, const char *kind) { return dies.motion.kind == kind; }
// The first pass's upper die's own path (-die_path with its turns; none unless -die_motion path).
inline ToolPath DiePath(const Options &opt)
{
  return FirstDies(opt).motion.OwnPath() ? PathOf(UpperDie(opt).spec) : ToolPath();
}
// The die's travel over the first pass in units of the stroke U (mm; -output_stroke counts it): along -stroke_path,
// half -die_path's length (ToolPath: a fixed lower die's U is half the upper one's travel), or -stroke.
inline double Travel(const Options &opt)
{
  if (FirstDies(opt).motion.OwnPath()) return DiePath(opt).end();
  double travel = opt.stroke.path.empty() ? opt.stroke.u : 0, at = 0;
  for (double u : opt.stroke.path) travel += std::abs(u - at), at = u;
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
// A die motion that leaves its press's y axis: a path with a sideways point or a turn.
inline bool MotionOffAxis(const DieMotion &m)
{
  bool off = false;
  if (m.OwnPath()) {
    for (const Vec2 &p : m.spec.points) off = off || p[0] != 0;
    for (double a : m.spec.turns) off = off || a != 0;
  }
  return off;
}
// The first pass's upper die leaves the press's y axis: -die_offset, or a -die_path with a sideways motion or a
// turn.
inline bool DieOffAxis(const Options &opt)
{
  return opt.tools.model.die_offset != 0 || MotionOffAxis(FirstDies(opt).motion);
}

// Pass `pass`'s upper die leaves its press's y axis: the first pass's as DieOffAxis says, a later one's on a path
// of its own with a sideways point or a turn.
inline bool PassOffAxis(const Options &opt, int pass)
{
  return pass == 0 ? DieOffAxis(opt) : MotionOffAxis(LaterPass(opt, pass).dies.motion);
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
// upper die's motion; the upper die drawn on the tube (UpperDieShape), its motion's reach the tube's outer radius.
inline DieSet DiesOfPass(const Options &opt, int pass)
{
  DieSet dies = FirstDies(opt);
  dies.upper.spec.ro = opt.tube_ro, dies.motion.spec.reach = opt.tube_ro; // (UpperDieShape, UpperDie)
  if (pass == 0) return dies;
  const DieSet &given = LaterPass(opt, pass).dies;
  if (given.upper.kind == kVShape) { // (its own V numbers: ReadPassShapes)
    const ShapeSpec &v = given.upper.spec;
    dies.upper.kind = kVShape, dies.upper.spec.angle = v.angle, dies.upper.spec.r_apex = v.r_apex;
    dies.upper.spec.u_close = v.u_close, dies.upper.spec.r_edge = v.r_edge;
  } else if (!given.upper.kind.empty()) {
    dies.upper.kind = given.upper.kind, dies.upper.spec.file = given.upper.spec.file;
  }
  if (given.lower.Given()) dies.lower = given.lower;
  if (given.side.Given()) dies.side = given.side;
  dies.motion = given.motion, dies.motion.spec.reach = opt.tube_ro;
  dies.side_force = given.side_force;
  return dies;
}
// Pass `pass`'s lower die's word (-lower_die, -pass<N>_lower_die: the first pass's where not given).
inline std::string PassLowerDie(const Options &opt, int pass) { return ShapeWord(DiesOfPass(opt, pass).lower); }
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
