// The scenes tubeform runs, by name (the -scene option).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "tubeform/scenes/scene.hpp"

namespace tf {

struct SceneEntry {
  const char *name;
  const char *what; // one line for -help and docs/
  std::unique_ptr<Scene> (*make)(const Options &opt);
};

const std::vector<SceneEntry> &SceneRegistry();
std::vector<std::string> SceneNames();
// The scene of opt.scene; null if the name is not registered.
std::unique_ptr<Scene> CreateScene(const Options &opt);

} // namespace tf
