// A strip of thickness t (x) and length L (y) with a sine bow of amplitude e0,
// pinned at the centre nodes of both ends and shortened by -stroke: buckling
// at the Euler load (docs/verification.md, "Scenes against closed forms").
// History: stroke = end shortening (mm), load = axial force (N/mm).
#include <cmath>

#include "tubeform/core/option_reader.hpp"
#include "tubeform/mesh/generator.hpp"
#include "tubeform/scenes/common.hpp"
#include "tubeform/scenes/scene_params.hpp"

namespace tf {

namespace {

class ColumnScene : public Scene {
public:
  explicit ColumnScene(const Options &opt) : opt_(opt) {}
  std::vector<std::string> BoundarySets() const override { return {"left", "right", "bottom", "top"}; }
  std::string BuildMesh(const Options &opt, SerialMesh &mesh) const override
  {
    if (opt.mesh_nt % 2)
      return "-mesh_nt " + std::to_string(opt.mesh_nt) +
             ": the column needs an even number of elements through the thickness (a node on the axis)";
    const ColumnParams &c = OwnParams<ColumnParams>(opt);
    mesh = GenerateRectangle(c.t, c.l, (int)opt.mesh_nt, (int)opt.mesh_ntheta);
    for (int n = 0; n < mesh.num_nodes(); ++n) {
      const double y = mesh.xy[2 * n + 1];
      mesh.xy[2 * n] += -0.5 * c.t + c.imperfection * std::sin(M_PI * y / c.l);
    }
    return "";
  }
  std::string MeshLayout(const Options &opt) const override
  {
    return "-mesh_nt " + std::to_string(opt.mesh_nt) + " across x -mesh_ntheta " + std::to_string(opt.mesh_ntheta) +
           " along";
  }
  LoadPath Path(const Options &opt) const override { return {1.0, opt.driver.dynamics_time, {}, {}}; }
  // The axial force and the end shortening are work-conjugate.
  double LoadWorkShare(double) const override { return 1.0; }
  PetscErrorCode Load(Model &m, double, double dlambda) override
  {
    for (PetscInt n : Pins(m, "bottom")) m.system.Prescribe(n, 0, 0.0), m.system.Prescribe(n, 1, 0.0);
    for (PetscInt n : Pins(m, "top")) m.system.Prescribe(n, 0, 0.0), m.system.Prescribe(n, 1, -dlambda * opt_.stroke.u);
    return 0;
  }
  PetscErrorCode ExternalForce(Model &, double, Vec f) override { return VecZeroEntries(f); }
  const char *StrokeName() const override { return "end shortening (mm)"; }
  const char *LoadUnit() const override { return "N/mm (axial force)"; }
  PetscErrorCode Measure(Model &m, double lambda, Vec f_int, HistoryRow &row) override
  {
    PetscFunctionBeginUser;
    row.stroke = lambda * opt_.stroke.u;
    const auto pins = Pins(m, "top");
    const PetscScalar *f;
    double local = 0;
    PetscCall(VecGetArrayRead(f_int, &f));
    for (PetscInt n : pins) local += PetscRealPart(f[m.mesh.node_dof[n] + 1]);
    PetscCall(VecRestoreArrayRead(f_int, &f));
    PetscCall(MPIU_Allreduce(&local, &row.load, 1, MPIU_REAL, MPIU_SUM, m.comm));
    row.load = -row.load; // the strip pushes the pin up: compression counts positive
    PetscFunctionReturn(PETSC_SUCCESS);
  }

private:
  static constexpr double kOnAxis = 1e-9; // an end node this close to x = 0 (mm) is the pin
  Options opt_;
  // The end node on the column's axis (x0 = 0 at both ends, where the bow vanishes).
  static std::vector<PetscInt> Pins(Model &m, const std::string &end)
  {
    std::vector<PetscInt> pins;
    for (PetscInt n : m.mesh.node_sets[end])
      if (std::abs(m.mesh.x0[2 * n]) < kOnAxis) pins.push_back(n);
    return pins;
  }
};

} // namespace

std::unique_ptr<Scene> MakeColumnScene(const Options &opt) { return std::make_unique<ColumnScene>(opt); }

PetscErrorCode ReadColumnOptions(PetscOptionItems *PetscOptionsObject, OptionReader &read, ColumnParams &c)
{
  PetscFunctionBeginUser;
  PetscCall(read.Real(PetscOptionsObject, "-column_l", "column scene: length between the pins (mm)", c.l));
  PetscCall(read.Real(PetscOptionsObject, "-column_t", "column scene: thickness (mm)", c.t));
  PetscCall(read.Real(PetscOptionsObject, "-column_imperfection",
                      "column scene: amplitude of the initial sine-shaped bow (mm)", c.imperfection));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode CheckColumnOptions(MPI_Comm comm, const ColumnParams &c)
{
  PetscFunctionBeginUser;
  PetscCheck(c.l > 0 && c.t > 0 && c.t < c.l, comm, PETSC_ERR_USER_INPUT, "-column_l %g, -column_t %g: need 0 < t < L",
             c.l, c.t);
  PetscFunctionReturn(PETSC_SUCCESS);
}

} // namespace tf
