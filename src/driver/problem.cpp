#include "tubeform/driver/problem.hpp"

#include <algorithm>
#include <cmath>

#include "tubeform/core.hpp"
#include "tubeform/driver/log.hpp"
#include "tubeform/io/output.hpp"
#include "tubeform/material/j2.hpp"

namespace tf {

// Events of a re-solved (friction) step found this far beyond its end are taken with it.
constexpr double kEventSlack = 1e-2;
// Solves of a shortened non-linear step before it is taken with an event inside.
constexpr int kMaxResolves = 3;
// -dynamics implicit: no step shorter than this fraction of the trial step.
// Events closer than that (a node whose normal force is all but zero, a point
// a hair from the yield surface) are taken with it; shorter steps would make
// M / dt^2 swamp K (precision) for no gain in resolution.
constexpr double kMinDynamicStep = 1e-6;

Problem::~Problem() = default;

PetscErrorCode Problem::Setup(MPI_Comm comm, const Options &opt)
{
  PetscFunctionBeginUser;
  auto scene = CreateScene(opt);
  PetscCheck(scene, comm, PETSC_ERR_USER_INPUT, "-scene %s: not available yet (available: pressure, shear, rotation, column, tension)", opt.scene_name.c_str());
  PetscCall(Setup(comm, opt, std::move(scene)));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Problem::CreateMaterial()
{
  const MaterialParams &m = opt_.material;
  std::unique_ptr<Hardening> h;

  PetscFunctionBeginUser;
  if (m.law == "elastic") {
    material_ = std::make_unique<Elastic>(m.E, m.nu);
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  if (m.law == "ludwik") h = std::make_unique<LudwikHardening>(m.sy, m.K, m.n);
  else if (m.law == "swift") h = std::make_unique<SwiftHardening>(m.sy, m.K, m.n);
  else {
    std::vector<double> ep, sy;
    for (size_t i = 0; i + 1 < opt_.material_table.size(); i += 2) ep.push_back(opt_.material_table[i]), sy.push_back(opt_.material_table[i + 1]);
    h = std::make_unique<TableHardening>(ep, sy);
  }
  // Before a point has yielded, H' is the secant over one strain-limit step.
  material_ = std::make_unique<J2Plasticity>(m.E, m.nu, std::move(h), opt_.rmin_deps, opt_.drift_correction);
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Problem::Setup(MPI_Comm comm, const Options &opt, std::unique_ptr<Scene> scene)
{
  SerialMesh serial;
  char why[PETSC_MAX_PATH_LEN] = "";

  PetscFunctionBeginUser;
  comm_ = comm;
  opt_ = opt;
  scene_ = std::move(scene);
  PetscCallMPI(MPI_Comm_rank(comm, &rank_));
  PetscCallMPI(MPI_Comm_size(comm, &size_));
  PetscCall(Log::Register());
  PetscCall(PetscLogStagePush(Log::setup_stage));
  PetscCall(CreateMaterial());

  // 1. The serial mesh on rank 0; its verdict is shared so all ranks stop together.
  PetscCall(PetscLogEventBegin(Log::mesh, 0, 0, 0, 0));
  if (rank_ == 0) {
    std::string err = scene_->BuildMesh(opt, serial);
    if (err.empty()) err = serial.validate(scene_->BoundarySets());
    if (!err.empty() && !opt.mesh_file.empty() && err.find(opt.mesh_file) == std::string::npos) err = "-mesh_file " + opt.mesh_file + ": " + err;
    PetscCall(PetscStrncpy(why, err.c_str(), sizeof(why)));
  }
  PetscCallMPI(MPI_Bcast(why, sizeof(why), MPI_CHAR, 0, comm));
  PetscCheck(why[0] == 0, comm, PETSC_ERR_USER_INPUT, "%s", why);
  int ncells = serial.num_cells();
  PetscCallMPI(MPI_Bcast(&ncells, 1, MPI_INT, 0, comm));
  PetscCheck(ncells >= size_, comm, PETSC_ERR_USER_INPUT, "the mesh has %d cells, fewer than the %d MPI ranks: refine it or run on fewer ranks", ncells, (int)size_);

  // 2. Partition, distribute, build the element tables and the global system.
  PetscCall(mesh_.Create(comm, serial, scene_->BoundarySets()));
  PetscCall(PetscLogEventEnd(Log::mesh, 0, 0, 0, 0));
  PetscCall(system_.Setup(mesh_));
  state_.assign(fe::kGauss * mesh_.num_cells, PointState{});
  yield_factor_.assign(state_.size(), 1e300);
  if (opt_.element == fe::Formulation::QM6) condensation_.assign(mesh_.num_cells, fe::Condensation{});
  x_ = mesh_.x0;
  u_.assign(2 * mesh_.num_nodes, 0.0);
  inertia_ = opt_.dynamics == Dynamics::Implicit;
  if (opt_.dynamics != Dynamics::Quasistatic) {
    mass_.assign(fe::kNodes * mesh_.num_cells, 0.0);
    v_.assign(2 * mesh_.num_nodes, 0.0);
    a_.assign(2 * mesh_.num_nodes, 0.0);
    double xe[8];
    for (PetscInt e = 0; e < mesh_.num_cells; ++e) {
      CellCoordinates(e, xe);
      fe::LumpedMass(xe, opt_.material.density, &mass_[fe::kNodes * e]);
    }
  }
  PetscCall(PetscLogStagePop());
  PetscFunctionReturn(PETSC_SUCCESS);
}

void Problem::CellCoordinates(PetscInt cell, double xe[8]) const
{
  for (int a = 0; a < 4; ++a) {
    const PetscInt n = mesh_.cell_nodes[4 * cell + a];
    xe[2 * a] = x_[2 * n];
    xe[2 * a + 1] = x_[2 * n + 1];
  }
}

bool Problem::CellStiffness(PetscInt e, const double xe[8], const Mat4 c[4], const Voigt s[4], fe::ElemMat &ke)
{
  if (opt_.element == fe::Formulation::QM6) return fe::QM6Stiffness(xe, c, s, true, ke, condensation_[e]);
  fe::QuadGeometry geo;
  if (!fe::ComputeGeometry(xe, geo)) return false;
  fe::ElementStiffness(geo, opt_.element, c, s, true, ke);
  return true;
}

bool Problem::CellKinematics(PetscInt e, const double xe[8], const fe::QuadGeometry &geo, int g, const fe::ElemVec &du, Voigt &deps, double &omega) const
{
  if (opt_.element != fe::Formulation::QM6) {
    fe::IncrementKinematics(geo, g, opt_.element, du, deps, omega);
    return true;
  }
  // Internal modes of the increment from the condensation of its assembly.
  fe::InternalVec alpha{};
  for (int k = 0; k < fe::kInternal; ++k)
    for (int j = 0; j < fe::kDofs; ++j) alpha[k] += condensation_[e][k][j] * du[j];
  return fe::QM6Kinematics(xe, g, du, alpha, deps, omega);
}

bool Problem::CellInternalForce(PetscInt e, const double xe[8], const fe::QuadGeometry &geo, const Voigt s[4], fe::ElemVec &f) const
{
  if (opt_.element == fe::Formulation::QM6) return fe::QM6InternalForce(xe, s, condensation_[e], f);
  fe::InternalForce(geo, opt_.element, s, f);
  return true;
}

// Element dofs of cell e from a local vector.
static void GatherCell(const Mesh &mesh, PetscInt e, const PetscScalar *v, fe::ElemVec &ve)
{
  for (int a = 0; a < 4; ++a) {
    const PetscInt n = mesh.cell_nodes[4 * e + a];
    ve[2 * a] = PetscRealPart(v[mesh.node_dof[n]]);
    ve[2 * a + 1] = PetscRealPart(v[mesh.node_dof[n] + 1]);
  }
}

PetscErrorCode Problem::AssembleTangent()
{
  fe::ElemMat ke;
  Mat4 c[fe::kGauss];
  Voigt s[fe::kGauss];
  double xe[8];
  PetscInt bad = -1, anybad;

  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(Log::assemble, 0, 0, 0, 0));
  PetscCall(system_.Begin());
  for (PetscInt e = 0; e < mesh_.num_cells; ++e) {
    CellCoordinates(e, xe);
    for (int g = 0; g < fe::kGauss; ++g) {
      c[g] = material_->Tangent(state_[fe::kGauss * e + g]);
      s[g] = state_[fe::kGauss * e + g].sigma;
    }
    if (!CellStiffness(e, xe, c, s, ke)) {
      bad = mesh_.cell_orig[e];
      continue;
    }
    if (dt_ > 0)
      for (int a = 0; a < fe::kNodes; ++a) {
        const double m = mass_[fe::kNodes * e + a] / (dt_ * dt_);
        ke[2 * a][2 * a] += m;
        ke[2 * a + 1][2 * a + 1] += m;
      }
    PetscCall(system_.AddElement(e, ke));
  }
  PetscCall(MPIU_Allreduce(&bad, &anybad, 1, MPIU_INT, MPI_MAX, comm_));
  PetscCheck(anybad < 0, comm_, PETSC_ERR_USER_INPUT, "element %d is inverted (det J <= 0): the increment is too large (lower -rmin_deps) or the mesh is tangled", (int)anybad);
  PetscCall(PetscLogEventEnd(Log::assemble, 0, 0, 0, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Problem::ScanTrial(Vec du_local, bool apply, StepLimit &limit, PetscInt &switches)
{
  const PetscScalar *du;
  fe::QuadGeometry geo;
  double xe[8];
  PetscInt local_switches = 0;
  StepLimit yield, strain, rotation;

  PetscFunctionBeginUser;
  PetscCall(VecGetArrayRead(du_local, &du));
  for (PetscInt e = 0; e < mesh_.num_cells; ++e) {
    fe::ElemVec due;
    CellCoordinates(e, xe);
    if (!fe::ComputeGeometry(xe, geo)) continue;
    GatherCell(mesh_, e, du, due);
    for (int g = 0; g < fe::kGauss; ++g) {
      Voigt deps;
      double omega;
      PointState &ps = state_[fe::kGauss * e + g];
      // The trial increment is linear in r on the start configuration.
      CellKinematics(e, xe, geo, g, due, deps, omega);
      if (material_->plastic_law() && material_->Loading(ps, deps) != ps.plastic) {
        ++local_switches;
        if (apply) ps.plastic = !ps.plastic;
      }
      double &r1 = yield_factor_[fe::kGauss * e + g];
      r1 = material_->YieldOnset(ps, deps, omega);
      yield.Offer(r1, Limiter::Yield, mesh_.cell_orig[e]);
      strain.Offer(StrainFactor(deps, opt_.rmin_deps), Limiter::Strain, mesh_.cell_orig[e]);
      rotation.Offer(RotationFactor(omega, opt_.rmin_domega), Limiter::Rotation, mesh_.cell_orig[e]);
    }
  }
  PetscCall(VecRestoreArrayRead(du_local, &du));
  PetscCall(MPIU_Allreduce(&local_switches, &switches, 1, MPIU_INT, MPI_SUM, comm_));
  for (StepLimit *l : {&yield, &strain, &rotation}) {
    PetscCall(ReduceStepLimit(comm_, *l));
    limit.Offer(l->r, l->who, l->where);
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Problem::Commit(Vec du_local, double r, CommitInfo &info)
{
  const PetscScalar *du;
  fe::QuadGeometry geo;
  double xe[8], local[3] = {0, 0, 0}, global[3];
  PetscInt nplastic = 0;
  const bool midpoint = opt_.kinematics == ObjectiveScheme::Midpoint;

  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(Log::update, 0, 0, 0, 0));
  PetscCall(VecGetArrayRead(du_local, &du));
  for (PetscInt e = 0; e < mesh_.num_cells; ++e) {
    fe::ElemVec due;
    GatherCell(mesh_, e, du, due);
    CellCoordinates(e, xe);
    // Gradients on the mid-increment configuration (Hughes-Winget: a rigid
    // rotation then gives zero strain and an exact rotation of the stress),
    // or on the start configuration (the paper's forward form).
    if (midpoint)
      for (int k = 0; k < 8; ++k) xe[k] += 0.5 * due[k];
    if (!fe::ComputeGeometry(xe, geo)) continue; // reported by the next assembly
    for (int g = 0; g < fe::kGauss; ++g) {
      Voigt deps;
      double omega;
      PointState &ps = state_[fe::kGauss * e + g];
      CellKinematics(e, xe, geo, g, due, deps, omega);
      const Voigt old = ps.sigma;
      // Strang splitting: half the rotation, the constitutive increment in the
      // mid-rotated frame, the other half (forward scheme: all at once, first order).
      const double first = midpoint ? 0.5 : 1.0;
      RotateStress(opt_.kinematics, omega, ps.sigma, first);
      const UpdateInfo u = material_->Update(ps, deps);
      if (midpoint) RotateStress(opt_.kinematics, omega, ps.sigma, 0.5);
      // Points that reach the yield surface in this increment (the limiter and
      // those grouped with it), or pass it, are plastic from now on.
      if (!ps.plastic && material_->plastic_law() &&
          (yield_factor_[fe::kGauss * e + g] <= r * (1 + opt_.rmin_group_tol) || VonMises(ps.sigma) >= (1 - kOnSurface) * material_->YieldStress(ps.ep)))
        ps.plastic = true;
      nplastic += ps.plastic;
      for (int c = 0; c < 4; ++c) local[0] += geo.wdet[g] * 0.5 * (old[c] + ps.sigma[c]) * deps[c];
      local[1] += geo.wdet[g] * u.dwp;
      local[2] = std::max(local[2], std::abs(u.drift));
    }
  }
  for (PetscInt n = 0; n < mesh_.num_nodes; ++n)
    for (int k = 0; k < 2; ++k) {
      const double d = PetscRealPart(du[mesh_.node_dof[n] + k]);
      x_[2 * n + k] += d;
      u_[2 * n + k] += d;
    }
  PetscCall(VecRestoreArrayRead(du_local, &du));
  PetscCall(MPIU_Allreduce(local, global, 2, MPIU_REAL, MPIU_SUM, comm_));
  PetscCall(MPIU_Allreduce(&local[2], &global[2], 1, MPIU_REAL, MPIU_MAX, comm_));
  PetscCall(MPIU_Allreduce(&nplastic, &info.n_plastic, 1, MPIU_INT, MPI_SUM, comm_));
  info.dw_int = global[0];
  info.dw_plastic = global[1];
  info.drift = global[2];
  PetscCall(PetscLogEventEnd(Log::update, 0, 0, 0, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

void Problem::SetElasticOnly()
{
  material_ = std::make_unique<Elastic>(opt_.material.E, opt_.material.nu);
  for (auto &ps : state_) ps.plastic = false;
}

PetscErrorCode Problem::SolveTrial(double lambda, double dl, Vec du, StepLimit &limit, PetscInt &redo, PetscInt &iterations, bool last)
{
  PetscInt switches = 0;
  std::vector<double> reactions;

  PetscFunctionBeginUser;
  redo = 0;
  // One loop re-solves until nothing changes: friction forces linearized
  // about the last iterate, and points whose loading state (alpha) disagreed
  // with the last solution switched (at most -rmin_max_redo times).
  const auto solve = [&]() -> PetscErrorCode {
    PetscFunctionBeginUser;
    dt_ = inertia_ ? dl * duration_ : 0.0;
    release_fraction_ = inertia_ ? std::max(1e-9, MinStepFraction(dl)) : 1e-9;
    PetscCall(AssembleTangent());
    PetscCall(VecZeroEntries(f_inc_));
    PetscCall(scene_->Load(*this, lambda, dl, f_inc_));
    if (dt_ > 0) PetscCall(AddInertiaLoad());
    if (opt_.residual_correction) PetscCall(system_.AddFreeForce(f_res_));
    PetscCall(system_.Solve(du, reactions));
    ++iterations;
    PetscFunctionReturn(PETSC_SUCCESS);
  };
  scene_->ResetIterates();
  for (PetscInt it = 0;; ++it) {
    PetscCall(solve());
    bool converged = true;
    if (scene_->Iterative()) PetscCall(scene_->UpdateIterates(*this, du, converged));
    limit = StepLimit{};
    const bool may_switch = redo < opt_.rmin_max_redo;
    PetscCall(ScanTrial(du, may_switch, limit, switches));
    // The scene's switches (contact nodes pulled off without force) always
    // apply: they are finite by construction (a node is released at most once
    // per trial and a grazing one then stays), and a node left in contact in
    // tension would carry a wrong force; Gauss-point switches have a budget.
    PetscInt scene_switches = 0;
    PetscCall(scene_->Switches(*this, du, true, scene_switches));
    const bool material = switches > 0 && may_switch;
    if (material) ++redo;
    if (converged && !material && scene_switches == 0) break;
    if (it >= opt_.friction_max_iters + opt_.rmin_max_redo) {
      if (!last) {
        converged_ = false; // the caller shortens the step
        PetscFunctionReturn(PETSC_SUCCESS);
      }
      if (opt_.dynamics == Dynamics::Auto && !inertia_) {
        // Quasi-static steps cannot settle here: inertia from now on, and
        // this (shortest) step solved again with it.
        inertia_ = true;
        PetscCall(PetscPrintf(comm_, "tubeform: friction iterations do not settle at lambda %.6g: inertia on from here (-dynamics auto, docs/theory.md \"Inertia\")\n", lambda));
        scene_->ResetIterates();
        redo = 0;
        it = -1;
        continue;
      }
      // The shortest step still wanders (friction iterates drifting along a
      // nearly free slip mode, or a loading switch cycle): it is solved once
      // more the paper's way, the friction linearized about the start of the
      // increment with the trial's active sets, and that solution is taken
      // (r4-r6 and r1 still limit it). Counted in the history (`unsettled`);
      // the energy balance shows what it cost.
      ++unsettled_;
      scene_->LinearizeAtStart();
      PetscCall(solve());
      limit = StepLimit{};
      PetscCall(ScanTrial(du, false, limit, switches));
      break;
    }
  }
  converged_ = true;
  PetscCall(scene_->LimitStep(*this, du, limit));
  PetscFunctionReturn(PETSC_SUCCESS);
}

// Calls f(node, m) for every node of every local cell with the cell's lumped
// mass share: contributions that sum to M over the ranks (cells are owned once).
template <class F>
void Problem::ForEachMassShare(F &&f) const
{
  for (PetscInt e = 0; e < mesh_.num_cells; ++e)
    for (int a = 0; a < fe::kNodes; ++a) f(mesh_.cell_nodes[fe::kNodes * e + a], mass_[fe::kNodes * e + a]);
}

double Problem::MinStepFraction(double dl) const { return kMinDynamicStep / (opt_.increments * dl); }

PetscErrorCode Problem::AddInertiaLoad()
{
  PetscFunctionBeginUser;
  ForEachMassShare([&](PetscInt n, double m) { system_.AddForce(n, m * (a_[2 * n] + v_[2 * n] / dt_), m * (a_[2 * n + 1] + v_[2 * n + 1] / dt_)); });
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Problem::AdvanceInertia(Vec du_local, double &dw_inertia)
{
  const PetscScalar *du;
  double local = 0;

  PetscFunctionBeginUser;
  dw_inertia = 0;
  PetscCall(VecGetArrayRead(du_local, &du));
  if (!inertia_) {
    // -dynamics auto before the switch: the velocity of the quasi-static path
    // (the motion inertia starts from), no acceleration.
    for (PetscInt n = 0; n < mesh_.num_nodes; ++n)
      for (int k = 0; k < 2; ++k) v_[2 * n + k] = PetscRealPart(du[mesh_.node_dof[n] + k]) / dt_;
    PetscCall(VecRestoreArrayRead(du_local, &du));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  // The work with the old and new accelerations first, then the update.
  const auto a_new = [&](PetscInt n, int k) { return (PetscRealPart(du[mesh_.node_dof[n] + k]) / dt_ - v_[2 * n + k]) / dt_; };
  ForEachMassShare([&](PetscInt n, double m) {
    for (int k = 0; k < 2; ++k) local += m * 0.5 * (a_[2 * n + k] + a_new(n, k)) * PetscRealPart(du[mesh_.node_dof[n] + k]);
  });
  for (PetscInt n = 0; n < mesh_.num_nodes; ++n)
    for (int k = 0; k < 2; ++k) {
      a_[2 * n + k] = a_new(n, k);
      v_[2 * n + k] = PetscRealPart(du[mesh_.node_dof[n] + k]) / dt_;
    }
  PetscCall(VecRestoreArrayRead(du_local, &du));
  PetscCall(MPIU_Allreduce(&local, &dw_inertia, 1, MPIU_REAL, MPIU_SUM, comm_));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Problem::AddInertiaForce(Vec f_local)
{
  PetscScalar *f;

  PetscFunctionBeginUser;
  PetscCall(VecGetArray(f_local, &f));
  ForEachMassShare([&](PetscInt n, double m) {
    for (int k = 0; k < 2; ++k) f[mesh_.node_dof[n] + k] += m * a_[2 * n + k];
  });
  PetscCall(VecRestoreArray(f_local, &f));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Problem::KineticEnergy(double &w)
{
  double local = 0;

  PetscFunctionBeginUser;
  ForEachMassShare([&](PetscInt n, double m) { local += 0.5 * m * (v_[2 * n] * v_[2 * n] + v_[2 * n + 1] * v_[2 * n + 1]); });
  PetscCall(MPIU_Allreduce(&local, &w, 1, MPIU_REAL, MPIU_SUM, comm_));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Problem::InternalForce(Vec f_local)
{
  PetscScalar *f;
  fe::QuadGeometry geo;
  double xe[8];

  PetscFunctionBeginUser;
  PetscCall(VecZeroEntries(f_local));
  PetscCall(VecGetArray(f_local, &f));
  for (PetscInt e = 0; e < mesh_.num_cells; ++e) {
    Voigt s[fe::kGauss];
    fe::ElemVec fe_;
    CellCoordinates(e, xe);
    if (!fe::ComputeGeometry(xe, geo)) continue;
    for (int g = 0; g < fe::kGauss; ++g) s[g] = state_[fe::kGauss * e + g].sigma;
    CellInternalForce(e, xe, geo, s, fe_);
    for (int a = 0; a < 4; ++a) {
      const PetscInt n = mesh_.cell_nodes[4 * e + a];
      f[mesh_.node_dof[n]] += fe_[2 * a];
      f[mesh_.node_dof[n] + 1] += fe_[2 * a + 1];
    }
  }
  PetscCall(VecRestoreArray(f_local, &f));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Problem::ElasticEnergy(double &w)
{
  fe::QuadGeometry geo;
  double xe[8], local = 0;

  PetscFunctionBeginUser;
  for (PetscInt e = 0; e < mesh_.num_cells; ++e) {
    CellCoordinates(e, xe);
    if (!fe::ComputeGeometry(xe, geo)) continue;
    for (int g = 0; g < fe::kGauss; ++g) local += geo.wdet[g] * material_->ElasticEnergy(state_[fe::kGauss * e + g].sigma);
  }
  PetscCall(MPIU_Allreduce(&local, &w, 1, MPIU_REAL, MPIU_SUM, comm_));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Problem::WriteOutputs(ResultWriter &writer, PetscInt step, double t)
{
  std::vector<CellField> cells = {{"sigma_xx", {}}, {"sigma_yy", {}}, {"sigma_zz", {}}, {"sigma_xy", {}}, {"von_mises", {}}, {"eps_p", {}}, {"plastic", {}}};
  PetscFunctionBeginUser;
  for (auto &c : cells) c.values.assign(mesh_.num_cells, 0.0);
  // Cell values are Gauss-point averages.
  for (PetscInt e = 0; e < mesh_.num_cells; ++e)
    for (int g = 0; g < fe::kGauss; ++g) {
      const PointState &ps = state_[fe::kGauss * e + g];
      const Voigt &s = ps.sigma;
      const double vals[7] = {s[0], s[1], s[2], s[3], VonMises(s), ps.ep, ps.plastic ? 1.0 : 0.0};
      for (int k = 0; k < 7; ++k) cells[k].values[e] += 0.25 * vals[k];
    }
  PetscCall(writer.WriteStep(step, t, u_, cells));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Problem::Run()
{
  ResultWriter writer;
  Vec du, f_ext, f_int, f_ext0, f_int0;
  HistoryRow row;
  double lambda = 0, w_ext = 0, w_int = 0, w_plastic = 0, w_friction = 0, w_inertia = 0;
  bool warned = false;
  PetscInt step = 0, inc = 0;

  PetscFunctionBeginUser;
  // Outputs are checked before any work so a bad path fails at once.
  if (!opt_.history_csv.empty()) PetscCall(CheckWritable(comm_, opt_.history_csv, "-history_csv"));
  PetscCall(writer.Open(mesh_, opt_.output));
  {
    const std::string err = history_.OpenCsv(opt_.history_csv, rank_);
    int ok = err.empty();
    PetscCallMPI(MPI_Bcast(&ok, 1, MPI_INT, 0, comm_));
    PetscCheck(ok, comm_, PETSC_ERR_USER_INPUT, "-history_csv %s: cannot create the file (does the directory exist and is it writable?)", opt_.history_csv.c_str());
  }
  du = system_.CreateLocalVector();
  PetscCall(VecDuplicate(du, &f_inc_));
  PetscCall(VecDuplicate(du, &f_res_));
  PetscCall(VecDuplicate(du, &f_ext));
  PetscCall(VecDuplicate(du, &f_int));
  PetscCall(VecDuplicate(du, &f_ext0));
  PetscCall(VecDuplicate(du, &f_int0));
  PetscCall(VecZeroEntries(f_res_));

  // Increment 0: the initial state.
  PetscCall(scene_->Initialize(*this));
  PetscCall(InternalForce(f_int));
  PetscCall(scene_->ExternalForce(*this, 0.0, f_ext));
  PetscCall(scene_->Measure(*this, 0.0, f_int, row));
  history_.Append(row);
  PetscCall(WriteOutputs(writer, step++, 0.0));

  const double end = scene_->PathEnd(), eps = 1e-12;
  duration_ = scene_->Duration(opt_);
  std::vector<double> breaks = scene_->Breakpoints();
  breaks.push_back(end);
  std::vector<char> started(breaks.size(), 0);
  const double dlambda_trial = 1.0 / opt_.increments;
  PetscCall(PetscLogStagePush(Log::load_stage));
  // Stall watch: a window of -rmin_stall_increments increments that together
  // advance lambda by less than kStall ends the loading (results so far kept).
  const double kStall = 1e-6;
  double lambda_mark = 0;
  PetscInt inc_mark = 0;
  bool stalled = false;
  while (lambda < end - eps) {
    if (inc - inc_mark >= opt_.rmin_stall_increments) {
      if (lambda - lambda_mark < kStall) {
        stalled = true;
        break;
      }
      lambda_mark = lambda, inc_mark = inc;
    }
    PetscCheck(++inc <= opt_.rmin_max_increments, comm_, PETSC_ERR_NOT_CONVERGED, "no convergence of the load path: %d increments reached lambda = %g; raise -rmin_max_increments or relax -rmin_deps / -rmin_domega", (int)opt_.rmin_max_increments, lambda);
    for (size_t b = 0; b + 1 < breaks.size(); ++b)
      if (!started[b] && lambda >= breaks[b] - eps) {
        started[b] = 1;
        PetscCall(scene_->BeginStage(*this, lambda));
      }
    const double next_break = *std::find_if(breaks.begin(), breaks.end(), [&](double b) { return b > lambda + eps; });
    double dl = std::min(dlambda_trial, next_break - lambda);

    // 1. Trial solution and its r_min (paper eq. 16).
    StepLimit limit;
    PetscInt redo = 0, iterations = 0;
    PetscCall(scene_->BeginIncrement(*this, lambda));
    // A step whose iterations do not settle is halved (up to kMaxCuts times;
    // the last one is taken as it is).
    for (int cut = 0;; ++cut) {
      PetscCall(SolveTrial(lambda, dl, du, limit, redo, iterations, cut == kMaxCuts));
      if (converged_) break;
      dl *= 0.5;
    }
    Limiter who = lambda + dl >= end - eps ? Limiter::Final : Limiter::Trial;
    PetscInt where = -1;
    double r = 1.0, react_scale = 1.0, r_event = 1.0;
    if (limit.r < 1.0) r = limit.r, who = limit.who, where = limit.where;
    if (inertia_) r = std::min(1.0, std::max(r, MinStepFraction(dl)));
    PetscCheck(r > 1e-10, comm_, PETSC_ERR_NOT_CONVERGED, "r_min = %g (%s at %d) at lambda = %g: the increment cannot advance", r, LimiterName((int)limit.who), (int)limit.where, lambda);
    if (r < 1.0 && (scene_->Iterative() || inertia_)) {
      // Friction is not linear in r, nor is inertia (M / dt^2): the shortened
      // step is solved again (and again while the re-solve still finds an
      // event well inside it: the non-linearity moves events). The last
      // solution is taken as it is: scaling it would break the friction
      // forces' equilibrium; events slightly past its end are taken with it.
      double taken = r;
      for (int attempt = 0;; ++attempt) {
        dl *= taken;
        PetscInt redo2 = 0;
        PetscCall(SolveTrial(lambda, dl, du, limit, redo2, iterations, false));
        redo += redo2;
        for (int cut = 1; !converged_; ++cut) {
          dl *= 0.5;
          r *= 0.5;
          PetscCall(SolveTrial(lambda, dl, du, limit, redo2, iterations, cut == kMaxCuts));
        }
        if (limit.r >= 1.0 - kEventSlack || attempt == kMaxResolves - 1) break;
        taken = limit.r;
        if (inertia_) taken = std::max(taken, MinStepFraction(dl));
        if (taken >= 1.0) break;
        r *= taken;
      }
      r_event = std::max(1.0 + kEventSlack, std::min(limit.r, 1.0));
    } else {
      PetscCall(VecScale(du, r));
      react_scale = r_event = r;
      dl *= r;
    }

    // 2. Commit: stresses, plastic state, geometry, then the scene's state (contact).
    CommitInfo ci;
    double dw_friction = 0;
    PetscCall(VecCopy(f_ext, f_ext0));
    PetscCall(VecCopy(f_int, f_int0));
    PetscCall(Commit(du, r_event, ci));
    double dw_inertia = 0;
    if (opt_.dynamics != Dynamics::Quasistatic) {
      dt_ = dl * duration_;
      PetscCall(AdvanceInertia(du, dw_inertia));
    }
    PetscCall(scene_->CommitIncrement(*this, du, react_scale, r_event, dw_friction));
    lambda = std::abs(lambda + dl - next_break) < 1e-9 * dlambda_trial ? next_break : lambda + dl;

    // 3. Forces on the new configuration: out-of-balance force, and the
    //    external work by the trapezoidal rule (loads on free dofs, reactions
    //    on supported ones). The tools' work is the body's external work plus
    //    what friction dissipated.
    double residual, fnorm, dw_body;
    PetscCall(scene_->ExternalForce(*this, lambda, f_ext));
    PetscCall(InternalForce(f_int));
    if (inertia_) PetscCall(AddInertiaForce(f_int)); // f_int + M a: what the loads and reactions balance
    PetscCall(VecAXPBY(f_ext0, 0.5, 0.5, f_ext));
    PetscCall(VecAXPBY(f_int0, 0.5, 0.5, f_int));
    PetscCall(system_.ExternalWork(f_ext0, f_int0, du, dw_body));
    w_ext += dw_body + dw_friction;
    w_friction += dw_friction;
    w_int += ci.dw_int;
    w_plastic += ci.dw_plastic;
    w_inertia += dw_inertia;
    PetscCall(VecWAXPY(f_res_, -1.0, f_int, f_ext));
    PetscCall(system_.FreeNorm(f_res_, residual));
    {
      // Scale of the forces: the internal force over all dofs.
      PetscReal nrm;
      Vec g;
      PetscCall(DMGetGlobalVector(mesh_.dm, &g));
      PetscCall(VecZeroEntries(g));
      PetscCall(DMLocalToGlobal(mesh_.dm, f_int, ADD_VALUES, g));
      PetscCall(VecNorm(g, NORM_2, &nrm));
      PetscCall(DMRestoreGlobalVector(mesh_.dm, &g));
      fnorm = nrm;
    }

    row = HistoryRow{};
    row.increment = inc;
    row.rmin = r;
    row.limiter = static_cast<double>(who);
    row.limiter_where = where;
    row.n_plastic = ci.n_plastic;
    row.friction_iters = iterations;
    row.residual = residual;
    row.redo = redo;
    row.drift = ci.drift;
    row.unsettled = unsettled_;
    row.w_ext = w_ext;
    row.w_int = w_int;
    row.w_plastic = w_plastic;
    row.w_friction = w_friction;
    row.w_inertia = w_inertia;
    row.inertia = inertia_ ? 1 : 0;
    PetscCall(ElasticEnergy(row.w_elastic));
    if (inertia_) PetscCall(KineticEnergy(row.w_kinetic));
    row.energy_error = (w_ext - w_int - w_friction - w_inertia) / std::max(std::abs(w_ext), 1e-300);
    PetscCall(scene_->Measure(*this, lambda, f_int, row));
    history_.Append(row);
    if (!warned && std::abs(row.energy_error) > 0.05 && inc > 10) {
      warned = true;
      PetscCall(PetscPrintf(comm_, "tubeform: warning: energy balance error %.1f %% at increment %d (lambda %.4f): the solution is drifting from equilibrium; try smaller -rmin_deps / -increments, or see docs/theory.md\n", 100 * row.energy_error, (int)inc, lambda));
    }
    if (opt_.monitor)
      PetscCall(PetscPrintf(comm_, "inc %5d  lambda %.5f  stroke %-11.5g load %-11.5g r_min %.3g (%s%s)  plastic %d  contact %d  iters %d  residual %.2e (rel %.1e)  energy err %.1e\n", (int)inc, lambda, row.stroke, row.load, r, LimiterName((int)who),
                            where >= 0 ? (" @" + std::to_string(where)).c_str() : "", (int)ci.n_plastic, (int)row.n_contact, (int)iterations, residual, residual / std::max(fnorm, 1e-300), row.energy_error));
    if (inc % opt_.output_every == 0 || lambda >= end - eps) PetscCall(WriteOutputs(writer, step++, lambda));
  }
  if (stalled && inc % opt_.output_every != 0) PetscCall(WriteOutputs(writer, step++, lambda));
  PetscCall(PetscLogStagePop());

  PetscCall(PetscLogStagePush(Log::output_stage));
  const HistoryRow &last = history_.rows().back();
  std::vector<std::pair<std::string, double>> metrics = {{"final_stroke", last.stroke}, {"final_load", last.load}, {"x_max", last.x_max}, {"y_max", last.y_max}, {"stalled", stalled ? 1.0 : 0.0}};
  for (const auto &m : scene_->FinalMetrics(history_)) metrics.push_back(m);
  PetscCall(writer.Close(history_, metrics));
  PetscCheck(history_.FinishCsv(), comm_, PETSC_ERR_FILE_WRITE, "-history_csv %s: cannot rename the finished file into place", opt_.history_csv.c_str());
  PetscCall(PetscLogStagePop());
  if (!stalled) PetscCall(PetscPrintf(comm_, "tubeform: %s done, %d increments, %d factorizations; results in %s\n", opt_.scene_name.c_str(), (int)inc, (int)system_.factorizations(), opt_.output.c_str()));
  PetscCall(VecDestroy(&du));
  PetscCall(VecDestroy(&f_inc_));
  PetscCall(VecDestroy(&f_res_));
  PetscCall(VecDestroy(&f_ext));
  PetscCall(VecDestroy(&f_int));
  PetscCall(VecDestroy(&f_ext0));
  PetscCall(VecDestroy(&f_int0));
  // A stall is a failure of the run, reported after its results are written.
  PetscCheck(!stalled, comm_, PETSC_ERR_NOT_CONVERGED, "the load path stalled at stroke %g (lambda %.6g): %d increments (-rmin_stall_increments) advanced lambda by less than %g; the history column limiter names what cut them (docs/theory.md, \"Stalls\"); results up to there are in %s", history_.rows().back().stroke, lambda, (int)opt_.rmin_stall_increments, kStall, opt_.output.c_str());
  PetscFunctionReturn(PETSC_SUCCESS);
}

} // namespace tf
