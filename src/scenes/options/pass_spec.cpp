// The words of a pass's dies (include/tubeform/scenes/pass_spec.hpp) and its options' names: what the options' readers
// and checks (scenes/tool_options.hpp), the stroke's check and the scenes' messages spell alike.
#include "tubeform/core/core.hpp"
#include "tubeform/scenes/tool_scene.hpp"

namespace tf {

DieChoice DrawingChoice(const std::string &file)
{
  DieChoice shape(file.empty() ? DieFrom::Unset : DieFrom::Drawing);
  if (!file.empty()) shape.kind = DrawingKind(file);
  shape.spec.file = file;
  return shape;
}

DieChoice ShapeChoice(const std::string &word, bool none)
{
  DieChoice shape(EnumOfWord(kDieFromWords, word, DieFrom::Drawing));
  if (shape.Is(DieFrom::None) && !none) shape.from = DieFrom::Drawing; // (a lower die's none: a file so named)
  if (shape.Is(DieFrom::Plate)) shape.kind = kFlatShape;               // (the flat kind draws it)
  const ShapeKind *kind = FindShapeKind(word);
  if (shape.Is(DieFrom::Drawing) && kind && !kind->options.empty()) // (a shape of its own: v)
    shape.from = DieFrom::Shape, shape.kind = word, shape.spec = PaperVDie();
  if (shape.Is(DieFrom::Drawing)) shape.kind = DrawingKind(word), shape.spec.file = word;
  return shape;
}

std::string ShapeWord(const DieChoice &shape)
{
  if (shape.Is(DieFrom::Drawing)) return shape.spec.file;
  if (shape.Is(DieFrom::Shape)) return shape.kind;
  return shape.Given() ? WordOf(kDieFromWords, shape.from) : "";
}

// The name of pass `pass`'s (1: the second) option `what`: -pass2_stroke, ...

std::string PassExtent::Option() const
{
  const char *what = Forced() ? "die_force" : "stroke";
  return PassOptionName(pass, what);
}

} // namespace tf
