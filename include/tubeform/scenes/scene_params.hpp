// The parameters of the scenes without tools, one struct per scene. Each scene reads and checks its own (its
// Read*Options and Check*Options in src/scenes/<scene>.cpp, listed in the scene registry); the chosen scene's travel
// with the run's options to its levels and companions (Options::scene_params), read back with OwnParams.
#pragma once

#include <vector>

#include "tubeform/io/options.hpp"

namespace tf {

// The run's scene's own parameters, P its struct (Options::scene_params, set by ReadOptions for the chosen scene), or
// P's built-in values where the options hold none of P (a scene made from options built in code).
template <class P>
const P &OwnParams(const Options &opt)
{
  return HeldOr<P>(opt.scene_params);
}

// What the pressure scene ramps (-pressure_control): the pressure, or the inner radial displacement.
enum class PressureControl { Load, Displacement };
inline constexpr const char *kPressureControlWords[] = {"load", "displacement"};
// The pressure scene (-pressure_*).
struct PressureParams {
  double p = 50.0;                                 // final internal pressure (MPa), -pressure_control load
  PressureControl control = PressureControl::Load; // what is ramped
  double u = 0.1; // final inner radial displacement (mm), -pressure_control displacement
};

// The shear scene (-shear_*).
struct ShearParams {
  double gamma = 1.0; // final shear strain
};

// The rotation scene (-rotation_*).
struct RotationParams {
  double angle = 90.0;  // degrees
  double strain = 1e-3; // prestretch before the rotation
};

// The column scene (-column_*).
struct ColumnParams {
  double l = 25.0, t = 1.0, imperfection = 0.025; // length between the pins, thickness, bow (mm)
};

// The tension scene (-tension_*).
struct TensionParams {
  double strain = 0.1;       // signed: < 0 compresses
  std::vector<double> cycle; // nominal strains the block is then taken to in turn (reversals)
};

// The bending scene (-bending_*).
struct BendingParams {
  double strain = 0.01;      // the outer fibre's nominal strain at lambda 1 (signed)
  std::vector<double> cycle; // outer-fibre strains the strip is then taken to in turn
};

// The slide scene's tool (-slide_tool): a block on a flat floor, or a quarter ring turned inside a cylinder.
enum class SlideTool { Flat, Arc };
inline constexpr const char *kSlideToolWords[] = {"flat", "arc"};
// The slide scene (-slide_*).
struct SlideParams {
  double n = 100.0, push = 0.2; // normal force (N/mm, arc: pressure MPa), push (mm)
  double back = 0;              // (flat) push back by this much in a third stage (mm)
  SlideTool tool = SlideTool::Flat;
};

} // namespace tf
