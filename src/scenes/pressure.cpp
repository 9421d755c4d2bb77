// Thick cylinder under internal pressure (quarter, plane strain): Lame's and
// Hill's solutions (docs/verification.md, "Scenes against closed forms").
// -pressure_control load: the pressure is ramped to -pressure_p; history
//   stroke = mean radial displacement of the inner surface (mm), load = pressure (MPa).
// -pressure_control displacement: the inner radial displacement is ramped to
//   -pressure_u (inner nodes carry radial frames); stroke = that displacement,
//   load = the pressure it takes: radial reaction / current inner arc length.
#include <cmath>

#include "tubeform/core/option_reader.hpp"
#include "tubeform/scenes/common.hpp"
#include "tubeform/scenes/scene_params.hpp"

namespace tf {

namespace {

class PressureScene : public Scene {
public:
  explicit PressureScene(const Options &opt)
      : opt_(opt), own_(OwnParams<PressureParams>(opt)), displacement_(own_.control == PressureControl::Displacement)
  {}
  std::vector<std::string> BoundarySets() const override { return {"inner", "outer", "x0", "y0"}; }
  std::string BuildMesh(const Options &opt, SerialMesh &mesh) const override { return TubeMesh(opt, mesh); }
  LoadPath Path(const Options &opt) const override { return {1.0, opt.driver.dynamics_time, {}, {}}; }

  PetscErrorCode BeginIncrement(Model &m, double) override
  {
    // Radial frames on the inner surface (axisymmetry keeps nodes on their rays).
    if (displacement_)
      for (PetscInt n : m.mesh.node_sets["inner"])
        m.system.SetFrame(n, std::atan2(m.mesh.x0[2 * n + 1], m.mesh.x0[2 * n]));
    return 0;
  }

  PetscErrorCode Load(Model &m, double lambda, double dlambda) override
  {
    PetscFunctionBeginUser;
    if (displacement_)
      for (PetscInt n : m.mesh.node_sets["inner"]) m.system.Prescribe(n, 0, dlambda * own_.u);
    else
      PetscCall(AddEdgePressure(m, "inner", dlambda * own_.p, nullptr, true, lambda * own_.p));
    PetscCall(QuarterSymmetry(m));
    PetscFunctionReturn(PETSC_SUCCESS);
  }

  PetscErrorCode ExternalForce(Model &m, double lambda, Vec f) override
  {
    PetscFunctionBeginUser;
    PetscCall(VecZeroEntries(f));
    if (!displacement_) PetscCall(AddEdgePressure(m, "inner", lambda * own_.p, f, false));
    PetscFunctionReturn(PETSC_SUCCESS);
  }

  const char *StrokeName() const override { return "inner radial displacement (mm)"; }
  const char *LoadUnit() const override { return "MPa"; }
  PetscErrorCode Measure(Model &m, double lambda, Vec f_int, HistoryRow &row) override
  {
    double sum[3] = {0, 0, 0}, g[3];
    PetscFunctionBeginUser;
    const Mesh &mesh = m.mesh;
    const auto &x = m.body.position();
    const auto &u = m.body.displacement();
    for (PetscInt n : m.mesh.node_sets["inner"]) {
      if (!mesh.node_owned[n]) continue;
      const double r = std::hypot(mesh.x0[2 * n], mesh.x0[2 * n + 1]);
      sum[0] += (u[2 * n] * mesh.x0[2 * n] + u[2 * n + 1] * mesh.x0[2 * n + 1]) / r;
      sum[1] += 1;
    }
    for (const auto &e : m.mesh.edge_sets["inner"])
      sum[2] += std::hypot(x[2 * e.node[1]] - x[2 * e.node[0]], x[2 * e.node[1] + 1] - x[2 * e.node[0] + 1]);
    PetscCall(MPIU_Allreduce(sum, g, 3, MPIU_REAL, MPIU_SUM, m.comm));
    row.stroke = g[0] / g[1];
    if (displacement_) {
      double fr;
      const auto radial = [&](PetscInt n, double d[2]) {
        const double r = std::hypot(mesh.x0[2 * n], mesh.x0[2 * n + 1]);
        d[0] = mesh.x0[2 * n] / r, d[1] = mesh.x0[2 * n + 1] / r; // internal force = the pressure the support applies
      };
      PetscCall(SetForce(m, "inner", f_int, radial, fr));
      row.load = fr / g[2];
    } else
      row.load = lambda * own_.p;
    PetscCall(OuterExtents(m, row));
    PetscFunctionReturn(PETSC_SUCCESS);
  }

private:
  Options opt_;
  PressureParams own_; // (-pressure_*)
  bool displacement_;
};

} // namespace

std::unique_ptr<Scene> MakePressureScene(const Options &opt) { return std::make_unique<PressureScene>(opt); }

PetscErrorCode ReadPressureOptions(PetscOptionItems *PetscOptionsObject, OptionReader &read, PressureParams &p)
{
  PetscFunctionBeginUser;
  PetscCall(read.Real(PetscOptionsObject, "-pressure_p",
                      "pressure scene: final internal pressure (MPa), -pressure_control load", p.p));
  PetscCall(ChooseWord(PetscOptionsObject, read, "-pressure_control",
                       "pressure scene: ramp the pressure (load) or the inner radial displacement (displacement)",
                       kPressureControlWords, p.control));
  PetscCall(read.Real(PetscOptionsObject, "-pressure_u",
                      "pressure scene: final inner radial displacement (mm), -pressure_control displacement", p.u));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode CheckPressureOptions(MPI_Comm comm, const PressureParams &p)
{
  PetscFunctionBeginUser;
  PetscCheck(p.u > 0, comm, PETSC_ERR_USER_INPUT, "-pressure_u %g: must be positive (mm)", p.u);
  PetscCheck(std::isfinite(p.p), comm, PETSC_ERR_USER_INPUT, "-pressure_p %g: must be a finite pressure (MPa)", p.p);
  PetscFunctionReturn(PETSC_SUCCESS);
}

} // namespace tf
