// The registry of tool shapes: a kind's name, and how it is drawn from a ShapeSpec and what it refuses. A new
// shape is its own file and a line here.
#include <utility>

#include "tubeform/tool/profile.hpp"
#include "tubeform/tool/shape.hpp"

namespace tf {

namespace {
// "" or why not, and the tool drawn.
using Factory = std::string (*)(const ShapeSpec &spec, Tool &t);

const std::pair<const char *, Factory> kShapes[] = {
  {"v", [](const ShapeSpec &s, Tool &t) { return MakeVDie(s.ro, s.r_apex, s.u_close, s.r_edge, s.angle, t); }},
  {"flat", [](const ShapeSpec &s, Tool &t) { return t = BuildFlatPlate(s.y, s.x0, s.x1, s.floor), std::string(); }},
  {"profile", [](const ShapeSpec &s, Tool &t) { return ParseProfile(s.text, s.file, t); }},
  {"dxf",
   [](const ShapeSpec &s, Tool &t) {
     std::vector<ProfileItem> items;
     const std::string error = DxfProfile(s.text, s.file, items);
     return error.empty() ? BuildProfile(items, s.file, t) : error;
   }},
};
} // namespace

std::string MakeShape(const std::string &kind, const ShapeSpec &spec, Tool &tool)
{
  for (const auto &[name, make] : kShapes)
    if (kind == name) return make(spec, tool);
  std::string known;
  for (const std::string &k : ShapeKinds()) known += (known.empty() ? "" : ", ") + k;
  return "no shape '" + kind + "' (known: " + known + ")";
}

std::vector<std::string> ShapeKinds()
{
  std::vector<std::string> kinds;
  for (const auto &s : kShapes) kinds.push_back(s.first);
  return kinds;
}

std::string DrawingKind(const std::string &f)
{
  const bool dxf = f.size() > 4 && (f.compare(f.size() - 4, 4, ".dxf") == 0 || f.compare(f.size() - 4, 4, ".DXF") == 0);
  return dxf ? "dxf" : "profile";
}

} // namespace tf
