#include "tubeform/driver/problem.hpp"

#include <cmath>

#include "tubeform/core.hpp"
#include "tubeform/driver/log.hpp"
#include "tubeform/io/output.hpp"

namespace tf {

Problem::~Problem() = default;

PetscErrorCode Problem::Setup(MPI_Comm comm, const Options &opt)
{
  SerialMesh serial;
  char why[PETSC_MAX_PATH_LEN] = "";

  PetscFunctionBeginUser;
  comm_ = comm;
  opt_ = opt;
  PetscCallMPI(MPI_Comm_rank(comm, &rank_));
  PetscCallMPI(MPI_Comm_size(comm, &size_));
  PetscCall(Log::Register());
  PetscCall(PetscLogStagePush(Log::setup_stage));
  scene_ = CreateScene(opt);
  PetscCheck(scene_, comm, PETSC_ERR_USER_INPUT, "-scene %s: not available yet (available: pressure)", opt.scene_name.c_str());

  PetscCheck(opt.material.law == "elastic", comm, PETSC_ERR_USER_INPUT, "-material_law %s: plasticity is not implemented yet; use -material_law elastic", opt.material.law.c_str());
  material_ = std::make_unique<Elastic>(opt.material.E, opt.material.nu);

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
  x_ = mesh_.x0;
  u_.assign(2 * mesh_.num_nodes, 0.0);
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

PetscErrorCode Problem::AssembleTangent()
{
  fe::QuadGeometry geo;
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
    if (!fe::ComputeGeometry(xe, geo)) {
      bad = mesh_.cell_orig[e];
      continue;
    }
    for (int g = 0; g < fe::kGauss; ++g) {
      c[g] = material_->Tangent(state_[fe::kGauss * e + g]);
      s[g] = state_[fe::kGauss * e + g].sigma;
    }
    fe::ElementStiffness(geo, opt_.element, c, s, true, ke);
    PetscCall(system_.AddElement(e, ke));
  }
  PetscCall(MPIU_Allreduce(&bad, &anybad, 1, MPIU_INT, MPI_MAX, comm_));
  PetscCheck(anybad < 0, comm_, PETSC_ERR_USER_INPUT, "element %d is inverted (det J <= 0): the increment is too large or the mesh is tangled", (int)anybad);
  PetscCall(PetscLogEventEnd(Log::assemble, 0, 0, 0, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Problem::Commit(Vec du_local, double &dw_int)
{
  const PetscScalar *du;
  fe::QuadGeometry geo;
  double xe[8], local_w = 0;

  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(Log::update, 0, 0, 0, 0));
  PetscCall(VecGetArrayRead(du_local, &du));
  // Stresses first: gradients are taken on the configuration at the start
  // of the increment (updated Lagrangian reference).
  for (PetscInt e = 0; e < mesh_.num_cells; ++e) {
    fe::ElemVec due;
    CellCoordinates(e, xe);
    if (!fe::ComputeGeometry(xe, geo)) continue; // caught at assembly
    for (int a = 0; a < 4; ++a) {
      const PetscInt n = mesh_.cell_nodes[4 * e + a];
      due[2 * a] = PetscRealPart(du[mesh_.node_dof[n]]);
      due[2 * a + 1] = PetscRealPart(du[mesh_.node_dof[n] + 1]);
    }
    for (int g = 0; g < fe::kGauss; ++g) {
      Voigt deps;
      double omega;
      PointState &ps = state_[fe::kGauss * e + g];
      fe::IncrementKinematics(geo, g, opt_.element, due, deps, omega);
      const Voigt old = ps.sigma;
      material_->Update(ps, deps, omega);
      // Trapezoidal stress work of the increment.
      for (int r = 0; r < 4; ++r) local_w += geo.wdet[g] * 0.5 * (old[r] + ps.sigma[r]) * deps[r];
    }
  }
  for (PetscInt n = 0; n < mesh_.num_nodes; ++n)
    for (int k = 0; k < 2; ++k) {
      const double d = PetscRealPart(du[mesh_.node_dof[n] + k]);
      x_[2 * n + k] += d;
      u_[2 * n + k] += d;
    }
  PetscCall(VecRestoreArrayRead(du_local, &du));
  PetscCall(MPIU_Allreduce(&local_w, &dw_int, 1, MPIU_REAL, MPIU_SUM, comm_));
  PetscCall(PetscLogEventEnd(Log::update, 0, 0, 0, 0));
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
    fe::InternalForce(geo, opt_.element, s, fe_);
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
  std::vector<CellField> cells = {{"sigma_xx", {}}, {"sigma_yy", {}}, {"sigma_zz", {}}, {"sigma_xy", {}}, {"von_mises", {}}, {"eps_p", {}}};
  PetscFunctionBeginUser;
  for (auto &c : cells) c.values.assign(mesh_.num_cells, 0.0);
  // Cell values are Gauss-point averages.
  for (PetscInt e = 0; e < mesh_.num_cells; ++e)
    for (int g = 0; g < fe::kGauss; ++g) {
      const PointState &ps = state_[fe::kGauss * e + g];
      const Voigt &s = ps.sigma;
      const double p = (s[0] + s[1] + s[2]) / 3;
      const double vm = std::sqrt(1.5 * ((s[0] - p) * (s[0] - p) + (s[1] - p) * (s[1] - p) + (s[2] - p) * (s[2] - p) + 2 * s[3] * s[3]));
      const double vals[6] = {s[0], s[1], s[2], s[3], vm, ps.ep};
      for (int k = 0; k < 6; ++k) cells[k].values[e] += 0.25 * vals[k];
    }
  PetscCall(writer.WriteStep(step, t, u_, cells));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode Problem::Run()
{
  ResultWriter writer;
  Vec du, f_inc, f_ext, f_int;
  std::vector<double> reactions;
  HistoryRow row;
  double lambda = 0, w_ext = 0, w_int = 0;
  PetscInt step = 0;

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
  PetscCall(VecDuplicate(du, &f_inc));
  PetscCall(VecDuplicate(du, &f_ext));
  PetscCall(VecDuplicate(du, &f_int));

  // Increment 0: the initial state.
  PetscCall(scene_->Measure(*this, 0.0, row));
  history_.Append(row);
  PetscCall(WriteOutputs(writer, step++, 0.0));

  PetscCall(PetscLogStagePush(Log::load_stage));
  const double dlambda = 1.0 / opt_.increments;
  for (PetscInt inc = 1; inc <= opt_.increments; ++inc) {
    double dw_int, dw_ext_local, dw_ext, residual, fnorm;
    const PetscScalar *fa, *da;

    // Trial increment: tangent, loads, supports, solve. (The r_min scaling of
    // METHOD.md sec. 4 enters here; the elastic scenes take r = 1.)
    PetscCall(AssembleTangent());
    PetscCall(VecZeroEntries(f_inc));
    PetscCall(scene_->Load(*this, lambda, dlambda, f_inc));
    PetscCall(system_.Solve(du, reactions));

    // External work: load at the start plus half the increment, times du
    // (trapezoid; exact while the increment is linear).
    PetscCall(scene_->ExternalForce(*this, lambda, f_ext));
    PetscCall(VecAXPY(f_ext, 0.5, f_inc));
    PetscCall(VecGetArrayRead(f_ext, &fa));
    PetscCall(VecGetArrayRead(du, &da));
    dw_ext_local = 0;
    for (PetscInt k = 0; k < 2 * mesh_.num_nodes; ++k) dw_ext_local += PetscRealPart(fa[k] * da[k]);
    PetscCall(VecRestoreArrayRead(du, &da));
    PetscCall(VecRestoreArrayRead(f_ext, &fa));
    PetscCall(MPIU_Allreduce(&dw_ext_local, &dw_ext, 1, MPIU_REAL, MPIU_SUM, comm_));

    PetscCall(Commit(du, dw_int));
    lambda = inc == opt_.increments ? 1.0 : lambda + dlambda;
    w_ext += dw_ext;
    w_int += dw_int;

    // Out-of-balance force on the new configuration.
    PetscCall(scene_->ExternalForce(*this, lambda, f_ext));
    PetscCall(InternalForce(f_int));
    PetscCall(VecAXPY(f_int, -1.0, f_ext));
    PetscCall(system_.FreeNorm(f_int, residual));
    PetscCall(system_.FreeNorm(f_ext, fnorm));

    row = HistoryRow{};
    row.increment = inc;
    row.rmin = 1.0;
    row.limiter = static_cast<double>(inc == opt_.increments ? Limiter::Final : Limiter::Trial);
    row.residual = residual;
    row.w_ext = w_ext;
    row.w_int = w_int;
    PetscCall(ElasticEnergy(row.w_elastic));
    row.energy_error = (w_ext - w_int) / std::max(std::abs(w_ext), 1e-300);
    PetscCall(scene_->Measure(*this, lambda, row));
    history_.Append(row);
    if (opt_.monitor)
      PetscCall(PetscPrintf(comm_, "inc %4d  stroke %-12.6g load %-12.6g r_min %.3g (%s)  residual %.3e (rel %.1e)  energy err %.1e\n", (int)inc, row.stroke, row.load, row.rmin, LimiterName((int)row.limiter), residual, residual / std::max(fnorm, 1e-300), row.energy_error));
    if (inc % opt_.output_every == 0 || inc == opt_.increments) PetscCall(WriteOutputs(writer, step++, lambda));
  }
  PetscCall(PetscLogStagePop());

  PetscCall(PetscLogStagePush(Log::output_stage));
  const HistoryRow &last = history_.rows().back();
  PetscCall(writer.Close(history_, {{"final_stroke", last.stroke}, {"final_load", last.load}, {"x_max", last.x_max}, {"y_max", last.y_max}}));
  PetscCheck(history_.FinishCsv(), comm_, PETSC_ERR_FILE_WRITE, "-history_csv %s: cannot rename the finished file into place", opt_.history_csv.c_str());
  PetscCall(PetscLogStagePop());
  PetscCall(PetscPrintf(comm_, "tubeform: %s done, %d increments, %d factorizations; results in %s\n", opt_.scene_name.c_str(), (int)opt_.increments, (int)system_.factorizations(), opt_.output.c_str()));
  PetscCall(VecDestroy(&du));
  PetscCall(VecDestroy(&f_inc));
  PetscCall(VecDestroy(&f_ext));
  PetscCall(VecDestroy(&f_int));
  PetscFunctionReturn(PETSC_SUCCESS);
}

} // namespace tf
