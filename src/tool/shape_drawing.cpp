// The shapes drawn from a file (tool/shape.hpp): tubeform's profile of lines and arcs (profile.cpp) and a DXF
// drawing (dxf.cpp), from the file's text and name (ShapeSpec::text, file). They read no options: the file is
// their tool's choice of shape (the upper die's -die_profile; DrawingKind picks the kind by the file's name).
#include "tubeform/tool/profile.hpp"
#include "tubeform/tool/shape.hpp"

namespace tf {

const ShapeKind &ProfileKind()
{
  static const ShapeKind kind{
    "profile", {}, nullptr, nullptr, [](const ShapeSpec &s, Tool &t) { return ParseProfile(s.text, s.file, t); }};
  return kind;
}

const ShapeKind &DxfKind()
{
  static const ShapeKind kind{"dxf", {}, nullptr, nullptr, [](const ShapeSpec &s, Tool &t) {
                                std::vector<ProfileItem> items;
                                const std::string error = DxfProfile(s.text, s.file, items);
                                return error.empty() ? BuildProfile(items, s.file, t) : error;
                              }};
  return kind;
}

std::string DrawingKind(const std::string &f)
{
  const bool dxf = f.size() > 4 && (f.compare(f.size() - 4, 4, ".dxf") == 0 || f.compare(f.size() - 4, 4, ".DXF") == 0);
  return dxf ? "dxf" : "profile";
}

} // namespace tf
