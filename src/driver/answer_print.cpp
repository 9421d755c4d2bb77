// The answer's lines at the end of a run (include/tubeform/driver/answer.hpp).
#include <algorithm>
#include <string>

#include "tubeform/core/core.hpp"
#include "tubeform/driver/answer.hpp"

namespace tf {

namespace {

// "C/t 0.6377, C1/C2 1.0049 (C1 18.825 mm across the press, C2 18.734 mm along it)"; with `from`, the half-extents'
// changes from it.
std::string Shape(const ShapeAt &s, const ShapeAt *from)
{
  std::string out = Formatted("C/t %.4f, C1/C2 %.4f (C1 %.4f mm", s.c_over_t, s.Ratio(), s.c1);
  if (from) out += Formatted(" (%+.4f)", s.c1 - from->c1);
  out += Formatted(" across the press, C2 %.4f mm", s.c2);
  if (from) out += Formatted(" (%+.4f)", s.c2 - from->c2);
  return out + " along it)";
}

// The load line of a pass: at its end, the largest, at the reported strokes.
std::string LoadLine(const Answer &a, const PassAnswer &s)
{
  const char *u = a.stroke_name.c_str(), *unit = a.load_unit.c_str();
  std::string out =
    Formatted("load at the end of loading (%s = %.4g) %.5g %s, largest %.5g", u, s.stroke, s.load, unit, s.load_max);
  if (s.strokes.size() < 2) return out;
  std::string at, where;
  for (size_t k = 0; k + 1 < s.strokes.size(); ++k) {
    at += Formatted(k ? ", %.5g" : "%.5g", s.loads[k]);
    where += Formatted(k ? ", %g" : "%g", s.strokes[k]);
  }
  return out + "; at " + u + " = " + where + ": " + at;
}

// The estimate of a pass: "load 12 %, C/t 0.04".
std::string Errors(const Answer &a, const PassAnswer &s)
{
  double load = 0, ct = s.ct_unloaded_error;
  for (size_t k = 0; k < s.strokes.size(); ++k)
    load = std::max(load, s.load_error[k]), ct = std::max(ct, s.ct_error[k]);
  return Formatted("load %.2g %%", 100 * load) + (a.tool ? Formatted(", C/t %.2g", ct) : "");
}

PetscErrorCode PrintPass(MPI_Comm comm, const Answer &a, size_t p)
{
  const PassAnswer &s = a.passes[p];
  const std::string pass = p == 0 ? "" : "second pass: ";
  PetscFunctionBeginUser;
  if (p > 0)
    PetscCall(PetscPrintf(comm, "tubeform: second pass, its upper die from %s = %s to %s mm:\n", a.stroke_name.c_str(),
                          Formatted("%.4g", s.start).c_str(), Formatted("%.4g", s.stroke).c_str()));
  PetscCall(PetscPrintf(comm, "tubeform: %s%s\n", pass.c_str(), LoadLine(a, s).c_str()));
  if (s.transient_max > 0)
    PetscCall(PetscPrintf(comm,
                          "tubeform: %sa dynamic transient reads %.5g N/mm at U = %.4g (a local snap resolved with "
                          "inertia: the wall's impact, not the quasi-static curve; docs/results.md)\n",
                          pass.c_str(), s.transient_max, s.transient_stroke));
  if (!a.tool) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PetscPrintf(comm, "tubeform: %sloaded: %s\n", pass.c_str(), Shape(s.loaded, nullptr).c_str()));
  if (s.springback)
    PetscCall(PetscPrintf(comm, "tubeform: %safter springback (%s): %s\n", pass.c_str(), a.release.c_str(),
                          Shape(s.unloaded, &s.loaded).c_str()));
  PetscFunctionReturn(PETSC_SUCCESS);
}

} // namespace

PetscErrorCode PrintAnswer(MPI_Comm comm, const Answer &a, double target_load, double target_ct)
{
  PetscFunctionBeginUser;
  for (size_t p = 0; p < a.passes.size(); ++p) PetscCall(PrintPass(comm, a, p));
  if (!a.estimated) PetscFunctionReturn(PETSC_SUCCESS);
  std::string line =
    a.mesh_covered
      ? Formatted("estimated error (an upper bound: %g x the difference from a run at half the resolution): ",
                  kEstimateSafety)
      : Formatted("estimated error of the increments alone (%g x the difference from a run with half as many; "
                  "the mesh is -mesh_file's, whose error this run does not estimate): ",
                  kEstimateSafety);
  for (size_t p = 0; p < a.passes.size(); ++p) {
    const PassAnswer &s = a.passes[p];
    line += p == 0 ? "" : "; second pass: ";
    line += s.estimated ? Errors(a, s) : "none (the companion run did not reach it)";
  }
  if (target_load > 0)
    line += Formatted(a.mesh_covered ? " (targets %.3g %%, %.3g)" : " (the targets %.3g %%, %.3g unchecked)",
                      100 * target_load, target_ct);
  PetscCall(PetscPrintf(comm, "tubeform: %s\n", line.c_str()));
  if (!a.mesh_covered) PetscFunctionReturn(PETSC_SUCCESS); // (no bound to hold against the targets)
  const bool over =
    (target_load > 0 && a.worst_load_error > target_load) || (a.tool && target_ct > 0 && a.worst_ct_error > target_ct);
  if (over)
    PetscCall(PetscPrintf(comm, "tubeform: warning: the estimated error passes the accuracy target, which this "
                                "run therefore cannot confirm: refine (-mesh_density, -mesh_nt, -increments) or "
                                "take a more accurate preset (docs/accuracy.md)\n"));
  PetscFunctionReturn(PETSC_SUCCESS);
}

} // namespace tf
