// Pieces the scenes share: loads, supports and measurements of the quarter
// models.
#pragma once

#include <petscvec.h>

#include <string>

#include "tubeform/metrics/shape.hpp"
#include "tubeform/scenes/pass_spec.hpp"
#include "tubeform/scenes/scene.hpp"

namespace tf {

// Uniform pressure on the edges of a boundary set (current geometry): nodal
// forces into f_local (if given) and into the system (with to_system), and
// the follower-load stiffness of the pressure stiffness_p into the system.
PetscErrorCode AddEdgePressure(Model &m, const std::string &set, double pressure, Vec f_local, bool to_system,
                               double stiffness_p = 0);
// The displacement along the global unit direction (dx, dy) held at 0 on a node set (an axis of each node's frame).
PetscErrorCode HoldAlong(Model &m, const std::string &set, double dx, double dy);
// u_x = 0 on x = 0, u_y = 0 on y = 0, in each node's frame.
PetscErrorCode QuarterSymmetry(Model &m);
// The part of the tube a tool scene models: the quarter x, y >= 0, the half x >= 0, or the whole tube.
enum class TubePart { Quarter, Half, Full };
// It models both dies, above and below the tube (the half and the full model).
inline bool BothDies(TubePart part) { return part != TubePart::Quarter; }
// It models the whole tube, its dies across the y axis (the full model).
inline bool WholeTube(TubePart part) { return part == TubePart::Full; }
// The side dies' force in the model per side die's force on the whole tube: the quarter carries the upper half
// of one, the half model one, the full model two (-side_die).
inline double SideDiesInModel(TubePart part)
{
  return part == TubePart::Full ? 2.0 : part == TubePart::Half ? 1.0 : 0.5;
}
// Whether a pass's springback by `release` is elastic: -springback elastic, or auto under the paper's release, reverse
// (its dead loads can drive a thin wall into a collapse by the material's law; docs/theory.md, "Unloading").
inline bool ElasticRelease(const Options &opt, Unload release)
{
  return opt.release.springback == Springback::Elastic ||
         (opt.release.springback == Springback::Auto && release == Unload::Reverse);
}
// C1 = x_max, C2 = y_max of the outer surface (the half model's C2 half its height, the full model's C1 half
// its width) and their ratio. A pass that turned the tube measures in its press's frame: `press` maps the
// tube's coordinates there (the inverse of the map that drew its dies).
PetscErrorCode OuterExtents(Model &m, HistoryRow &row, TubePart part = TubePart::Quarter, const TurnMap &press = {});
// Collective: the outer-surface nodes of the whole mesh on every rank, along the surface by angle (contact
// state, and the segment of the upper die, tool 0, a node touches). With `upper`, only the nodes that started
// in the quarter x, y >= 0 (the half and full models' upper right quarter, on which the shape metrics are
// measured as in the quarter model). Coordinates, and the quarter, in the press's frame (`press`).
PetscErrorCode GatherOuter(Model &m, std::vector<SurfacePoint> &all, bool upper = false, const TurnMap &press = {});
// Collective: the same where the mesh put the nodes (the round tube before any pass), in the tube's frame.
PetscErrorCode GatherRoundOuter(Model &m, std::vector<SurfacePoint> &all);
// The outer surface `all` in order around the tube from the point opposite the side between the nodes of input
// numbers ends[0], ends[1] (so that the side lies between its ends in that order, whatever quarter it is in;
// GatherOuter's order starts at -pi).
void OrderAroundSide(std::vector<SurfacePoint> &all, const long ends[2]);
// Collective: the lowest y of the outer surface in the press's frame (where a floor goes under the tube).
PetscErrorCode LowestOuterY(Model &m, double &y, const TurnMap &press = {});

// The half and full models' supports where no die holds the tube (scenes/pins.cpp).
// Collective: the springback's pin (the tube's rigid motion along the press's y, held along press.Inverse() of
// (0, 1)): the local index of the inner node nearest the press's x axis on its positive side (a node on it
// keeps y = 0 in a symmetric case; the lowest input number among equals), or -1 where another rank has it.
PetscErrorCode ChooseSpringbackPin(Model &m, PetscInt &pin, const TurnMap &press = {});
// A mesh node this close to the y axis (relative to its height) is on it.
constexpr double kAxisPin = 1e-9;
// Collective: the full model's pins, node set "axis": the outer nodes on the press's y axis at the tube's top
// and at its bottom, whose press x held (HoldAlong along press.Inverse() of (1, 0)) holds the tube's rotation
// and its motion along the press's x (exactly, in a press symmetric about its y axis: their x stays 0); an
// error on every rank if the mesh has none. Not `exact`, or in a press turned by an angle that is no quarter turn
// (press.angle), the surface's nodes nearest the axis (by angle). With `surface` "inner" and `set` "hold": the rotation
// hold's nodes (scenes/hold.hpp).
PetscErrorCode MarkAxisPins(Model &m, const TurnMap &press = {}, const char *surface = "outer",
                            const char *set = "axis", bool exact = true);
// A press's summary metrics per pass: the loaded state (the last row of its press, stage 2 p) and the unloaded
// one (the last of its release): loaded_* and unloaded_* of C/t, C1/C2, x_max, y_max for the first pass (as the
// run's summary), pass2_loaded_* and so on for the second, pass3_* for the third, ...
std::vector<std::pair<std::string, double>> PassMetrics(const History &h);
// The tube mesh of the options: structured (the part asked) or -mesh_file.
std::string TubeMesh(const Options &opt, SerialMesh &mesh, TubePart part = TubePart::Quarter);
// The history's stage: 0 up to lambda = 1, 1 up to 2 (unloading, or a scene's second stage), and so on.
inline double StageOf(double lambda)
{
  int stage = 0;
  while (lambda > stage + 1.0 + kLambdaTol) ++stage;
  return stage;
}

// Sum over ranks of each rank's element contributions at the nodes of a set
// (owned and ghost: every contribution is counted once), dotted with `dir(n)`.
template <class Dir>
PetscErrorCode SetForce(Model &m, const std::string &set, Vec f_local, Dir dir, double &total)
{
  const PetscScalar *f;
  double local = 0;
  PetscFunctionBeginUser;
  PetscCall(VecGetArrayRead(f_local, &f));
  for (PetscInt n : m.mesh.node_sets[set]) {
    double d[2];
    dir(n, d);
    const PetscInt o = m.mesh.node_dof[n];
    local += d[0] * PetscRealPart(f[o]) + d[1] * PetscRealPart(f[o + 1]);
  }
  PetscCall(VecRestoreArrayRead(f_local, &f));
  PetscCall(MPIU_Allreduce(&local, &total, 1, MPIU_REAL, MPIU_SUM, m.comm));
  PetscFunctionReturn(PETSC_SUCCESS);
}

// Volume-free average over all Gauss points of a function of the point state.
template <class F>
PetscErrorCode PointAverage(Model &m, F f, double &avg)
{
  double local[2] = {0, 0}, g[2];
  PetscFunctionBeginUser;
  for (const auto &ps : m.body.state()) local[0] += f(ps), local[1] += 1;
  PetscCall(MPIU_Allreduce(local, g, 2, MPIU_REAL, MPIU_SUM, m.comm));
  avg = g[0] / g[1];
  PetscFunctionReturn(PETSC_SUCCESS);
}

} // namespace tf
