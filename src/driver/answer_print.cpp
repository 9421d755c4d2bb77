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

// Where a pass's largest error of one quantity is (`errors`: at each reported stroke; `after`: after springback,
// or null) and the largest at the other places.
struct Worst {
  ErrorParts parts;
  std::string where;    // "at U = 4.2", "after springback"
  double elsewhere = 0; // the largest total at the other places
};
Worst WorstOf(const Answer &a, const PassAnswer &s, const std::vector<ErrorParts> &errors, const ErrorParts *after)
{
  Worst w;
  size_t at = errors.size(); // (after springback)
  if (after) w.parts = *after;
  for (size_t k = 0; k < errors.size(); ++k)
    if (errors[k].Total() > w.parts.Total()) w.parts = errors[k], at = k;
  for (size_t k = 0; k < errors.size(); ++k)
    if (k != at) w.elsewhere = std::max(w.elsewhere, errors[k].Total());
  if (after && at < errors.size()) w.elsewhere = std::max(w.elsewhere, after->Total());
  w.where = at < errors.size() ? Formatted("at %s = %g", a.stroke_name.c_str(), s.strokes[at]) : "after springback";
  return w;
}

// The pass's largest estimated errors, where each is, its mesh's part and its increments', and the largest at the
// other reported strokes.
std::string Errors(const Answer &a, const PassAnswer &s)
{
  const Worst load = WorstOf(a, s, s.load_parts, nullptr);
  const Worst ct = WorstOf(a, s, s.ct_parts, s.springback ? &s.ct_unloaded_parts : nullptr);
  const bool several = s.strokes.size() + (s.springback ? 1 : 0) > 1;
  const auto parts = [&](const Worst &w, double unit, const char *sign) {
    std::string in = a.mesh_covered ? Formatted("mesh %.2g%s, increments %.2g%s", unit * w.parts.mesh, sign,
                                                unit * w.parts.steps, sign)
                                    : std::string();
    if (w.parts.Total() <= 0) return in.empty() ? in : " (" + in + ")"; // (nothing to locate)
    if (several) in += Formatted("%s%.2g%s at most elsewhere", in.empty() ? "" : "; ", unit * w.elsewhere, sign);
    return " " + w.where + (in.empty() ? "" : " (" + in + ")");
  };
  return Formatted("load %.2g %%", 100 * load.parts.Total()) + parts(load, 100, " %") +
         (a.tool ? Formatted(", C/t %.2g", ct.parts.Total()) + parts(ct, 1, "") : "");
}

// What the estimate is held against: the demanded targets (only those given) or what the preset expects.
std::string Targets(const Answer &a)
{
  if (!a.demanded)
    return Formatted(a.mesh_covered ? " (the preset expects %.3g %%, %.3g)"
                                    : " (the preset expects %.3g %%, %.3g unchecked)",
                     100 * a.target_load, a.target_ct);
  std::string named;
  if (a.target_load > 0) named += Formatted("load %.3g %%", 100 * a.target_load);
  if (a.tool && a.target_ct > 0) named += (named.empty() ? "" : ", ") + Formatted("C/t %.3g", a.target_ct);
  if (named.empty()) return "";
  return Formatted(" (%s %s%s)", a.mesh_covered ? "target" : "the target", named.c_str(),
                   a.mesh_covered ? "" : " unchecked");
}

PetscErrorCode PrintPass(MPI_Comm comm, const Answer &a, size_t p)
{
  const PassAnswer &s = a.passes[p];
  const std::string pass = p == 0 ? "" : PassOrdinal((int)p) + " pass: ";
  PetscFunctionBeginUser;
  if (p > 0)
    PetscCall(PetscPrintf(comm, "tubeform: %s pass, its upper die from %s = %s to %s mm:\n",
                          PassOrdinal((int)p).c_str(), a.stroke_name.c_str(), Formatted("%.4g", s.start).c_str(),
                          Formatted("%.4g", s.stroke).c_str()));
  PetscCall(PetscPrintf(comm, "tubeform: %s%s\n", pass.c_str(), LoadLine(a, s).c_str()));
  if (s.transient_max > 0)
    PetscCall(PetscPrintf(comm,
                          "tubeform: %sa dynamic transient reads %.5g N/mm at U = %.4g (a local snap resolved with "
                          "inertia: the wall's impact, not the quasi-static curve; docs/results.md)\n",
                          pass.c_str(), s.transient_max, s.transient_stroke));
  if (!a.tool) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PetscPrintf(comm, "tubeform: %sloaded: %s\n", pass.c_str(), Shape(s.loaded, nullptr).c_str()));
  if (s.springback)
    PetscCall(PetscPrintf(comm, "tubeform: %safter springback (%s): %s\n", pass.c_str(), s.release.c_str(),
                          Shape(s.unloaded, &s.loaded).c_str()));
  PetscFunctionReturn(PETSC_SUCCESS);
}

} // namespace

PetscErrorCode PrintAnswer(MPI_Comm comm, const Answer &a, bool finer_follows, const std::string &why)
{
  PetscFunctionBeginUser;
  for (size_t p = 0; p < a.passes.size(); ++p) PetscCall(PrintPass(comm, a, p));
  if (!a.estimated) PetscFunctionReturn(PETSC_SUCCESS);
  std::string line =
    !a.mesh_covered ? "estimated error of the increments alone (the mesh is -mesh_file's, whose error this run "
                      "does not estimate): "
    : !a.wall_covered
      ? Formatted("estimated error (the mesh's part around the tube and the increments' from two companion runs; not "
                  "the wall's: its %d cells through are the companions' too): ",
                  (int)kCompanionMinNt)
    : a.estimate_level > 0 ? Formatted("estimated error (the mesh's part from level %d, its cells %.2g times as large, "
                                       "the increments' from its cells at twice its increment limits): ",
                                       a.estimate_level, a.estimate_ratio)
                           : "estimated error (the mesh's part and the increments' from two companion runs): ";
  for (size_t p = 0; p < a.passes.size(); ++p) {
    const PassAnswer &s = a.passes[p];
    line += p == 0 ? "" : "; " + PassOrdinal((int)p) + " pass: ";
    line += s.estimated ? Errors(a, s) : "none (a companion run did not reach it)";
  }
  if (a.target_load > 0 || a.target_ct > 0) line += Targets(a);
  PetscCall(PetscPrintf(comm, "tubeform: %s\n", line.c_str()));
  if (!a.Over()) PetscFunctionReturn(PETSC_SUCCESS);
  const std::string unread = Formatted("the estimate does not read the wall's %d cells through", (int)kCompanionMinNt);
  if (finer_follows)
    PetscCall(PetscPrintf(comm, "tubeform: %s: %s (accuracy on demand)\n",
                          a.ErrorOver() ? "the estimate passes the target" : unread.c_str(), why.c_str()));
  else if (a.demanded)
    PetscCall(PetscPrintf(comm,
                          "tubeform: warning: %s (%s): allow more levels or time (-target_levels, -target_time; "
                          "docs/accuracy.md)\n",
                          a.ErrorOver()
                            ? "the estimated error passes the target, which this run therefore cannot confirm"
                            : (unread + ", so this run cannot confirm the target").c_str(),
                          why.c_str()));
  else
    PetscCall(PetscPrintf(comm, "tubeform: warning: the estimated error passes what the preset expects, which this "
                                "run therefore cannot confirm: name the accuracy you need (-target_load, "
                                "-target_c_over_t: finer levels follow until the estimate meets it) or refine "
                                "(-mesh_density, -mesh_nt, -increments; docs/accuracy.md)\n"));
  PetscFunctionReturn(PETSC_SUCCESS);
}

} // namespace tf
