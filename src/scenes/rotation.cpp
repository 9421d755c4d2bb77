// A block stretched in x (uniaxial strain -rotation_strain, lambda in [0, 0.1])
// then turned rigidly about the origin by -rotation_angle (lambda in [0.1, 1]):
// objectivity (docs/verification.md, "Scenes against closed forms").
// History: stroke = rotation angle so far (degrees), load = mean von Mises stress.
#include <cmath>

#include "tubeform/core/option_reader.hpp"
#include "tubeform/scenes/block.hpp"
#include "tubeform/scenes/scene_params.hpp"

namespace tf {

namespace {

class RotationScene : public BlockScene {
public:
  explicit RotationScene(const Options &opt) : BlockScene(opt), own_(OwnParams<RotationParams>(opt)) {}
  LoadPath Path(const Options &opt) const override { return {1.0, opt.driver.dynamics_time, {kStretch}, {}}; }
  PetscErrorCode Load(Model &m, double lambda, double dlambda) override
  {
    if (lambda < kStretch - kLambdaTol) {
      const double de = dlambda / kStretch * own_.strain;
      PrescribeBoundary(m, [&](PetscInt n, double d[2]) { d[0] = de * m.mesh.x0[2 * n], d[1] = 0; });
    } else {
      const double dth = dlambda / (1 - kStretch) * own_.angle * M_PI / 180;
      const double c = std::cos(dth), s = std::sin(dth);
      PrescribeBoundary(m, [&](PetscInt n, double d[2]) {
        const double x = m.body.position()[2 * n], y = m.body.position()[2 * n + 1];
        d[0] = (c - 1) * x - s * y, d[1] = s * x + (c - 1) * y;
      });
    }
    return 0;
  }
  const char *StrokeName() const override { return "angle (deg)"; }
  const char *LoadUnit() const override { return "MPa (mean von Mises)"; }
  PetscErrorCode Measure(Model &m, double lambda, Vec, HistoryRow &row) override
  {
    PetscFunctionBeginUser;
    row.stroke = lambda <= kStretch ? 0.0 : (lambda - kStretch) / (1 - kStretch) * own_.angle;
    PetscCall(PointAverage(
      m, [](const PointState &s) { return VonMises(s.sigma); }, row.load));
    PetscFunctionReturn(PETSC_SUCCESS);
  }

private:
  static constexpr double kStretch = 0.1; // the share of the load path that stretches the block
  RotationParams own_;                    // (-rotation_*)
};

} // namespace

std::unique_ptr<Scene> MakeRotationScene(const Options &opt) { return std::make_unique<RotationScene>(opt); }

PetscErrorCode ReadRotationOptions(PetscOptionItems *PetscOptionsObject, OptionReader &read, RotationParams &own)
{
  PetscFunctionBeginUser;
  PetscCall(read.Real(PetscOptionsObject, "-rotation_angle",
                      "rotation scene: rigid rotation after the prestretch (degrees)", own.angle));
  PetscCall(read.Real(PetscOptionsObject, "-rotation_strain",
                      "rotation scene: uniaxial prestretch strain in x before the rotation", own.strain));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode CheckRotationOptions(MPI_Comm comm, const RotationParams &own)
{
  PetscFunctionBeginUser;
  PetscCheck(std::fabs(own.angle) <= 3600, comm, PETSC_ERR_USER_INPUT,
             "-rotation_angle %g: must lie within +-3600 degrees", own.angle);
  PetscFunctionReturn(PETSC_SUCCESS);
}

} // namespace tf
