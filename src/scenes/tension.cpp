// Plane-strain uniaxial tension or compression of a block (sigma_yy = 0):
// left edge u_x = 0, bottom edge u_y = 0, right edge u_x = the nominal strain
// e(lambda): -tension_strain at lambda 1, then each -tension_cycle strain one
// unit of lambda later (piecewise linear; the stages' ends are breakpoints, so
// that an increment's motion stays linear in its length).
// History: stroke = nominal strain, load = mean sigma_xx (MPa).
#include <algorithm>

#include "tubeform/scenes/block.hpp"

namespace tf {

namespace {

class TensionScene : public BlockScene {
public:
  explicit TensionScene(const Options &opt) : BlockScene(opt)
  {
    targets_ = {0.0, opt.tension_strain};
    targets_.insert(targets_.end(), opt.tension_cycle.begin(), opt.tension_cycle.end());
  }
  LoadPath Path(const Options &opt) const override
  {
    LoadPath path{(double)targets_.size() - 1, opt.dynamics_time, {}};
    for (size_t k = 1; k + 1 < targets_.size(); ++k) path.breakpoints.push_back((double)k);
    return path;
  }
  PetscErrorCode Load(Model &m, double lambda, double dlambda) override
  {
    // (the stage of lambda's step: its end, lambda + dlambda, may be the stage's breakpoint)
    const size_t k = std::min((size_t)(lambda + 0.5 * dlambda), targets_.size() - 2);
    for (PetscInt n : m.mesh.node_sets["left"]) m.system.Prescribe(n, 0, 0.0);
    for (PetscInt n : m.mesh.node_sets["bottom"]) m.system.Prescribe(n, 1, 0.0);
    for (PetscInt n : m.mesh.node_sets["right"]) m.system.Prescribe(n, 0, dlambda * (targets_[k + 1] - targets_[k]));
    return 0;
  }
  PetscErrorCode Measure(Model &m, double lambda, Vec, HistoryRow &row) override
  {
    PetscFunctionBeginUser;
    row.stroke = Strain(lambda);
    PetscCall(PointAverage(
      m, [](const PointState &s) { return s.sigma[0]; }, row.load));
    PetscFunctionReturn(PETSC_SUCCESS);
  }

private:
  std::vector<double> targets_; // nominal strains at lambda = 0, 1, 2, ...
  double Strain(double lambda) const
  {
    const size_t k = std::min((size_t)std::max(lambda, 0.0), targets_.size() - 2);
    return targets_[k] + (lambda - (double)k) * (targets_[k + 1] - targets_[k]);
  }
};

} // namespace

std::unique_ptr<Scene> MakeTensionScene(const Options &opt) { return std::make_unique<TensionScene>(opt); }

} // namespace tf
