// The deformable body: its current coordinates and displacements, the state
// of every Gauss point, the material law and the element formulation, and
// the loops over the cells that the incremental method needs (docs/theory.md,
// sections 1-5): the tangent K into the global system, the scan of a
// trial increment for r1-r3 and loading switches, the commit of an
// increment, the internal force and the stored elastic energy.
#pragma once

#include <petscvec.h>

#include <algorithm>
#include <memory>
#include <utility>
#include <vector>

#include "tubeform/assembly/system.hpp"
#include "tubeform/fe/formulation.hpp"
#include "tubeform/material/elastic.hpp"
#include "tubeform/mesh/archive.hpp"
#include "tubeform/mesh/mesh.hpp"
#include "tubeform/step/rmin.hpp"

namespace tf {

// QM6's modes in balance (equilibrium iterations): corrections per cell of
// the modes cond du (Kii is their exact stiffness for a linear step, so one
// removes all but the step's second-order part of their force; a second
// changed the load by less than 1e-4 on the default preset).
constexpr int kModeCorrections = 1;
// Midpoint kinematics: the equilibrium corrections take the tangent at their
// iterate (Body::AssembleIterateTangent) in every cell where the bulk modulus
// is at least this many times the shear modulus (nu >= 0.45): the start's
// tangent is off in the volumetric strain by the order of the strain
// increment, which K multiplies; from K/G 10 that error is an order above the
// deviatoric one, and at nu 0.49 (K/G 50) the start's tangent took 5.2
// factorizations an increment against 3.8. Below it the start's tangent
// stays (the iterate's costs 23 % more CPU on the default case at nu 0.34 for
// 1.4 % fewer factorizations). A constant of the material, not a threshold on
// the iterate: a choice round-off could flip cell by cell parted runs of one
// thin tube on two OpenBLAS kernels (docs/theory.md, 5a).
constexpr double kNearlyIncompressible = 10;

struct BodyParams {
  fe::Formulation element = fe::Formulation::BBar;
  MaterialParams material;
  double rmin_deps = 2e-3; // r2: largest principal strain increment
  // r2 relative to the material: the strain increment also at most this many
  // initial yield strains sigma_y0 / E (0: off). A step many yield strains
  // long carries a point's stress far around the yield surface at once.
  double rmin_deps_yield = 0;
  double rmin_domega = 1e-2; // r3: largest rotation increment (rad)
  double group_tol = 1e-6;   // points reaching yield within (1 + tol) r_min turn plastic together
  // r1 off: points yield inside a step, with the tangent weighted by the step's
  // elastic fraction m, m D_e + (1 - m) D_ep(onset stress), and the update split
  // at the onset; the step is re-solved while any m moves by more than yield_tol.
  bool yield_inside = false;
  double yield_tol = 0.05;
  bool drift_correction = false;
  PlasticUpdate plastic_update = PlasticUpdate::Tangent;
  // The stress update takes a point's loading state from its strain increment
  // (on the yield surface and loading), not from its tangent's (equilibrium iterations).
  bool state_from_strain = false;
  ObjectiveScheme kinematics = ObjectiveScheme::Forward;
};

class Body {
public:
  // Collective: the material and the initial state on the cells of `mesh`.
  PetscErrorCode Setup(const Mesh &mesh, const BodyParams &prm);

  // Collective: K of the current state into `system` (after System::Begin,
  // before other terms): the system's kept body matrix, updated by the cells
  // whose tangent changed since the last call, or rebuilt.
  PetscErrorCode AssembleTangent(System &system);
  // With midpoint kinematics an equilibrium correction takes the tangent at its
  // iterate (docs/theory.md, 5a): UpdateTangents (collective) brings the start's
  // cell tangents up to date without assembling them (QM6: the condensations
  // the iterate's forces take); then, after TrialForce of the iterate,
  // AssembleIterateTangent (collective; before other terms) puts K into
  // `system`: in every cell, the start's rows on the iterate's configuration
  // with the derivative of its mid-increment strain in the columns
  // (fe/midpoint.hpp; unsymmetric), where K/G reaches kNearlyIncompressible. With forward
  // kinematics the start's tangent linearizes the strain exactly: AssembleTangent.
  bool IterateTangent() const { return MidpointKinematics() && BulkToShear() >= kNearlyIncompressible; }
  bool MidpointKinematics() const { return prm_.kinematics == ObjectiveScheme::Midpoint; }
  PetscErrorCode UpdateTangents(System &system);
  PetscErrorCode AssembleIterateTangent(System &system);
  // What the trial increment du would do at the Gauss points: r1 (yield
  // onset), r2 (strain), r3 (rotation) into `limit`; `switches` counts the
  // points whose loading state (alpha) disagrees with du, and with `apply`
  // those points are switched.
  // With yield_inside, r1 does not limit; points that reach the surface inside
  // the step (elastic fraction m < 1) are counted in `transitions`, and a
  // change of their m by more than yield_tol since the tangent was assembled
  // counts as a switch (applied with `apply`: the next tangent uses the new m).
  PetscErrorCode ScanTrial(Vec du, bool apply, StepLimit &limit, PetscInt &switches, PetscInt &transitions);
  // Equilibrium corrections (on) take each plastic point's tangent where the law has one for a step
  // (Material::StepTangent: the radial return's algorithmic tangent) at the increment the last ScanTrial saw,
  // kept through the corrections while the point's loading state holds; off: the start's.
  void StepTangents(bool on);
  // yield_inside: a new step starts elastic everywhere; a step shortened by
  // `factor` keeps its transitions (m / factor).
  void ResetTransitions();
  void ScaleTransitions(double factor);
  struct CommitInfo {
    double dw_int = 0, dw_plastic = 0, drift = 0;
    PetscInt n_plastic = 0;
  };
  // Advances stress, coordinates and displacement by du (local vector).
  // Elastic points whose yield factor (from the last ScanTrial) is within
  // (1 + group_tol) of `r` turn plastic; with yield_inside, those whose yield
  // factor lies inside the step take the part up to it elastically and the
  // rest plastically.
  PetscErrorCode Commit(Vec du, double r, CommitInfo &info);
  // Collective-free: the nodal forces of the stresses (local contribution
  // vector); with `magnitude`, also the sum of the magnitudes of the cells'
  // nodal force components and their count on this rank (the force scale of
  // the equilibrium criterion).
  PetscErrorCode InternalForce(Vec f_local, double *magnitude = nullptr, double *count = nullptr) const;
  // Collective-free: the nodal forces (local contribution vector) of the state
  // the increment du (a solution scaled by r, as Commit takes it) would reach,
  // on the moved geometry; nothing is committed.
  // `magnitude`, `count`: as InternalForce.
  PetscErrorCode TrialForce(Vec du, double r, Vec f_local, double *magnitude, double *count) const;
  // Collective: the elastic energy stored in the stresses.
  PetscErrorCode ElasticEnergy(double &w) const;
  // Collective: the lowest input number of a cell whose stresses, plastic
  // strains or corners are not finite (NaN, Inf), -1 if none.
  PetscErrorCode NonFiniteCell(PetscInt &cell) const;
  // A release (the springback) begins: with `elastic` every point is elastic while it lasts (the paper's
  // unloading), else the material's law acts in it as in loading. Either way what the release does at the
  // yield surface is measured from this state on (MeasureRelease). `by_loads`: a release by loads from a state
  // at its limit load (the paper's reversed contact forces): every point starts it elastic, unloading; the
  // plastic tangents' step under the falling load would follow the collapse branch, which is consistent too
  // (docs/theory.md, "Unloading"). A release by motion unloads its points by the loading switches.
  void BeginRelease(bool elastic, bool by_loads);
  // The release is over (a press after it): the material's law again; the points of an elastic release start
  // elastic, their stress and hardening as it left them.
  void EndRelease();
  // What the release under way did at the yield surface since it began (zeros outside one).
  struct ReleaseYield {
    bool releasing = false; // a release is under way
    bool elastic = false;   // ... with every point elastic
    // The points that reached the yield surface: those that flowed (the material's law), or that the release
    // carried past it by more than kOnSurface (elastic).
    PetscInt reached = 0;
    double excess = 0; // elastic: the largest sigma_eq / sigma_y - max(1, the point's own at the release's start)
    double dep = 0;    // the material's law: the largest plastic strain taken in the release
  };
  // Collective: that measure of the current state.
  PetscErrorCode MeasureRelease(ReleaseYield &y) const;
  bool releasing() const { return releasing_; }
  // Collective: writes or reads what carries from one increment to the next
  // (point states, coordinates, displacements, the release under way).
  PetscErrorCode Persist(Archive &ar);

  // Current cell corner coordinates.
  void CellCoordinates(PetscInt cell, double xe[2 * fe::kNodes]) const;
  const Mesh &mesh() const { return *mesh_; }
  MPI_Comm comm() const { return mesh_->comm; }
  const std::vector<PointState> &state() const { return state_; } // kGauss per local cell
  // The material's own law (an elastic release does not change it).
  const Material &material() const { return law_ ? *law_ : *material_; }
  const std::vector<double> &position() const { return x_; }     // current coordinates, 2 per local node
  const std::vector<double> &displacement() const { return u_; } // total displacement, 2 per local node

private:
  const Mesh *mesh_ = nullptr;
  BodyParams prm_;
  double deps_limit_ = 0;              // r2's bound: rmin_deps, or rmin_deps_yield yield strains if smaller
  std::unique_ptr<Material> material_; // the law the points follow
  std::unique_ptr<Material> law_;      // the material's own while an elastic release replaces it (else null)
  bool releasing_ = false;             // a release is under way (BeginRelease)
  // Per point where the release began: its yield ratio (Material::YieldRatio) and plastic strain.
  std::vector<double> release_start_;
  static constexpr int kReleaseStart = 2; // (numbers per point in release_start_)
  // The points follow the elastic law (true) or the material's own.
  void ActElastic(bool elastic);
  fe::CellFormulation cells_;
  std::vector<PointState> state_;
  std::vector<double> yield_factor_; // r1 of each Gauss point from the last ScanTrial
  std::vector<double> fraction_;     // yield_inside: elastic fraction m in the assembled tangent (1: elastic)
  std::vector<PointState> onset_;    // yield_inside: state where the point meets the surface (plastic)
  std::vector<double> x_, u_;
  std::vector<std::pair<Voigt, double>> trial_; // ScanTrial: strain and spin increments of each point
  bool step_tangents_ = false;                  // StepTangents
  // Cell tangents of the last assembly; a cell is recomputed only when its
  // geometry, stresses or point tangents changed since (the friction
  // iterations and re-solves of an increment change few or none).
  std::vector<fe::ElemMat> ke_;
  std::vector<char> ke_stale_;
  // The system's kept body matrix cell by cell: a cell's block in it is its
  // start tangent ke_ (kBlockStart), or held_: a start tangent since
  // recomputed (kBlockOutdated), or its tangent at an iterate (kBlockIterate).
  enum Block : char { kBlockStart, kBlockOutdated, kBlockIterate };
  std::vector<char> block_;
  std::vector<fe::ElemMat> held_;
  // The elastic bulk to shear modulus ratio K/G = 2 (1 + nu) / (3 (1 - 2 nu)).
  double BulkToShear() const { return 2 * (1 + prm_.material.nu) / (3 * (1 - 2 * prm_.material.nu)); }

  // Cell geometry (gradients, weights) on the current coordinates, computed
  // once per configuration: the scans, internal forces and energies of an
  // increment share it. ok_ false: an inverted cell.
  struct GeometryCache {
    std::vector<fe::QuadGeometry> geo;
    std::vector<char> ok;
    bool valid = false;
  };
  mutable GeometryCache geometry_;
  // The geometry of cell e (nullptr if inverted) and its corners `xe`.
  const fe::QuadGeometry *CellGeometry(PetscInt e, double xe[2 * fe::kNodes]) const;

  // What advancing cells adds up: internal and plastic work, plastic points, largest drift.
  struct Advanced {
    double w_int = 0, w_plastic = 0, drift = 0;
    PetscInt n_plastic = 0;
  };
  // The states cell e's points reach with its nodal increments due (a solution
  // scaled by r), into to[0..kGauss); false (to untouched) if the cell's
  // geometry is inverted. Shared by Commit and TrialForce.
  // `used`: the condensation the cell's modes and forces were taken with (qm6).
  // `grad`: the velocity gradient of each point's strain and spin increments.
  bool AdvanceCell(PetscInt e, const fe::ElemVec &due, double r, PointState *to, Advanced &acc,
                   fe::Condensation *used = nullptr, fe::Gradient *grad = nullptr) const;
  // The start's point tangents and stresses of cell e (what its tangent is assembled from).
  void StartTangents(PetscInt e, Mat4 c[fe::kGauss], Voigt s[fe::kGauss]) const;
  // Cell e's tangent recomputed if stale; false if the cell is inverted (it stays stale).
  bool RefreshCell(PetscInt e);
  // Cell e's tangent at the iterate of the last TrialForce (AssembleIterateTangent); false
  // if its mid or end configuration is inverted.
  bool IterateCellTangent(PetscInt e, fe::ElemMat &ke) const;
  // Collective: stops the run naming the lowest inverted cell (bad: this rank's, -1 if none).
  PetscErrorCode CheckInverted(PetscInt bad, System &system) const;
  // qm6 with equilibrium iterations: the tangents are selected by the strain
  // increment itself (OwnTangents), not by the assembly, so that a cell's
  // forces are a function of its nodal increments (docs/theory.md, 5a).
  bool OwnTangents() const { return prm_.state_from_strain && cells_.has_modes() && material_->plastic_law(); }
  // Point i's loading state for its strain increment from the start state:
  // on the yield surface and loading (the rule of ScanTrial and AdvanceCell
  // with own tangents, whatever its tangent's flag).
  bool OwnLoading(size_t i, const Voigt &deps) const;
  // What a point's increment selects: plastic (on the surface and loading),
  // or elastic with the fraction m < 1 of the step before the yield onset
  // (yield_inside), or elastic (m = 1); its strain and spin increments.
  struct Selected {
    bool plastic = false;
    double m = 1;
    Voigt deps{};
    double omega = 0;
  };
  // The states cell e's increment due selects with the modes of the
  // condensation `cond`, on the start corners xs (geometry gs); true when
  // they differ from the assembled ones.
  bool SelectStates(PetscInt e, const double xs[2 * fe::kNodes], const fe::QuadGeometry &gs, const fe::ElemVec &due,
                    const fe::Condensation &cond, Selected sel[fe::kGauss]) const;
  // The tangents of those states.
  void SelectedTangents(PetscInt e, const Selected sel[fe::kGauss], Mat4 c[fe::kGauss]) const;
  // With own tangents: the condensation of the tangents cell e's increment due selects itself, a fixed point from
  // the assembled one (`cond`, `kii_inv`); once it takes one of its own (`own`, `own_kii_inv`), cond and kii_inv
  // point to it.
  void SelectCondensation(PetscInt e, const double xs[2 * fe::kNodes], const fe::QuadGeometry &start,
                          const fe::ElemVec &due, fe::Condensation &own, fe::ModeMatrix &own_kii_inv,
                          const fe::Condensation *&cond, const fe::ModeMatrix *&kii_inv) const;
  // The state point i reaches with strain and spin increments deps, omega;
  // adds its work (weight wdet) and drift into acc.
  PointState AdvancePoint(size_t i, const Voigt &deps, double omega, double r, double wdet, Advanced &acc) const;
  // The states of the last TrialForce, for the commit of the same increment.
  struct TrialStates {
    std::vector<double> du; // its local increment
    double r = 0;
    std::vector<PointState> states;
    std::vector<fe::Condensation> conds; // qm6: per cell, the condensation of its forces
    std::vector<fe::Gradient> grad;      // per point, the velocity gradient of its increments
    Advanced acc;
    bool valid = false;
  };
  mutable TrialStates last_trial_;
  void Stale(size_t point) { ke_stale_[point / fe::kGauss] = 1; }
  void StaleAll() { std::fill(ke_stale_.begin(), ke_stale_.end(), 1); }
  // The state where an elastic point meets the yield surface, at the fraction
  // m of its linear elastic step (deps, omega); plastic: its C_ep takes H' as
  // a plastic point would next.
  PointState OnsetState(const PointState &elastic, const Voigt &deps, double omega, double m) const;
  // m D_e + (1 - m) D_ep, D_ep at the onset state.
  Mat4 TransitionTangent(const PointState &elastic, const PointState &onset, double m) const;
  Mat4 TransitionTangent(size_t i) const { return TransitionTangent(state_[i], onset_[i], fraction_[i]); }
  // yield_inside, point i elastic: whether its elastic fraction min(1, r1) moved
  // by more than yield_tol from the assembled one; with `apply` it is taken
  // (and its onset state computed).
  bool ScanTransition(size_t i, const Voigt &deps, double omega, bool apply);
};

// Element dofs of cell e from a local vector.
void GatherCell(const Mesh &mesh, PetscInt e, const PetscScalar *v, fe::ElemVec &ve);

} // namespace tf
