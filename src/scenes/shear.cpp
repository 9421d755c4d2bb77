// Simple shear x = X + gamma Y to -shear_gamma (docs/verification.md, "Scenes against closed forms").
// History: stroke = gamma, load = mean sigma_xy (MPa). Hypoelastic Jaumann
// reference: sigma_xy = G sin(gamma), sigma_xx = -sigma_yy = G (1 - cos(gamma)).
#include "tubeform/core/option_reader.hpp"
#include "tubeform/scenes/block.hpp"
#include "tubeform/scenes/scene_params.hpp"

namespace tf {

namespace {

class ShearScene : public BlockScene {
public:
  explicit ShearScene(const Options &opt) : BlockScene(opt), own_(OwnParams<ShearParams>(opt)) {}
  PetscErrorCode Load(Model &m, double, double dlambda) override
  {
    const double dgamma = dlambda * own_.gamma;
    PrescribeBoundary(m, [&](PetscInt n, double d[2]) { d[0] = dgamma * m.body.position()[2 * n + 1], d[1] = 0; });
    return 0;
  }
  const char *StrokeName() const override { return "gamma"; }
  const char *LoadUnit() const override { return "MPa (mean sigma_xy)"; }
  PetscErrorCode Measure(Model &m, double lambda, Vec, HistoryRow &row) override
  {
    PetscFunctionBeginUser;
    row.stroke = lambda * own_.gamma;
    PetscCall(PointAverage(
      m, [](const PointState &s) { return s.sigma[3]; }, row.load));
    PetscFunctionReturn(PETSC_SUCCESS);
  }

private:
  ShearParams own_; // (-shear_*)
};

} // namespace

std::unique_ptr<Scene> MakeShearScene(const Options &opt) { return std::make_unique<ShearScene>(opt); }

PetscErrorCode ReadShearOptions(PetscOptionItems *PetscOptionsObject, OptionReader &read, ShearParams &own)
{
  PetscFunctionBeginUser;
  PetscCall(read.Real(PetscOptionsObject, "-shear_gamma", "shear scene: final shear strain gamma", own.gamma));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode CheckShearOptions(MPI_Comm comm, const ShearParams &own)
{
  const double gamma = own.gamma;
  PetscFunctionBeginUser;
  PetscCheck(std::isfinite(gamma) && gamma != 0, comm, PETSC_ERR_USER_INPUT,
             "-shear_gamma %g: must be a finite non-zero shear strain", gamma);
  PetscFunctionReturn(PETSC_SUCCESS);
}

} // namespace tf
