// How far a pass presses, as its upper die's motion decides it (docs/motions.md): to the stroke it ends at (stroke:
// -stroke, -pass<N>_stroke; path: where its own path ends, which its reader sets as its stroke) or with the force it
// presses with (force: -die_force, -pass<N>_die_force; its stroke the outcome, an unknown of each increment). The
// one place that says whether a pass is pressed, what ends it, how its load rises over its stage and where its U is
// measured from: the options' checks (PassCount, passes_check.cpp) and the press scene (its stroke, force, reach and
// metrics) ask it.
#pragma once

#include <algorithm>
#include <string>

#include "tubeform/scenes/pass_spec.hpp"

namespace tf {

struct PassExtent {
  int pass = 0;        // 0 the first
  bool forced = false; // its upper die's motion kind's MotionKind::unknown_stroke (force), read once by ExtentOf
  double stroke = 0;   // where its upper die ends (mm, from -stroke's zero; not under force)
  double force = 0;    // the punch load it presses with at its end (N/mm; force only)

  // Its stroke is the outcome of the force it presses with (the die's own, an unknown of each increment).
  bool Forced() const { return forced; }
  // The pass is pressed: the first always, a later one given its stroke, a path (its stroke) or a force.
  bool Given() const { return pass == 0 || stroke > 0 || Forced(); }
  // What ends it, its word and the option that gives it (-stroke, -die_force, -pass2_stroke, -pass2_die_force;
  // a path's pass by the stroke its path ends at, named as the stroke: passes_check.cpp).
  double Target() const { return Forced() ? force : stroke; }
  const char *TargetWord() const { return Forced() ? "force" : "stroke"; }
  std::string Option() const;
  // The share of its load at lambda over its press stage from `stage` (a force rising from 0 to its end's).
  static double Ramp(double lambda, double stage) { return std::min(std::max(lambda - stage, 0.0), 1.0); }
  // Its U (the history's stroke) from -stroke's zero: the die's own stroke under force, else its path's U at the
  // scene's stroke (`path_u`), less how far back (in U) its die started (0 the first pass).
  double U(double die_stroke, double path_u, double back) const { return (Forced() ? die_stroke : path_u) - back; }
};

// Pass `pass`'s extent from its spec, `stroke` its stroke (the first pass's: -stroke, Options::stroke).
inline PassExtent ExtentOf(const PassSpec &p, int pass, double stroke)
{
  PassExtent e;
  e.pass = pass, e.forced = MotionStrokeUnknown(p.dies.motion.kind), e.stroke = stroke;
  e.force = e.Forced() ? p.dies.motion.spec.force : 0.0;
  return e;
}

} // namespace tf
