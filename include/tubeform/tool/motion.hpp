// How a rigid tool moves (docs/motions.md): where its stroke has moved it, how far it has turned it, its motion per
// unit stroke on the piece it follows, whether its stroke is an unknown found from a force. One kind per file
// (src/tool/motion_*.cpp): the motion, the options it reads under its tool's options prefix, how it is made;
// each named in the registry (motion_registry.cpp). Geometry, and PETSc only to read the options.
//
// A motion's only state between increments is its tool's stroke (Tool::stroke, which the contact set persists for
// a restart) and the piece it follows, which Follow takes again from the stroke at each increment's start
// (ContactSet::SetStroke); the rest is its configuration, made again from the options on a restart.
#pragma once

#include <petscsys.h>

#include <memory>
#include <string>
#include <vector>

#include "tubeform/core/core.hpp"
#include "tubeform/tool/path.hpp"
#include "tubeform/tool/turn_map.hpp"

namespace tf {

// The strokes of `strokes` (rising) below `until`: a motion's kinks within the press (Motion::Kinks).
inline std::vector<double> KinksBelow(const std::vector<double> &strokes, double until)
{
  std::vector<double> k;
  for (double s : strokes)
    if (s < until) k.push_back(s);
  return k;
}

class Motion {
public:
  virtual ~Motion() = default;
  virtual std::unique_ptr<Motion> Clone() const = 0;
  // Its name in the registry (fixed, stroke, path, force, ...).
  virtual std::string Kind() const = 0;
  // Where the stroke s has moved the tool from its drawing.
  virtual Vec2 Offset(double s) const = 0;
  // How far the stroke s has turned it about its frame's origin (radians, counter-clockwise).
  virtual double Turn(double /*s*/) const { return 0.0; }
  // How far the stroke s has moved it along its motion's axis (in units of that axis, as Offset = Travel x axis for
  // a motion along one line): a stroke's and a force's s, a pulse's s less its wave, a schedule's distance along
  // its direction, 0 for a tool that stays (the side dies' travel, the history's side_stroke).
  virtual double Travel(double s) const { return s; }
  // Per unit stroke on the piece it follows: the motion of its frame's origin, and its turn about it.
  virtual Vec2 Direction() const = 0;
  virtual double Spin() const { return 0.0; }
  // The line it is moved back along to start clear of the piece (MovedBack): a schedule's and a pulse's own axis,
  // whatever piece they start on; else the piece it follows.
  virtual Vec2 Axis() const { return Direction(); }
  // Takes the piece a step from stroke s runs on (a step never crosses a kink).
  virtual void Follow(double /*s*/) {}
  // The strokes below `until` where it changes piece, rising: an increment ends there (Scene's LoadPath::kinks).
  virtual std::vector<double> Kinks(double /*until*/) const { return {}; }
  // Its stroke is an unknown of each increment, found from the force it presses with (force control), not the
  // scene's stroke.
  virtual bool Unknown() const { return false; }
  // The same motion for the tool drawn mapped by `map` (its directions mapped, its turns with the orientation).
  virtual void Map(const TurnMap &map) = 0;
};

// A motion held by value: copied with its tool (the second pass's dies, mirrored and side dies are copies).
class MotionHandle {
public:
  MotionHandle(); // a stroke straight down: (0, -1) per unit stroke
  MotionHandle(std::unique_ptr<Motion> m) : m_(std::move(m)) {}
  MotionHandle(const MotionHandle &o) : m_(o.m_->Clone()) {}
  MotionHandle(MotionHandle &&) = default;
  MotionHandle &operator=(const MotionHandle &o)
  {
    if (this != &o) m_ = o.m_->Clone();
    return *this;
  }
  MotionHandle &operator=(MotionHandle &&) = default;
  Motion *operator->() { return m_.get(); }
  const Motion *operator->() const { return m_.get(); }
  const Motion &operator*() const { return *m_; }

private:
  std::unique_ptr<Motion> m_;
};

// The kinds, one file each.
// fixed: stays where it is drawn (motion_fixed.cpp).
std::unique_ptr<Motion> FixedMotion();
// stroke: moves by the stroke along `direction` per unit stroke (motion_stroke.cpp); its kind's name, the upper
// die's motion unless another is chosen.
std::unique_ptr<Motion> StrokeMotion(const Vec2 &direction);
inline constexpr const char *kStrokeMotion = "stroke";
// The path and force kinds' names (what the options' old spellings -die_path and -die_force choose; the side dies'
// force control).
inline constexpr const char *kPathMotion = "path";
inline constexpr const char *kForceMotion = "force";
// path: along a path of its own, turning about its frame's origin as the path says (motion_path.cpp: the upper
// die's -die_motion path; the lower die's -lower_die_motion path is the schedule below).
std::unique_ptr<Motion> PathMotion(const ToolPath &path);
// force: along `direction`, its stroke an unknown found from the force it presses with (motion_force.cpp).
std::unique_ptr<Motion> ForceMotion(const Vec2 &direction);

// schedule: through displacements `to` at strokes `at` (rising from 0), standing after the last, its travel counted
// along `axis` (none: 0); "" or why not (motion_schedule.cpp).
std::string ScheduleMotion(const std::vector<double> &at, const std::vector<Vec2> &to, MotionHandle &m,
                           const Vec2 &axis = {0.0, 0.0});

// What a kind of motion is made from (each kind reads what it needs).
struct MotionSpec {
  std::string tool = "the tool"; // whose motion it is, as its reader's refusals name it ("the lower die")
  Vec2 direction{0, -1};         // stroke, force, schedule: per unit stroke (the tool's, given by its scene)
  std::vector<Vec2> points;      // path: its points in turn from where it starts (what -<prefix>path gives)
  std::vector<double> turns;     // and its turns there (degrees, counter-clockwise; none: it does not turn)
  std::vector<double> pivot;     // the point x, y it turns about (where it starts; none: its frame's origin)
  double reach = 0;              // a turn counted in the path's length at this reach (mm, > 0 with turns)
  std::vector<double> at;        // schedule: the strokes
  std::vector<Vec2> to;          // and the displacements there
  std::vector<double> along;     // or its distances there along `direction` (what -<prefix>path gives)
  double force = 0;              // force: the force it presses with at the end (what -<prefix>force gives)
  std::vector<double> own;       // a kind's own numbers, as its reader reads them (its file says which)
};

// The name of pass `pass`'s option `what` (0 the first pass, whose options carry no number): -side_force,
// -pass2_side_force, ... (every pass's options are named so, the dies' and the scene's alike).
inline std::string PassOptionName(int pass, const char *what)
{
  return pass == 0 ? std::string("-") + what : Formatted("-pass%d_%s", pass + 1, what);
}

// What a kind's press check (MotionKind::press_check) reads of the press whose upper die it moves: the tool scenes
// fill it from their options (scenes/motion_checks.hpp); the kind refuses there what it cannot do.
struct MotionPress {
  std::string prefix;         // its options' prefix, dashed: "-die_", "-pass2_die_" (-die_path, -pass2_die_force)
  std::string scene;          // the scene's name
  bool dies = true;           // the scene presses with dies (squaring), not plates
  bool tools = true;          // the scene presses with tools, dies or plates (squaring, flattening)
  int pass = 0;               // the pass (0 the first)
  bool quarter = true;        // the quarter model
  bool lower_stays = false;   // the lower die stays (-lower_die_motion fixed)
  std::string withdrawn_by;   // the option that withdraws the pass's dies (-unload, -pass<N>_unload; "": not so)
  bool stroke_given = false;  // a later pass's stroke given as well (-pass<N>_stroke)
  bool stroke_path = false;   // the first pass's stroke along -stroke_path
  bool corner_radius = false; // the first pass's stroke from -stroke_corner_radius
  bool side_dies = false;     // side dies in the pass (-side_die, -pass<N>_side_die)
  bool die_offset = false;    // the pass's die moved off its axis (-die_offset, -pass<N>_die_offset)
  bool off_axis = false;      // the pass's die leaves its press's y axis (a sideways point or a turn)
  bool held = false;          // the pass is held by the rotation hold (the full model's)
  // The pass's option `what` (PassOptionName).
  std::string Option(const char *what) const { return PassOptionName(pass, what); }
};
// A kind's press check: "" or its refusal, one line naming the option and what goes with it.
using MotionPressCheck = std::string (*)(const MotionSpec &spec, const MotionPress &press);

// The path of a path motion's spec: through its points, turned by its turns (radians in the path) counted at its
// reach (none where it has turns but no reach > 0) (motion_path.cpp).
ToolPath PathOf(const MotionSpec &spec);
// The point a path motion's spec turns about: its pivot, or its frame's origin where it names none.
inline Vec2 PivotOf(const MotionSpec &spec)
{
  return spec.pivot.size() == 2 ? Vec2{spec.pivot[0], spec.pivot[1]} : Vec2{0.0, 0.0};
}

// A kind's reader: its options, under the options prefix of the PetscOptionsBegin block it is called in (the
// tool's: "lower_die_" reads -lower_die_path as "-path"), into `spec`; a bad or missing value refused in one line
// naming the full option. Under -help it lists them and refuses nothing.
using MotionReader = PetscErrorCode (*)(PetscOptionItems *PetscOptionsObject, MotionSpec &spec);
// A kind's factory: the motion from `spec` into `m`; "" or why not.
using MotionFactory = std::string (*)(const MotionSpec &spec, MotionHandle &m);
// A kind in the registry: its name, its options' names under a prefix (without the dash), its reader (none: it
// reads nothing) and its factory; the word -lower_die_motion offers it under (none: the lower die does not take it)
// and what the lower die then does in -help's words (none: "moves as its motion <word> says", naming its options
// under each pass's prefix: a kind that reads options gives none); the word
// -die_motion and -pass<N>_die_motion offer it under (none: the upper die does not take it); the word -side_motion and
// -pass<N>_side_motion offer it under (none: the side dies do not take it); and what the press asks
// of a kind before its motion is made (by the kind's name: MotionOwnsPath, MotionStrokeUnknown), so that no one
// compares names: path, the path its tool's stroke goes along, for a kind that carries one (path: a pass's stroke path
// and end are the path's; none: the tool goes by the scene's stroke), and unknown_stroke, its stroke is an unknown
// found from a force (force, as its Motion::Unknown says); its press check (none: it goes with every press); and
// whether the spec takes the tool off its press's y axis (off_axis; none: it stays on it), which chooses the model.
// Each kind's file defines its own (FixedKind(), ..., the registry lists them).
struct MotionKind {
  const char *name;
  std::vector<std::string> options;
  MotionReader read;
  MotionFactory make;
  const char *lower_word = nullptr;
  const char *lower_help = nullptr;
  const char *upper_word = nullptr;
  const char *side_word = nullptr;
  ToolPath (*path)(const MotionSpec &spec) = nullptr;
  bool unknown_stroke = false;
  MotionPressCheck press_check = nullptr;
  bool (*off_axis)(const MotionSpec &spec) = nullptr;
};

// The registry: a motion of the kind named `kind` from `spec` into `m`; "" or why not (an unknown kind names the
// known ones; a kind refuses a spec it cannot move by: a path with no points, a force along no direction).
std::string MakeMotion(const std::string &kind, const MotionSpec &spec, MotionHandle &m);
// The registered kinds, in the registry's order.
std::vector<std::string> MotionKinds();
// The kind named `kind`, or nullptr.
const MotionKind *FindMotionKind(const std::string &kind);
// The kind named `kind` carries the path its tool's stroke goes along (MotionKind::path; no such kind: false).
bool MotionOwnsPath(const std::string &kind);
// That path for `spec` (MotionKind::path), or an empty one (a kind that carries none).
ToolPath MotionPathOf(const std::string &kind, const MotionSpec &spec);
// The kind named `kind` moves its tool off its press's y axis by `spec` (MotionKind::off_axis; none: false).
bool MotionLeavesAxis(const std::string &kind, const MotionSpec &spec);
// The kind named `kind`'s stroke is an unknown found from a force (MotionKind::unknown_stroke; no such kind: false).
bool MotionStrokeUnknown(const std::string &kind);
// The kind named `kind`'s press check of `spec` in `press` (MotionKind::press_check): "" or its refusal.
std::string CheckMotionInPress(const std::string &kind, const MotionSpec &spec, const MotionPress &press);
// Reads the options of the kind named `kind` (a registered one) into `spec` (MotionReader).
PetscErrorCode ReadMotion(PetscOptionItems *PetscOptionsObject, const std::string &kind, MotionSpec &spec);

} // namespace tf
