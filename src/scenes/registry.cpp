#include "tubeform/scenes/registry.hpp"

namespace tf {

// One factory per scene file.
std::unique_ptr<Scene> MakeSquaringScene(const Options &opt);
std::unique_ptr<Scene> MakeFlatteningScene(const Options &opt);
std::unique_ptr<Scene> MakePressureScene(const Options &opt);
std::unique_ptr<Scene> MakeShearScene(const Options &opt);
std::unique_ptr<Scene> MakeRotationScene(const Options &opt);
std::unique_ptr<Scene> MakeColumnScene(const Options &opt);
std::unique_ptr<Scene> MakeTensionScene(const Options &opt);
std::unique_ptr<Scene> MakeBendingScene(const Options &opt);
std::unique_ptr<Scene> MakeSlideScene(const Options &opt);
std::unique_ptr<Scene> MakeArcSlideScene(const Options &opt);

namespace {
std::unique_ptr<Scene> MakeAnySlideScene(const Options &opt)
{
  return opt.slide_tool == "arc" ? MakeArcSlideScene(opt) : MakeSlideScene(opt);
}
} // namespace

const std::vector<SceneEntry> &SceneRegistry()
{
  static const std::vector<SceneEntry> scenes = {
    {"squaring", "quarter tube pressed by the upper 90-degree V-die (the paper's process)", MakeSquaringScene},
    {"flattening", "quarter ring crushed by a flat plate", MakeFlatteningScene},
    {"pressure", "quarter thick cylinder under internal pressure (Lame, Hill)", MakePressureScene},
    {"shear", "simple shear of a block (Jaumann objectivity)", MakeShearScene},
    {"rotation", "a stressed block turned rigidly (objectivity)", MakeRotationScene},
    {"column", "a bowed strip shortened past its Euler load (geometric stiffness)", MakeColumnScene},
    {"tension", "plane-strain tension or compression of a block (flow curve)", MakeTensionScene},
    {"bending", "pure bending and unbending of a plane-strain strip (springback)", MakeBendingScene},
    {"slide", "a block pushed along a floor, or a ring turned in a cylinder (-slide_tool arc): Coulomb friction",
     MakeAnySlideScene},
  };
  return scenes;
}

std::vector<std::string> SceneNames()
{
  std::vector<std::string> names;
  for (const auto &s : SceneRegistry()) names.push_back(s.name);
  return names;
}

std::unique_ptr<Scene> CreateScene(const Options &opt)
{
  for (const auto &s : SceneRegistry())
    if (opt.scene == s.name) return s.make(opt);
  return nullptr;
}

} // namespace tf
