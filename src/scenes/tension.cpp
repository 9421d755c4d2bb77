// Plane-strain uniaxial tension or compression of a block (sigma_yy = 0):
// left edge u_x = 0, bottom edge u_y = 0, right edge u_x = the nominal strain
// e(lambda): -tension_strain at lambda 1, then each -tension_cycle strain one
// unit of lambda later (piecewise linear, scenes/strain_path.hpp).
// History: stroke = nominal strain, load = mean sigma_xx (MPa).
#include "tubeform/scenes/block.hpp"
#include "tubeform/scenes/strain_path.hpp"

namespace tf {

namespace {

class TensionScene : public BlockScene {
public:
  explicit TensionScene(const Options &opt) : BlockScene(opt), strain_(opt.tension_strain, opt.tension_cycle) {}
  LoadPath Path(const Options &opt) const override { return strain_.Path(opt.dynamics_time); }
  PetscErrorCode Load(Model &m, double lambda, double dlambda) override
  {
    for (PetscInt n : m.mesh.node_sets["left"]) m.system.Prescribe(n, 0, 0.0);
    for (PetscInt n : m.mesh.node_sets["bottom"]) m.system.Prescribe(n, 1, 0.0);
    for (PetscInt n : m.mesh.node_sets["right"]) m.system.Prescribe(n, 0, strain_.Change(lambda, dlambda));
    return 0;
  }
  const char *StrokeName() const override { return "nominal strain"; }
  const char *LoadUnit() const override { return "MPa (mean sigma_xx)"; }
  PetscErrorCode Measure(Model &m, double lambda, Vec, HistoryRow &row) override
  {
    PetscFunctionBeginUser;
    row.stroke = strain_.At(lambda);
    row.stage = StrainPath::Stage(lambda);
    PetscCall(PointAverage(
      m, [](const PointState &s) { return s.sigma[0]; }, row.load));
    PetscFunctionReturn(PETSC_SUCCESS);
  }

private:
  StrainPath strain_;
};

} // namespace

std::unique_ptr<Scene> MakeTensionScene(const Options &opt) { return std::make_unique<TensionScene>(opt); }

} // namespace tf
