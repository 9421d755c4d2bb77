// The flat plate (tool/shape.hpp): one line, pressing down or a floor under the body. It reads no options (its
// scene places it).
#include "tubeform/tool/shape.hpp"

namespace tf {

Tool BuildFlatPlate(double y0, double x0, double x1, bool floor)
{
  Tool t;
  t.name = floor ? "floor" : "plate";
  Segment s;
  s.a = {x0, y0};
  s.b = {x1, y0};
  s.n_line = {0, floor ? 1.0 : -1.0};
  t.segments.push_back(s);
  return t;
}

const ShapeKind &FlatKind()
{
  static const ShapeKind kind{kFlatShape, {}, nullptr, nullptr, [](const ShapeSpec &s, Tool &t) {
                                return t = BuildFlatPlate(s.y, s.x0, s.x1, s.floor), std::string();
                              }};
  return kind;
}

} // namespace tf
