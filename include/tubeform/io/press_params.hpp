// The loading's parameters as the options give them, one struct per group (docs/motions.md): how far a scene presses
// (the stroke; also the column's end shortening) and how it is released (also the bending scene's springback).
// Options holds one of each (so that they travel with the run's options to its levels and companions); io reads and
// checks them (io/loading_options.hpp), and the scenes take them from there. The tool scenes' own model and passes
// are theirs: scenes/tool_scene.hpp.
#pragma once

#include <petscsys.h>

#include <vector>

namespace tf {

// The most strokes -stroke_path takes (a press's path, not a cycle test: a few dozen).
constexpr PetscInt kMaxPathPoints = 32;

// The stroke (-stroke, -stroke_corner_radius, -stroke_path): where the press ends, given, by the paper's
// corner-radius rule, or as the last of the die's strokes in turn (CheckStrokeOptions sets u to it; a -die_path sets
// it too).
struct StrokeParams {
  double u = 4.2;           // final tool stroke U / prescribed end displacement (mm)
  double corner_radius = 0; // > 0: stroke from the paper's corner-radius rule
  std::vector<double> path; // tool scenes: the die's strokes in turn (empty: 0 to u)
};

// How a press is released after loading (-unload): its contact forces reversed and the dies removed (the paper's),
// the dies moved back, or not at all. The words of the option in the enumerators' order.
enum class Unload { Reverse, Withdraw, None };
inline constexpr const char *kUnloadWords[] = {"reverse", "withdraw", "none"};
// The release's law (-springback): auto (ElasticRelease), the material's own, or every point elastic (the paper's).
enum class Springback { Auto, Material, Elastic };
inline constexpr const char *kSpringbackWords[] = {"auto", "material", "elastic"};

// The release (-unload, -springback): how the press lets the tube go, and by what law it springs back.
struct ReleaseParams {
  Unload unload = Unload::Reverse;
  Springback springback = Springback::Auto;
};

} // namespace tf
