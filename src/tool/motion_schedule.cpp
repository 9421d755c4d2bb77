// A tool moved through displacements given at strokes (-lower_die_motion path, -lower_die_path): from (0, 0) at
// stroke 0 through each point at its stroke, linear in the stroke between them; past the last stroke it stays
// there. Each stroke is a kink: a step runs on one piece (Follow), ending at the next stroke. Its option,
// -<prefix>path U1,d1,U2,d2,...: the distances d along the tool's direction at the strokes U. The lower die's word
// for it is path; the upper die's path is the path kind (motion_path.cpp says how the two share the word).
#include <cmath>
#include <cstdio>

#include "tubeform/tool/motion.hpp"

namespace tf {

namespace {
std::string Number(double v)
{
  char s[32];
  std::snprintf(s, sizeof s, "%g", v);
  return s;
}

class Schedule : public Motion {
public:
  Schedule(const std::vector<double> &at, const std::vector<Vec2> &to, const Vec2 &axis)
      : at_{0.0}, to_{{0.0, 0.0}}, axis_(axis)
  {
    at_.insert(at_.end(), at.begin(), at.end());
    to_.insert(to_.end(), to.begin(), to.end());
    Follow(0);
  }
  std::unique_ptr<Motion> Clone() const override { return std::make_unique<Schedule>(*this); }
  std::string Kind() const override { return "schedule"; }
  Vec2 Offset(double s) const override
  {
    const size_t k = Piece(s);
    if (k + 1 == at_.size()) return to_.back();
    const Vec2 v = Slope(k);
    return {to_[k][0] + (s - at_[k]) * v[0], to_[k][1] + (s - at_[k]) * v[1]};
  }
  Vec2 Direction() const override { return d_; }
  Vec2 Axis() const override { return axis_; }
  double Travel(double s) const override
  {
    const Vec2 o = Offset(s);
    return o[0] * axis_[0] + o[1] * axis_[1];
  }
  void Follow(double s) override
  {
    const size_t k = Piece(s);
    d_ = k + 1 == at_.size() ? Vec2{0.0, 0.0} : Slope(k);
  }
  std::vector<double> Kinks(double until) const override { return KinksBelow({at_.begin() + 1, at_.end()}, until); }
  void Map(const TurnMap &map) override
  {
    for (Vec2 &p : to_) p = map(p);
    d_ = map(d_), axis_ = map(axis_);
  }

private:
  std::vector<double> at_; // the strokes, from 0
  std::vector<Vec2> to_;   // the displacements there
  Vec2 d_{};               // the motion per unit stroke on the piece followed
  Vec2 axis_;              // the unit direction its travel is counted along (Travel)

  // A stroke this close to one of the strokes (relative to the last) is at it: a step from there runs on the piece
  // after it (the stroke at a kink is the commits' sum, within round-off of the given one).
  static constexpr double kAtStroke = 1e-12;
  // The piece a step from s runs on: at_.size() - 1 past the last stroke (standing).
  size_t Piece(double s) const
  {
    size_t k = 0;
    while (k + 1 < at_.size() && s >= at_[k + 1] - kAtStroke * at_.back()) ++k;
    return k;
  }
  Vec2 Slope(size_t k) const
  {
    const double ds = at_[k + 1] - at_[k];
    return {(to_[k + 1][0] - to_[k][0]) / ds, (to_[k + 1][1] - to_[k][1]) / ds};
  }
};
} // namespace

std::string ScheduleMotion(const std::vector<double> &at, const std::vector<Vec2> &to, MotionHandle &m,
                           const Vec2 &axis)
{
  if (at.empty() || at.size() != to.size()) return "give a stroke and a displacement for each point";
  for (size_t k = 0; k < at.size(); ++k) {
    const double before = k ? at[k - 1] : 0.0;
    if (!(std::isfinite(at[k]) && at[k] > before && std::isfinite(to[k][0]) && std::isfinite(to[k][1])))
      return "the strokes must rise from 0 and every number be finite (stroke " + Number(at[k]) + " after " +
             Number(before) + ")";
  }
  const double n = std::hypot(axis[0], axis[1]);
  m = MotionHandle(std::make_unique<Schedule>(at, to, n > 0 ? Vec2{axis[0] / n, axis[1] / n} : Vec2{0.0, 0.0}));
  return "";
}

namespace {
// -<prefix>path's numbers at most: 32 points, as -die_path's.
constexpr PetscInt kMaxNumbers = 64;

PetscErrorCode ReadSchedule(PetscOptionItems *PetscOptionsObject, MotionSpec &spec)
{
  std::vector<PetscReal> v(kMaxNumbers, 0.0); // (-help prints the first as the default)
  PetscInt n = kMaxNumbers;
  PetscBool set;
  const char *prefix = PetscOptionsObject->prefix ? PetscOptionsObject->prefix : "";

  PetscFunctionBeginUser;
  const std::string help = std::string("the tool's travel y along its motion (mm, from where it starts; the lower "
                                       "die's up, the side dies' in) at strokes U in turn, as U,y pairs (U rising "
                                       "from 0), linear in U between them; it stays after the last (-") +
                           prefix + "motion path)";
  PetscCall(PetscOptionsRealArray("-path", help.c_str(), "tubeform", v.data(), &n, &set));
  if (PetscOptionsObject->printhelp) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCheck(set && n > 0 && n % 2 == 0, PetscOptionsObject->comm, PETSC_ERR_USER_INPUT,
             "-%spath: the path of -%smotion path, as U,y pairs (mm), an even count of numbers: give both or neither",
             prefix, prefix);
  spec.at.clear(), spec.to.clear(), spec.along.clear();
  for (PetscInt k = 0; k + 1 < n; k += 2) spec.at.push_back(v[k]), spec.along.push_back(v[k + 1]);
  std::vector<Vec2> probe; // (the factory's own refusals, before any direction is given)
  for (double d : spec.along) probe.push_back({0.0, d});
  MotionHandle m;
  const std::string why = ScheduleMotion(spec.at, probe, m);
  PetscCheck(why.empty(), PetscOptionsObject->comm, PETSC_ERR_USER_INPUT, "-%spath: %s", prefix, why.c_str());
  PetscFunctionReturn(PETSC_SUCCESS);
}

// The spec's displacements: `to`, or the distances `along` its direction (+ 0.0: a zero coordinate's sign is +).
std::string MakeSchedule(const MotionSpec &s, MotionHandle &m)
{
  std::vector<Vec2> to = s.to;
  if (to.empty())
    for (double d : s.along) to.push_back({d * s.direction[0] + 0.0, d * s.direction[1] + 0.0});
  return ScheduleMotion(s.at, to, m, s.direction);
}
} // namespace

const MotionKind &ScheduleKind()
{
  static const MotionKind kind{"schedule", {"path"}, ReadSchedule, MakeSchedule, "path", nullptr, nullptr, "path"};
  return kind;
}

} // namespace tf
