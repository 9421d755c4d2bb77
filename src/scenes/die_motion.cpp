// The press's dies' motions from the options, made by the motion registry (tool/motion.hpp): the lower die's of
// -lower_die_motion, with the upper die's that goes with it; the upper die's path (-die_path); force control
// (-die_force, -side_force).
#include "tubeform/scenes/die.hpp"

namespace tf {

namespace {
// A -lower_die_motion word: the lower die's motion (a kind of the registry, along `lower` per unit stroke U)
// and the upper die's (U: half the dies' closing either way, if `closing`: the closed forms of the dies' reach
// hold, CheckDieReach).
struct LowerMotion {
  const char *word, *kind;
  Vec2 lower, upper;
  bool closing;
};
const LowerMotion kLowerMotions[] = {
  {"mirror", "stroke", {0.0, 1.0}, {0.0, -1.0}, true}, // up by U: the mirror of the upper die's
  {"fixed", "fixed", {0.0, 0.0}, {0.0, -2.0}, true},   // it stays; the upper die travels 2 U
  {"path", "schedule", {}, {0.0, -1.0}, false},        // through -lower_die_path's rises at its strokes
};

const LowerMotion *LowerMotionOf(const Options &o)
{
  for (const LowerMotion &m : kLowerMotions)
    if (o.lower_die_motion == m.word) return &m;
  return nullptr;
}

// The lower die's motion spec of -lower_die_motion's word m.
MotionSpec LowerSpec(const Options &o, const LowerMotion &m)
{
  MotionSpec spec;
  spec.direction = m.lower;
  for (size_t k = 0; k + 1 < o.lower_die_path.size(); k += 2)
    spec.at.push_back(o.lower_die_path[k]), spec.to.push_back({0.0, o.lower_die_path[k + 1]});
  return spec;
}
} // namespace

PetscErrorCode SetMotion(MPI_Comm comm, const char *option, const std::string &kind, const MotionSpec &spec, Tool &t)
{
  PetscFunctionBeginUser;
  const std::string why = MakeMotion(kind, spec, t.motion);
  PetscCheck(why.empty(), comm, PETSC_ERR_USER_INPUT, "%s: the %s cannot move by %s", option, t.name.c_str(),
             why.c_str());
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode SetLowerMotion(MPI_Comm comm, const Options &o, Tool &upper, Tool &lower)
{
  PetscFunctionBeginUser;
  const LowerMotion *m = LowerMotionOf(o);
  PetscCheck(m, comm, PETSC_ERR_USER_INPUT, "-lower_die_motion %s: not a motion of the lower die",
             o.lower_die_motion.c_str());
  PetscCall(SetMotion(comm, o.lower_die_path.empty() ? "-lower_die_motion" : "-lower_die_path", m->kind,
                      LowerSpec(o, *m), lower));
  MotionSpec spec;
  spec.direction = m->upper;
  PetscCall(SetMotion(comm, "-lower_die_motion", "stroke", spec, upper));
  PetscFunctionReturn(PETSC_SUCCESS);
}

MotionHandle LowerDieMotion(const Options &o)
{
  MotionHandle lower;
  const LowerMotion *m = LowerMotionOf(o);
  if (!m || !MakeMotion(m->kind, LowerSpec(o, *m), lower).empty()) lower = StrokeMotion({0.0, 1.0});
  return lower;
}

double UpperTravel(const Options &o)
{
  const LowerMotion *m = LowerMotionOf(o);
  return m ? -m->upper[1] : 1.0;
}

bool LowerDieClosing(const Options &o)
{
  const LowerMotion *m = LowerMotionOf(o);
  return m && m->closing;
}

std::vector<double> PressKinks(const Options &opt)
{
  std::vector<double> kinks;
  MotionHandle upper, lower;
  MotionSpec spec;
  spec.path = DiePath(opt);
  if (!opt.die_path.empty() && MakeMotion("path", spec, upper).empty()) kinks = upper->Kinks();
  const LowerMotion *m = QuarterModel(opt) ? nullptr : LowerMotionOf(opt);
  if (m && MakeMotion(m->kind, LowerSpec(opt, *m), lower).empty())
    for (double s : lower->Kinks()) kinks.push_back(s);
  return kinks;
}

PetscErrorCode SetPressMotions(MPI_Comm comm, const Options &opt, size_t first_side, std::vector<Tool> &tools)
{
  PetscFunctionBeginUser;
  Tool &upper = tools[0];
  if (!opt.die_path.empty()) {
    MotionSpec spec;
    spec.path = DiePath(opt);
    PetscCall(SetMotion(comm, "-die_path", "path", spec, upper));
  }
  if (!opt.die_path_turn.empty()) upper.origin = DiePivot(opt);
  for (size_t k = 0; k < tools.size(); ++k) {
    const bool forced = k == 0 ? opt.die_force > 0 : k >= first_side && opt.side_force > 0;
    if (!forced) continue;
    MotionSpec spec;
    spec.direction = tools[k].Direction();
    PetscCall(SetMotion(comm, k == 0 ? "-die_force" : "-side_force", "force", spec, tools[k]));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

} // namespace tf
