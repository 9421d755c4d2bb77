// The registry of tool motions: each kind's name, the options it reads, its reader and its factory (a MotionKind,
// defined in the kind's own file, with what it refuses in a press). A new motion is its own file (motion_*.cpp) and a
// line here.
#include "tubeform/tool/motion.hpp"

namespace tf {

const MotionKind &FixedKind();    // motion_fixed.cpp
const MotionKind &StrokeKind();   // motion_stroke.cpp
const MotionKind &PathKind();     // motion_path.cpp
const MotionKind &ForceKind();    // motion_force.cpp
const MotionKind &ScheduleKind(); // motion_schedule.cpp
const MotionKind &PulseKind();    // motion_pulse.cpp

namespace {
const MotionKind &(*const kKinds[])() = {FixedKind, StrokeKind, PathKind, ForceKind, ScheduleKind, PulseKind};
} // namespace

const MotionKind *FindMotionKind(const std::string &kind)
{
  for (const auto &k : kKinds)
    if (kind == k().name) return &k();
  return nullptr;
}

bool MotionOwnsPath(const std::string &kind)
{
  const MotionKind *k = FindMotionKind(kind);
  return k && k->path;
}

ToolPath MotionPathOf(const std::string &kind, const MotionSpec &spec)
{
  const MotionKind *k = FindMotionKind(kind);
  return k && k->path ? k->path(spec) : ToolPath();
}

bool MotionLeavesAxis(const std::string &kind, const MotionSpec &spec)
{
  const MotionKind *k = FindMotionKind(kind);
  return k && k->off_axis && k->off_axis(spec);
}

bool MotionStrokeUnknown(const std::string &kind)
{
  const MotionKind *k = FindMotionKind(kind);
  return k && k->unknown_stroke;
}

std::string CheckMotionInPress(const std::string &kind, const MotionSpec &spec, const MotionPress &press)
{
  const MotionKind *k = FindMotionKind(kind);
  return k && k->press_check ? k->press_check(spec, press) : "";
}

std::string MakeMotion(const std::string &kind, const MotionSpec &spec, MotionHandle &m)
{
  if (const MotionKind *k = FindMotionKind(kind)) {
    const std::string why = k->make(spec, m);
    return why.empty() ? why : "a motion '" + kind + "': " + why;
  }
  std::string known;
  for (const std::string &k : MotionKinds()) known += (known.empty() ? "" : ", ") + k;
  return "no motion '" + kind + "' (known: " + known + ")";
}

std::vector<std::string> MotionKinds()
{
  std::vector<std::string> kinds;
  for (const auto &k : kKinds) kinds.push_back(k().name);
  return kinds;
}

PetscErrorCode ReadMotion(PetscOptionItems *PetscOptionsObject, const std::string &kind, MotionSpec &spec)
{
  PetscFunctionBeginUser;
  const MotionKind *k = FindMotionKind(kind);
  MotionHandle none;
  PetscCheck(k, PetscOptionsObject->comm, PETSC_ERR_USER_INPUT, "-%smotion %s: %s",
             PetscOptionsObject->prefix ? PetscOptionsObject->prefix : "", kind.c_str(),
             MakeMotion(kind, spec, none).c_str());
  if (k->read) PetscCall(k->read(PetscOptionsObject, spec));
  PetscFunctionReturn(PETSC_SUCCESS);
}

} // namespace tf
