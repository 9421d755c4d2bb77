// Friction on an arc: a quarter ring (outer radius R = -tube_ro, wall -tube_t)
// inside a rigid cylinder of radius R (a concave arc tool). lambda in [0, 1]:
// an internal pressure pushes it onto the cylinder (inner nodes held in the
// tangential direction); lambda in [1, 2]: the inner surface is turned about
// the centre by -slide_push / R. Coulomb: the moment needed is
// mu R sum f_n = mu R p r_i pi/2 (sum f_n = p x inner arc length).
// History: stroke = turn of the inner surface (rad), load = moment (N mm/mm),
// fn_sum = sum of the normal forces.
#include <cmath>

#include "tubeform/scenes/common.hpp"
#include "tubeform/scenes/contact_params.hpp"
#include "tubeform/scenes/scene_params.hpp"

namespace tf {

namespace {

class ArcSlideScene : public Scene {
public:
  explicit ArcSlideScene(const Options &opt) : opt_(opt), own_(OwnParams<SlideParams>(opt)) {}
  std::vector<std::string> BoundarySets() const override { return {"inner", "outer", "x0", "y0"}; }
  std::string BuildMesh(const Options &opt, SerialMesh &mesh) const override { return TubeMesh(opt, mesh); }
  LoadPath Path(const Options &opt) const override { return {2.0, opt.driver.dynamics_time, {1.0}, {}}; }
  // While the inner surface is turned, the moment and the turn are work-conjugate.
  double LoadWorkShare(double lambda) const override { return lambda > 1.0 ? 1.0 : 0.0; }
  PetscErrorCode Initialize(Model &, ContactSpec &tools) override
  {
    Segment arc;
    arc.kind = Segment::Arc;
    arc.c = {0, 0};
    arc.radius = opt_.tube_ro;
    arc.t0 = -M_PI / 3; // past both symmetry planes: the ring's ends stay on the arc
    arc.t1 = M_PI / 2 + M_PI / 3;
    arc.concave = true;
    Tool cylinder;
    cylinder.name = "cylinder";
    cylinder.segments = {arc};
    tools.tools = {cylinder};
    tools.candidates = "outer";
    tools.params = MakeContactParams(opt_, kVcri);
    return 0;
  }
  PetscErrorCode BeginIncrement(Model &m, double) override
  {
    const auto &x = m.body.position();
    for (PetscInt n : m.mesh.node_sets["inner"]) m.system.SetFrame(n, std::atan2(x[2 * n + 1], x[2 * n]));
    return 0;
  }
  PetscErrorCode Load(Model &m, double lambda, double dlambda) override
  {
    PetscFunctionBeginUser;
    if (lambda < 1.0) PetscCall(AddEdgePressure(m, "inner", dlambda * own_.n, nullptr, true, lambda * own_.n));
    const double turn = lambda < 1.0 ? 0.0 : dlambda * own_.push / opt_.tube_ro;
    // A rigid turn of the inner surface: tangential (frame n; l is radial)
    // displacement = turn x current radius, so the moment and the turn are
    // work-conjugate.
    const auto &x = m.body.position();
    for (PetscInt n : m.mesh.node_sets["inner"]) m.system.Prescribe(n, 1, turn * std::hypot(x[2 * n], x[2 * n + 1]));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  PetscErrorCode ExternalForce(Model &m, double lambda, Vec f) override
  {
    PetscFunctionBeginUser;
    PetscCall(VecZeroEntries(f));
    PetscCall(AddEdgePressure(m, "inner", std::min(lambda, 1.0) * own_.n, f, false));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  const char *StrokeName() const override { return "turn (rad)"; }
  const char *LoadUnit() const override { return "N mm/mm (moment)"; }
  PetscErrorCode Measure(Model &m, double lambda, Vec f_int, HistoryRow &row) override
  {
    PetscFunctionBeginUser;
    row.stroke = lambda <= 1.0 ? 0.0 : (lambda - 1.0) * own_.push / opt_.tube_ro;
    // Moment about the centre of the internal forces at the inner nodes (their supports).
    const auto &x = m.body.position();
    PetscCall(SetForce(
      m, "inner", f_int, [&](PetscInt n, double d[2]) { d[0] = -x[2 * n + 1], d[1] = x[2 * n]; }, row.load));
    row.stage = StageOf(lambda);
    PetscFunctionReturn(PETSC_SUCCESS);
  }

private:
  static constexpr double kVcri = 1e-3; // default quasi-stick slip (mm)
  Options opt_;
  SlideParams own_; // (-slide_*)
};

} // namespace

std::unique_ptr<Scene> MakeArcSlideScene(const Options &opt) { return std::make_unique<ArcSlideScene>(opt); }

} // namespace tf
