// Plane-strain uniaxial tension or compression of a block (sigma_yy = 0):
// left edge u_x = 0, bottom edge u_y = 0, right edge u_x = lambda * -tension_strain.
// History: stroke = nominal strain, load = mean sigma_xx (MPa).
#include "tubeform/scenes/block.hpp"

namespace tf {

namespace {

class TensionScene : public BlockScene {
public:
  using BlockScene::BlockScene;
  PetscErrorCode Load(Model &m, double, double dlambda) override
  {
    for (PetscInt n : m.mesh.node_sets["left"]) m.system.Prescribe(n, 0, 0.0);
    for (PetscInt n : m.mesh.node_sets["bottom"]) m.system.Prescribe(n, 1, 0.0);
    for (PetscInt n : m.mesh.node_sets["right"]) m.system.Prescribe(n, 0, dlambda * opt_.tension_strain);
    return 0;
  }
  PetscErrorCode Measure(Model &m, double lambda, Vec, HistoryRow &row) override
  {
    PetscFunctionBeginUser;
    row.stroke = lambda * opt_.tension_strain;
    PetscCall(PointAverage(
      m, [](const PointState &s) { return s.sigma[0]; }, row.load));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
};

} // namespace

std::unique_ptr<Scene> MakeTensionScene(const Options &opt) { return std::make_unique<TensionScene>(opt); }

} // namespace tf
