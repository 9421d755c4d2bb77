// A tool on a path of its own (tool/path.hpp): moved and turned along the piece ahead of its stroke, piece by piece.
// Its options under its tool's prefix: -<prefix>path x1,y1,x2,y2,... (its points in turn, mm, from where it
// starts), -<prefix>path_turn a1,a2,... (its turn at each point, degrees, counter-clockwise; none: it does not
// turn), -<prefix>pivot x,y (the point it turns about, where it starts; needs turns). The upper die's:
// -die_motion path, -die_path, -die_path_turn, -die_pivot (docs/motions.md), and what it goes with in a press (its
// press check).
//
// Two kinds answer to a user's "path": this one, a path in space that may turn (the upper die's), and the schedule
// (motion_schedule.cpp), distances along the tool's direction at given strokes (the lower die's -lower_die_motion
// path, -lower_die_path U,y,...). The registry names each kind once by what it is; each tool lists the words it
// takes and the kind each names (scenes/options/die_motion_options.cpp), so "path" stays the user's word on both dies
// and neither kind reads the other's numbers.
#include <cmath>

#include "tubeform/tool/motion.hpp"

namespace tf {

namespace {
class Path : public Motion {
public:
  explicit Path(const ToolPath &path) : path_(path), d_(path.Motion(0)), spin_(path.Spin(0)) {}
  std::unique_ptr<Motion> Clone() const override { return std::make_unique<Path>(*this); }
  std::string Kind() const override { return kPathMotion; }
  Vec2 Offset(double s) const override { return path_.At(s); }
  double Turn(double s) const override { return path_.Turn(s); }
  Vec2 Direction() const override { return d_; }
  double Spin() const override { return spin_; }
  void Follow(double s) override { d_ = path_.Motion(s), spin_ = path_.Spin(s); }
  std::vector<double> Kinks(double until) const override { return KinksBelow(path_.Turns(), until); }
  void Map(const TurnMap &map) override
  {
    path_ = path_.Mapped(map), d_ = map(d_);
    spin_ = map.det() * spin_;
  }

private:
  ToolPath path_;
  Vec2 d_;      // the motion per unit stroke on the piece followed
  double spin_; // and the turn
};

// -<prefix>path's points at most (a press's path, not a cycle test: a few dozen).
constexpr PetscInt kMaxPoints = 32;

// The pivot: one point, given with turns.
PetscErrorCode CheckPivot(PetscOptionItems *PetscOptionsObject, const std::vector<PetscReal> &pivot, bool turned,
                          MotionSpec &spec)
{
  const char *prefix = PetscOptionsObject->prefix ? PetscOptionsObject->prefix : "";
  PetscFunctionBeginUser;
  PetscCheck(pivot.empty() || (pivot.size() == 2 && std::isfinite(pivot[0]) && std::isfinite(pivot[1])),
             PetscOptionsObject->comm, PETSC_ERR_USER_INPUT, "-%spivot: one point x,y (mm, where the die starts)",
             prefix);
  PetscCheck(pivot.empty() || turned, PetscOptionsObject->comm, PETSC_ERR_USER_INPUT,
             "-%spivot: the point the die turns about; give its turns (-%spath_turn)", prefix, prefix);
  spec.pivot.assign(pivot.begin(), pivot.end());
  PetscFunctionReturn(PETSC_SUCCESS);
}

// The points (x,y pairs) and their turns: a turn for each point, if any; each point a pair of numbers, other than
// the one before it in place or turn.
PetscErrorCode CheckPoints(PetscOptionItems *PetscOptionsObject, const std::vector<PetscReal> &xy, MotionSpec &spec)
{
  const char *prefix = PetscOptionsObject->prefix ? PetscOptionsObject->prefix : "";
  Vec2 at = {0, 0};
  double turned = 0;
  PetscFunctionBeginUser;
  PetscCheck(spec.turns.empty() || 2 * spec.turns.size() == xy.size(), PetscOptionsObject->comm, PETSC_ERR_USER_INPUT,
             "-%spath_turn: %d angles for %d -%spath points: give one (degrees) for each point", prefix,
             (int)spec.turns.size(), (int)xy.size() / 2, prefix);
  spec.points.clear();
  for (size_t k = 0; k + 1 < xy.size(); k += 2) {
    const Vec2 p = {xy[k], xy[k + 1]};
    const double turn = spec.turns.empty() ? 0.0 : spec.turns[k / 2];
    PetscCheck(std::isfinite(p[0]) && std::isfinite(p[1]) && (p != at || turn != turned), PetscOptionsObject->comm,
               PETSC_ERR_USER_INPUT,
               "-%spath: %g,%g after %g,%g: each point must be a pair of numbers (mm), other than the one before it "
               "(the path starts at 0,0) or turned otherwise (-%spath_turn)",
               prefix, p[0], p[1], at[0], at[1], prefix);
    PetscCheck(std::isfinite(turn), PetscOptionsObject->comm, PETSC_ERR_USER_INPUT,
               "-%spath_turn %g: each turn must be a number of degrees", prefix, turn);
    spec.points.push_back(p), at = p, turned = turn;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

// A list of at most `max` numbers under the block's prefix: `value` (none where not given).
PetscErrorCode Numbers(PetscOptionItems *PetscOptionsObject, const char *name, const char *help, PetscInt max,
                       std::vector<PetscReal> &value, PetscBool &set)
{
  std::vector<PetscReal> v(max, 0.0); // (-help prints the first as the default)
  PetscInt n = max;
  PetscFunctionBeginUser;
  PetscCall(PetscOptionsRealArray(name, help, "tubeform", v.data(), &n, &set));
  value.assign(v.begin(), v.begin() + (set ? n : 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode ReadPath(PetscOptionItems *PetscOptionsObject, MotionSpec &spec)
{
  const char *prefix = PetscOptionsObject->prefix ? PetscOptionsObject->prefix : "";
  std::vector<PetscReal> xy, turns, pivot;
  PetscBool path, turned, pivoted;

  PetscFunctionBeginUser;
  PetscCall(
    Numbers(PetscOptionsObject, "-path",
            "a path motion: the tool's points x,y in turn (mm, from where it starts), straight between them, "
            "at twice the punch speed along it (-die_motion path, -pass<N>_die_motion path: the squaring scene's "
            "upper die over a lower die that stays, -lower_die_motion fixed; in place of the pass's stroke, "
            "U = -y / 2; a sideways "
            "motion takes the full model and the rotation hold; docs/motions.md)",
            2 * kMaxPoints, xy, path));
  PetscCall(Numbers(PetscOptionsObject, "-path_turn",
                    "a path motion: the tool's turn at each point (degrees, counter-clockwise, about its pivot; "
                    "linear between the points; a turn counts in the path's length as the arc of a point at the "
                    "tube's outer radius)",
                    kMaxPoints, turns, turned));
  PetscCall(Numbers(PetscOptionsObject, "-pivot",
                    "a path motion: the point x,y (mm, where the tool starts; default 0,0: the tube's centre) it "
                    "turns about under its turns (needs them), moving with it; the upper die's tool_moment is about it",
                    2, pivot, pivoted));
  if (PetscOptionsObject->printhelp) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCheck(path || (!turned && !pivoted), PetscOptionsObject->comm, PETSC_ERR_USER_INPUT,
             "-%spath_turn and -%spivot: the turns along a -%spath; give -%spath", prefix, prefix, prefix, prefix);
  PetscCheck(!xy.empty(), PetscOptionsObject->comm, PETSC_ERR_USER_INPUT,
             "-%spath: the points of -%smotion path: give x,y pairs (mm, from where %s starts)", prefix, prefix,
             spec.tool.c_str());
  PetscCall(CheckPivot(PetscOptionsObject, pivot, turned, spec));
  PetscCheck(xy.size() % 2 == 0, PetscOptionsObject->comm, PETSC_ERR_USER_INPUT,
             "-%spath: %s through x,y pairs (mm, from its start), in turn", prefix, spec.tool.c_str());
  spec.turns.assign(turns.begin(), turns.end());
  PetscCall(CheckPoints(PetscOptionsObject, xy, spec));
  PetscFunctionReturn(PETSC_SUCCESS);
}

// An upper die's turns along its path (degrees): a die turned by more than a quarter turn no longer presses along
// its press's y, along which its punch load is read.
constexpr double kMaxDieTurn = 90;

// In a press (MotionKind::press_check), any pass's: the squaring scene's die, within a quarter turn, ending below its
// start, over a lower die that stays, not moved off the axis by an offset (a path sideways is its own). The first
// pass's in place of -stroke and -stroke_path, with no side dies or withdrawal (off its axis the model's choice decides
// its hold: scenes/options/model_options.cpp); a later pass's with no side dies in it (they press by the stroke)
// and, off its press's axis, held by the rotation hold.
std::string CheckPathInPress(const MotionSpec &spec, const MotionPress &press)
{
  const std::string name = press.prefix + "path";
  const double y = spec.points.back()[1];
  if (!press.dies)
    return name + ": the squaring scene's upper die through x,y pairs (mm, from its start), in turn; not the " +
           press.scene + " scene's";
  for (double turn : spec.turns)
    if (std::abs(turn) > kMaxDieTurn)
      return Formatted("%s_turn %g: each turn must be a number of degrees within +-%g", name.c_str(), turn,
                       kMaxDieTurn);
  if (y >= 0)
    return Formatted("%s: the last point's y %g must be below the start: the press ends pressing (U = -y / 2)",
                     name.c_str(), y);
  if (!press.lower_stays)
    return name + ": the path is the upper die's, relative to a lower die that stays: give " +
           press.Option("lower_die_motion") + " fixed";
  if (press.pass == 0 &&
      (press.stroke_path || press.corner_radius || press.side_dies || !press.withdrawn_by.empty() || press.die_offset))
    return name + ": in place of -stroke and -stroke_path: not with -stroke_path, -stroke_corner_radius, -side_die, "
                  "-unload withdraw or -die_offset (a path sideways is its own offset)";
  if (press.pass > 0 && press.die_offset)
    return name + ": not with " + press.prefix + "offset (a path sideways is its own offset)";
  if (press.pass > 0 && press.side_dies)
    return name + ": not with side dies in its pass (-side_die, " + press.Option("side_die") +
           "), which press by the stroke";
  if (press.pass > 0 && press.off_axis && !press.held)
    return name + ": a die off the axis (a sideways point or a turn) breaks the tube's mirror symmetry; use -model "
                  "full (or auto) -full_hold rotation (or auto)";
  return "";
}

// Off its press's y axis: a sideways point or a turn (MotionKind::off_axis).
bool PathOffAxis(const MotionSpec &spec)
{
  bool off = false;
  for (const Vec2 &p : spec.points) off = off || p[0] != 0;
  for (double a : spec.turns) off = off || a != 0;
  return off;
}

std::string MakePath(const MotionSpec &s, MotionHandle &m)
{
  if (s.points.empty()) return "a path with no points";
  if (!s.turns.empty() && !(s.reach > 0)) return "turns with no reach to count them at";
  m = PathMotion(PathOf(s));
  return "";
}
} // namespace

ToolPath PathOf(const MotionSpec &spec)
{
  if (!spec.turns.empty() && !(spec.reach > 0)) return ToolPath();
  std::vector<double> turns;
  for (double a : spec.turns) turns.push_back(a * (M_PI / 180));
  return ToolPath(spec.points, turns, spec.reach);
}

std::unique_ptr<Motion> PathMotion(const ToolPath &path) { return std::make_unique<Path>(path); }

const MotionKind &PathKind()
{
  static const MotionKind kind{kPathMotion,
                               {"path", "path_turn", "pivot"},
                               ReadPath,
                               MakePath,
                               nullptr,
                               nullptr,
                               "path",
                               nullptr,
                               PathOf,
                               /*unknown_stroke=*/false,
                               CheckPathInPress,
                               PathOffAxis};
  return kind;
}

} // namespace tf
