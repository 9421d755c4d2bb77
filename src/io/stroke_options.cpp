// The stroke's options: read into Options::stroke (in the loading block of -help, where they always were) and checked,
// one line naming the option: its value, its path of strokes (which sets it), the corner-radius rule and the dies that
// rule is for.
#include <cmath>

#include "tubeform/io/loading_options.hpp"

namespace tf {

PetscErrorCode ReadStrokeOptions(PetscOptionItems *PetscOptionsObject, OptionReader &read, StrokeParams &s)
{
  PetscFunctionBeginUser;
  PetscCall(read.Real(PetscOptionsObject, "-stroke",
                      "Final stroke U (mm): tool travel, or the prescribed end shortening of the column", s.u));
  PetscCall(read.Real(PetscOptionsObject, "-stroke_corner_radius", "The paper's rule: the rounded square's corner (mm)",
                      s.corner_radius));
  PetscCall(RealList(PetscOptionsObject, read, "-stroke_path",
                     "tool scenes: the die's strokes in turn (mm, >= 0), at the punch speed: press, back off, press "
                     "again (in place of -stroke: the last is the final stroke)",
                     kMaxPathPoints, s.path));
  PetscFunctionReturn(PETSC_SUCCESS);
}

namespace {
// -stroke_path: the die goes to each stroke in turn at the punch speed; the last is the press's final stroke (u).
PetscErrorCode CheckStrokePath(MPI_Comm comm, Options &opt)
{
  StrokeParams &s = opt.stroke;
  PetscFunctionBeginUser;
  PetscCheck(PressesWithTools(opt), comm, PETSC_ERR_USER_INPUT, "-stroke_path: the %s scene presses with no dies",
             opt.scene.c_str());
  double at = 0;
  for (double u : s.path) {
    PetscCheck(std::isfinite(u) && u >= 0 && u != at, comm, PETSC_ERR_USER_INPUT,
               "-stroke_path: %g after %g: each stroke must be a non-negative number of mm, other than the one "
               "before it (the path starts at 0)",
               u, at);
    at = u;
  }
  PetscCheck(s.path.back() > 0, comm, PETSC_ERR_USER_INPUT,
             "-stroke_path: the last stroke is the press's final one and must be positive");
  PetscCheck(s.corner_radius <= 0, comm, PETSC_ERR_USER_INPUT, "-stroke_path: not with -stroke_corner_radius");
  s.u = s.path.back();
  PetscFunctionReturn(PETSC_SUCCESS);
}
} // namespace

PetscErrorCode CheckStrokeOptions(MPI_Comm comm, Options &opt)
{
  StrokeParams &s = opt.stroke;
  PetscFunctionBeginUser;
  if (!s.path.empty()) PetscCall(CheckStrokePath(comm, opt));
  PetscCheck(s.corner_radius >= 0, comm, PETSC_ERR_USER_INPUT, "-stroke_corner_radius %g: must be non-negative",
             s.corner_radius);
  PetscCheck(s.u > 0, comm, PETSC_ERR_USER_INPUT, "-stroke %g: must be positive (mm)", s.u);
  PetscFunctionReturn(PETSC_SUCCESS);
}

} // namespace tf
