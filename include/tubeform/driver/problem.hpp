// A run: the distributed mesh, the material, the per-Gauss-point state, the
// global system and the incremental loop. Scenes add their loads, supports
// and measurements through the Scene interface.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "tubeform/assembly/system.hpp"
#include "tubeform/driver/options.hpp"
#include "tubeform/fe/qm6.hpp"
#include "tubeform/io/history.hpp"
#include "tubeform/material/elastic.hpp"
#include "tubeform/mesh/mesh.hpp"
#include "tubeform/step/rmin.hpp"

namespace tf {

class Problem;

// What a scene decides: its mesh, its supports and loads per increment, and
// what `stroke` and `load` mean in its history.
class Scene {
public:
  virtual ~Scene() = default;
  virtual std::vector<std::string> BoundarySets() const = 0;
  // Once, before the first increment (tools, initial contacts).
  virtual PetscErrorCode Initialize(Problem &p) { return 0; }
  // Before each increment's assembly (node frames that the assembly needs).
  virtual PetscErrorCode BeginIncrement(Problem &p, double lambda) { return 0; }
  // Rank 0 only: the serial mesh (structured or read from -mesh_file).
  virtual std::string BuildMesh(const Options &opt, SerialMesh &mesh) const = 0;
  // Adds the load increment for lambda -> lambda + dlambda (lambda in [0, 1])
  // and the prescribed dofs to the system; returns the nodal load of the
  // increment per unit dlambda in `dforce` (local vector) for the work.
  virtual PetscErrorCode Load(Problem &p, double lambda, double dlambda, Vec dforce) = 0;
  // Total external load vector at lambda on the current geometry (local vector).
  virtual PetscErrorCode ExternalForce(Problem &p, double lambda, Vec f) = 0;
  // Fills stroke and load (and scene metrics) of the history row. `f_int` is
  // the internal force of the current state (local vector, global frame).
  virtual PetscErrorCode Measure(Problem &p, double lambda, Vec f_int, HistoryRow &row) = 0;
  // Values of lambda where the load path changes (an increment never crosses one).
  virtual std::vector<double> Breakpoints() const { return {}; }
  // Scene-specific limits on the trial increment (contact: r4-r6).
  virtual PetscErrorCode LimitStep(Problem &p, Vec du_trial, StepLimit &limit) { return 0; }
  // State switches the trial solution calls for (contact nodes pulled off the
  // tool without force): counted, applied with `apply`; the step is re-solved.
  virtual PetscErrorCode Switches(Problem &p, Vec du, bool apply, PetscInt &n)
  {
    n = 0;
    return 0;
  }
  // Non-linear loads (friction): the increment is solved by iteration.
  virtual bool Iterative() const { return false; }
  virtual void ResetIterates() {}
  // The friction linearized once about the state at the start of the
  // increment (the paper's one-solve step), keeping the trial's active set.
  virtual void LinearizeAtStart() {}
  virtual PetscErrorCode UpdateIterates(Problem &p, Vec du, bool &converged)
  {
    converged = true;
    return 0;
  }
  // Accepts the increment du of the last Load (its reactions scaled by
  // react_scale; r the fraction of the solved step that was taken, for events).
  virtual PetscErrorCode CommitIncrement(Problem &p, Vec du, double react_scale, double r, double &w_friction)
  {
    w_friction = 0;
    return 0;
  }
  // The load path runs over lambda in [0, PathEnd()] (> 1 with an unloading stage).
  virtual double PathEnd() const { return 1.0; }
  // Time (s) of lambda 0 -> 1 for -dynamics implicit (tool scenes: stroke / punch speed).
  virtual double Duration(const Options &opt) const { return opt.dynamics_time; }
  // Called before the first increment that starts at a breakpoint.
  virtual PetscErrorCode BeginStage(Problem &p, double lambda) { return 0; }
  // Scene metrics written as attributes at the end.
  virtual std::vector<std::pair<std::string, double>> FinalMetrics(const History &h) const { return {}; }
};

std::unique_ptr<Scene> CreateScene(const Options &opt);

class Problem {
public:
  Problem() = default;
  Problem(const Problem &) = delete;
  Problem &operator=(const Problem &) = delete;
  ~Problem();

  PetscErrorCode Setup(MPI_Comm comm, const Options &opt);
  // Setup with a scene made by the caller (tests).
  PetscErrorCode Setup(MPI_Comm comm, const Options &opt, std::unique_ptr<Scene> scene);
  PetscErrorCode Run();

  // Building blocks (also used by tests).
  PetscErrorCode AssembleTangent();
  // What the trial increment du would do at the Gauss points: r1 (yield
  // onset), r2 (strain), r3 (rotation) into `limit`; `switches` counts the
  // points whose loading state (alpha) disagrees with du, and with
  // `apply` those points are switched.
  PetscErrorCode ScanTrial(Vec du, bool apply, StepLimit &limit, PetscInt &switches);
  struct CommitInfo {
    double dw_int = 0, dw_plastic = 0, drift = 0;
    PetscInt n_plastic = 0;
  };
  // Advances stress, coordinates and displacement by du (local vector). Elastic
  // points whose yield factor (from the last ScanTrial) is within
  // (1 + group_tol) of `r` turn plastic.
  PetscErrorCode Commit(Vec du, double r, CommitInfo &info);
  PetscErrorCode InternalForce(Vec f_local);
  // From now on every point is elastic (the paper's unloading).
  void SetElasticOnly();
  // Current cell corner coordinates.
  void CellCoordinates(PetscInt cell, double xe[8]) const;

  const Options &options() const { return opt_; }
  Mesh &mesh() { return mesh_; }
  System &system() { return system_; }
  const std::vector<PointState> &state() const { return state_; }
  const std::vector<double> &position() const { return x_; }  // current coordinates, 2 per local node
  const std::vector<double> &displacement() const { return u_; }
  MPI_Comm comm() const { return comm_; }
  PetscMPIInt rank() const { return rank_; }
  const History &history() const { return history_; }
  // A contact node whose normal force would reach zero within this fraction of
  // the step being solved is released in the trial instead of limiting it (r5):
  // round-off without inertia; with inertia, the shortest step it may take.
  double release_fraction() const { return release_fraction_; }

private:
  MPI_Comm comm_ = MPI_COMM_NULL;
  PetscMPIInt rank_ = 0, size_ = 1;
  Options opt_;
  std::unique_ptr<Scene> scene_;
  std::unique_ptr<Material> material_;
  Mesh mesh_;
  System system_;
  std::vector<PointState> state_; // 4 per local cell
  std::vector<double> yield_factor_; // r1 of each Gauss point from the last ScanTrial
  std::vector<fe::Condensation> condensation_; // QM6: internal dofs = cond * du, per cell, from the last assembly

  // The element formulation behind one interface (Q4/B-bar or QM6).
  bool CellStiffness(PetscInt e, const double xe[8], const Mat4 c[4], const Voigt s[4], fe::ElemMat &ke);
  bool CellKinematics(PetscInt e, const double xe[8], const fe::QuadGeometry &geo, int g, const fe::ElemVec &du, Voigt &deps, double &omega) const;
  bool CellInternalForce(PetscInt e, const double xe[8], const fe::QuadGeometry &geo, const Voigt s[4], fe::ElemVec &f) const;
  std::vector<double> x_, u_;      // per local node, global frame
  History history_;
  bool converged_ = true; // did the last SolveTrial settle
  PetscInt unsettled_ = 0; // trial steps taken without settled iterations (after kMaxCuts halvings)
  static constexpr int kMaxCuts = 6;
  Vec f_inc_ = nullptr, f_res_ = nullptr; // load of the trial step; out-of-balance force of the last increment

  // -dynamics implicit (docs/theory.md, "Inertia"): row-sum lumped masses (4
  // per local cell, on the initial configuration: mass is conserved), node
  // velocity and acceleration (2 per local node, global frame), and the time
  // step of the system being assembled (0: quasi-static, no inertia terms).
  std::vector<double> mass_, v_, a_;
  double dt_ = 0, duration_ = 1; // duration_: time (s) of lambda 0 -> 1
  bool inertia_ = false;          // inertia in the increments (-dynamics implicit, or auto once switched)
  double release_fraction_ = 1e-9; // see release_fraction()
  // Backward Euler about (v_, a_): adds M / dt^2 to the cell blocks (in
  // AssembleTangent) and M (a + v / dt) to the loads (here).
  PetscErrorCode AddInertiaLoad();
  // New velocity and acceleration after the increment du over dt_; returns the
  // work of the inertia forces over it (trapezoidal, as the external work).
  PetscErrorCode AdvanceInertia(Vec du, double &dw_inertia);
  // Adds M a (per-cell contributions, global frame) to a local force vector.
  PetscErrorCode AddInertiaForce(Vec f_local);
  PetscErrorCode KineticEnergy(double &w);
  // The shortest step inertia allows, as a fraction of a step of dl.
  double MinStepFraction(double dl) const;
  template <class F>
  void ForEachMassShare(F &&f) const;

  PetscErrorCode ElasticEnergy(double &w);
  PetscErrorCode CreateMaterial();
  // One trial solution for the load step dl: friction iterations and
  // loading/unloading re-solves, then the r factors into `limit`. A trial whose
  // iterations do not settle sets converged_ = false, unless it is the `last`
  // try (then it is solved once with the friction linearized at the increment
  // start, taken, and counted in unsettled_).
  PetscErrorCode SolveTrial(double lambda, double dl, Vec du, StepLimit &limit, PetscInt &redo, PetscInt &iterations, bool last);
  PetscErrorCode WriteOutputs(class ResultWriter &writer, PetscInt step, double t);
};

} // namespace tf
