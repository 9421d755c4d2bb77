// The loading's parameters several scenes share, as the options give them, one struct per group (docs/motions.md): how
// far a scene presses (the stroke: the tool scenes' first pass's and the column's end shortening) and by what law it
// springs back (the tool scenes' releases and the bending scene's). Options holds one of each (so that they travel
// with the run's options to its levels and companions); io reads and checks them (io/loading_options.hpp), and the
// scenes take them from there. The tool scenes' own model and passes, the first pass's path of strokes and its
// release among them, are theirs: scenes/tool_scene.hpp.
#pragma once

#include <petscsys.h>

namespace tf {

// The stroke (-stroke): where the press ends (the tool scenes set it from the first pass's last stroke in turn, its
// -die_path's end; the corner-radius rule gives theirs in its place: scenes/pass_spec.hpp).
struct StrokeParams {
  double u = 4.2; // final tool stroke U / prescribed end displacement (mm)
};

// The release's law (-springback): auto (ElasticRelease), the material's own, or every point elastic (the paper's).
enum class Springback { Auto, Material, Elastic };
inline constexpr const char *kSpringbackWords[] = {"auto", "material", "elastic"};

// The release's law (-springback; how a tool scene's pass lets the tube go is the pass's: scenes/pass_spec.hpp).
struct ReleaseParams {
  Springback springback = Springback::Auto;
};

} // namespace tf
