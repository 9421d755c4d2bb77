// The registry of tool motions: a kind's name, and how it is made from a MotionSpec and what it refuses. A new
// motion is its own file (motion_*.cpp) and a line here.
#include <utility>

#include "tubeform/tool/motion.hpp"

namespace tf {

namespace {
// "" or why not, and the motion made.
using Factory = std::string (*)(const MotionSpec &spec, MotionHandle &m);

bool Moves(const Vec2 &d) { return d[0] != 0 || d[1] != 0; }

const std::pair<const char *, Factory> kMotions[] = {
  {"fixed", [](const MotionSpec &, MotionHandle &m) { return m = FixedMotion(), std::string(); }},
  {"stroke",
   [](const MotionSpec &s, MotionHandle &m) {
     return Moves(s.direction) ? (m = StrokeMotion(s.direction), std::string()) : "a stroke along no direction";
   }},
  {"path",
   [](const MotionSpec &s, MotionHandle &m) {
     return s.path.empty() ? "a path with no points" : (m = PathMotion(s.path), std::string());
   }},
  {"force",
   [](const MotionSpec &s, MotionHandle &m) {
     return Moves(s.direction) ? (m = ForceMotion(s.direction), std::string()) : "a force along no direction";
   }},
  {"schedule", [](const MotionSpec &s, MotionHandle &m) { return ScheduleMotion(s.at, s.to, m); }},
};
} // namespace

std::string MakeMotion(const std::string &kind, const MotionSpec &spec, MotionHandle &m)
{
  for (const auto &[name, make] : kMotions)
    if (kind == name) {
      const std::string why = make(spec, m);
      return why.empty() ? why : "a motion '" + kind + "': " + why;
    }
  std::string known;
  for (const std::string &k : MotionKinds()) known += (known.empty() ? "" : ", ") + k;
  return "no motion '" + kind + "' (known: " + known + ")";
}

std::vector<std::string> MotionKinds()
{
  std::vector<std::string> kinds;
  for (const auto &m : kMotions) kinds.push_back(m.first);
  return kinds;
}

} // namespace tf
