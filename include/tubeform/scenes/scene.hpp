// What a scene decides (docs/scenes.md): its mesh, its load path, its
// tools, its supports and loads per increment, and what `stroke` and `load`
// mean in its history. The driver owns everything else: the body, the
// global system, the increments, and the contact set the scene asks for.
#pragma once

#include <petscvec.h>

#include <string>
#include <utility>
#include <vector>

#include "tubeform/assembly/system.hpp"
#include "tubeform/body/body.hpp"
#include "tubeform/contact/contact.hpp"
#include "tubeform/io/history.hpp"
#include "tubeform/io/options.hpp"
#include "tubeform/mesh/mesh.hpp"
#include "tubeform/mesh/serial_mesh.hpp"

namespace tf {

// Values of the load parameter lambda this close are the same point of the path.
constexpr double kLambdaTol = 1e-12;

// What a scene sees of a run.
struct Model {
  MPI_Comm comm;
  Mesh &mesh;
  System &system;
  Body &body;
  ContactSet *contact; // the driver's contact set; null when the scene has no tools
  bool quiet = false;  // a companion run (the error estimate's): the scene prints no notes
};

// The load path: lambda runs over [0, end]; lambda 0 -> 1 takes `duration`
// seconds of -dynamics implicit; an increment never crosses a breakpoint.
struct LoadPath {
  double end = 1.0;
  double duration = 1.0;
  std::vector<double> breakpoints;
  std::vector<double> kinks; // where an increment ends too, inside a stage (a tool's path turning)
};

class Scene {
public:
  virtual ~Scene() = default;

  // Rank 0 only: the serial mesh (structured or read from -mesh_file) and the
  // boundary sets it must carry.
  virtual std::vector<std::string> BoundarySets() const = 0;
  virtual std::string BuildMesh(const Options &opt, SerialMesh &mesh) const = 0;
  // The structured mesh's counts as the run reports them (a tube's by default).
  virtual std::string MeshLayout(const Options &opt) const
  {
    return "-mesh_nt " + std::to_string(opt.mesh_nt) + " through the wall x -mesh_ntheta " +
           std::to_string(opt.mesh_ntheta) + " around";
  }
  // The load path; read again at each stage's start (its end, duration and stages the same: a kink a later pass
  // knows once it starts, as its lower die's strokes from where its dies start) and on a restart.
  virtual LoadPath Path(const Options &opt) const = 0;

  // Once, before the first increment: the tools the scene presses against the
  // body (`tools` left without a candidate set: no contact at all).
  virtual PetscErrorCode Initialize(Model &m, ContactSpec &tools) { return 0; }
  // Tool stroke at lambda (the tools move rigidly by it along their direction).
  virtual double ToolStroke(double lambda) const { return 0; }
  // The force a force-controlled tool (Tool::pad) puts on the model along its direction at lambda (N/mm).
  virtual double ToolForce(double lambda) const { return 0; }
  // Before the first increment that starts at a breakpoint.
  virtual PetscErrorCode BeginStage(Model &m, double lambda) { return 0; }
  // Whether the stage at lambda unloads (its trial steps are -unload_increments'): all past lambda = 1 by default.
  virtual bool Unloading(double lambda) const { return lambda >= 1 - kLambdaTol; }
  // Before each increment's assembly (node frames the scene's supports need).
  virtual PetscErrorCode BeginIncrement(Model &m, double lambda) { return 0; }
  // Supports and loads of the increment lambda -> lambda + dlambda into the system.
  virtual PetscErrorCode Load(Model &m, double lambda, double dlambda) = 0;
  // The scene's applied loads at lambda on the current geometry (local vector;
  // the contact forces are the driver's).
  virtual PetscErrorCode ExternalForce(Model &m, double lambda, Vec f) = 0;
  // Fills stroke and load (and scene metrics) of the history row. `f_int` is
  // the internal force of the current state (local vector, global frame).
  virtual PetscErrorCode Measure(Model &m, double lambda, Vec f_int, HistoryRow &row) = 0;
  // Work done on the model per unit of load x stroke (history columns) in the
  // stage at lambda, where the two are work-conjugate (a tool pressing the
  // quarter tube: 0.5, the load being the full tube's); 0 where they are not.
  // The energy check then takes its input from the reported load
  // (docs/theory.md, "Self-checks").
  virtual double LoadWorkShare(double lambda) const { return 0; }
  // The tools' work on the model over a step from `prev` to `row` where LoadWorkShare (`share`) is not 0: by
  // default the reported load over the stroke, the trapezoid rule; a scene with several tools whose forces
  // differ sums each one's over its own travel.
  virtual double ToolWork(const HistoryRow &prev, const HistoryRow &row, double share) const
  {
    return share * 0.5 * (prev.load + row.load) * (row.stroke - prev.stroke);
  }
  // Collective: writes or reads the state the scene carries between
  // increments (a stage's loads) for checkpoints; none by default.
  virtual PetscErrorCode Persist(Model &m, Archive &ar) { return 0; }
  // How the run's summary line names `stroke` and the unit of `load` (docs/scenes.md).
  virtual const char *StrokeName() const { return "U"; }
  virtual const char *LoadUnit() const { return "N/mm"; }
  // How pass `pass` (0 the first) lets the tube go, for the summary's springback line ("" where nothing does).
  virtual std::string ReleaseOf(int pass) const { return ""; }
  // Scene metrics written as attributes at the end.
  virtual std::vector<std::pair<std::string, double>> FinalMetrics(const History &h) const { return {}; }
};

} // namespace tf
