// Plane-strain uniaxial tension or compression of a block (sigma_yy = 0):
// left edge u_x = 0, bottom edge u_y = 0, right edge u_x = the nominal strain
// e(lambda): -tension_strain at lambda 1, then each -tension_cycle strain one
// unit of lambda later (piecewise linear, scenes/strain_path.hpp).
// History: stroke = nominal strain, load = mean sigma_xx (MPa).
#include "tubeform/core/option_reader.hpp"
#include "tubeform/scenes/block.hpp"
#include "tubeform/scenes/scene_params.hpp"
#include "tubeform/scenes/strain_path.hpp"

namespace tf {

namespace {

class TensionScene : public BlockScene {
public:
  explicit TensionScene(const Options &opt)
      : BlockScene(opt), strain_(OwnParams<TensionParams>(opt).strain, OwnParams<TensionParams>(opt).cycle)
  {}
  LoadPath Path(const Options &opt) const override { return strain_.Path(opt.driver.dynamics_time); }
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

PetscErrorCode ReadTensionOptions(PetscOptionItems *PetscOptionsObject, OptionReader &read, TensionParams &own)
{
  PetscFunctionBeginUser;
  PetscCall(read.Real(PetscOptionsObject, "-tension_strain",
                      "tension scene: final nominal strain in x (negative: compression)", own.strain));
  PetscCall(RealList(PetscOptionsObject, read, "-tension_cycle",
                     "tension scene: nominal strains the block is then taken to in turn, each over "
                     "-unload_increments trial increments (a tension-compression cycle: -tension_strain 0.02 "
                     "-tension_cycle -0.02,0.02)",
                     kMaxStrainCycle, own.cycle));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode CheckTensionOptions(MPI_Comm comm, const TensionParams &own)
{
  const double e = own.strain;
  PetscFunctionBeginUser;
  PetscCheck(std::isfinite(e) && e != 0 && std::fabs(e) < 1, comm, PETSC_ERR_USER_INPUT,
             "-tension_strain %g: must be non-zero with |strain| < 1", e);
  PetscFunctionReturn(PETSC_SUCCESS);
}

} // namespace tf
