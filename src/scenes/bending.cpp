// Pure bending of a plane-strain strip (the side of a squared tube bent and
// unbent): a strip kThickness thick, of which the half kLength long is
// modelled, the cut at x = 0 a symmetry plane (u_x = 0, its middle node
// u_y = 0), the end x = kLength kept plane and turned about its middle:
// u_x = 2 e(lambda) kLength y / kThickness, so that the outer fibre's
// nominal strain is e(lambda) (-bending_strain at lambda 1, then each
// -bending_cycle value one unit of lambda later, scenes/strain_path.hpp).
// u_y is free on both ends and the edges y = +-kThickness/2 are free: each
// fibre is in plane-strain uniaxial stress, the state of pure bending.
// History: stroke = the outer fibre's nominal strain, load = the bending
// moment on the end about its middle (N mm per mm of width). The first
// reversal is the release up to where the moment passes zero (-springback:
// elastic, or the material's law).
#include <cmath>

#include "tubeform/core/option_reader.hpp"
#include "tubeform/mesh/generator.hpp"
#include "tubeform/scenes/common.hpp"
#include "tubeform/scenes/scene_params.hpp"
#include "tubeform/scenes/strain_path.hpp"

namespace tf {

namespace {

constexpr double kThickness = 1.0; // mm: the strip's thickness
// mm: the modelled half length. A quarter of the thickness turns the end by
// half the outer strain, so that the end's rotation (second order in it) adds
// less than 1e-5 to any fibre's strain at an outer strain of 2 %.
constexpr double kLength = 0.25;

class BendingScene : public Scene {
public:
  explicit BendingScene(const Options &opt)
      : BendingScene(OwnParams<BendingParams>(opt), opt.release.springback == Springback::Elastic)
  {}
  BendingScene(const BendingParams &b, bool elastic_release)
      : strain_(b.strain, b.cycle), elastic_release_(elastic_release),
        reversal_(!b.cycle.empty() && (b.cycle[0] - b.strain) * b.strain < 0)
  {}
  std::vector<std::string> BoundarySets() const override { return {"left", "right", "bottom", "top"}; }
  std::string BuildMesh(const Options &opt, SerialMesh &mesh) const override
  {
    if (opt.mesh_nt % 2)
      return "-mesh_nt " + std::to_string(opt.mesh_nt) +
             ": the bending strip needs an even number of elements through the thickness (a node in the middle)";
    mesh = GenerateRectangle(kLength, kThickness, (int)opt.mesh_ntheta, (int)opt.mesh_nt);
    for (int n = 0; n < mesh.num_nodes(); ++n) mesh.xy[2 * n + 1] -= 0.5 * kThickness;
    return "";
  }
  std::string MeshLayout(const Options &opt) const override
  {
    return "-mesh_nt " + std::to_string(opt.mesh_nt) + " through the thickness x -mesh_ntheta " +
           std::to_string(opt.mesh_ntheta) + " along";
  }
  LoadPath Path(const Options &opt) const override { return strain_.Path(opt.driver.dynamics_time); }
  PetscErrorCode Load(Model &m, double lambda, double dlambda) override
  {
    const double de = strain_.Change(lambda, dlambda);
    for (PetscInt n : m.mesh.node_sets["left"]) {
      m.system.Prescribe(n, 0, 0.0);
      if (std::abs(m.mesh.x0[2 * n + 1]) < kOnAxis) m.system.Prescribe(n, 1, 0.0);
    }
    for (PetscInt n : m.mesh.node_sets["right"])
      m.system.Prescribe(n, 0, 2 * de * kLength * m.mesh.x0[2 * n + 1] / kThickness);
    return 0;
  }
  PetscErrorCode ExternalForce(Model &, double, Vec f) override { return VecZeroEntries(f); }
  // A second stage that turns the strip back (from lambda 1) is its release up to where the moment passes zero,
  // its springback (-springback elastic: elastic); past it the strip is bent back, by the material's law.
  PetscErrorCode BeginStage(Model &m, double lambda) override
  {
    if (lambda < 1.5 && reversal_)
      m.body.BeginRelease(elastic_release_, false), release_moment_ = moment_;
    else
      m.body.EndRelease();
    return 0;
  }
  PetscErrorCode BeginIncrement(Model &m, double) override
  {
    if (m.body.releasing() && moment_ * release_moment_ <= 0) m.body.EndRelease();
    return 0;
  }
  PetscErrorCode Persist(Model &, Archive &ar) override
  {
    PetscFunctionBeginUser;
    ar.Group("/scene");
    PetscCall(ar.Value("moment", moment_));
    PetscCall(ar.Value("release_moment", release_moment_));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  const char *StrokeName() const override { return "outer-fibre strain"; }
  const char *LoadUnit() const override { return "N mm/mm (moment)"; }
  PetscErrorCode Measure(Model &m, double lambda, Vec f_int, HistoryRow &row) override
  {
    PetscFunctionBeginUser;
    row.stroke = strain_.At(lambda);
    row.stage = StrainPath::Stage(lambda);
    // M = sum f_x (y - y_mid) on the end (current y; f_y is nil there, u_y being free).
    const auto &x = m.body.position();
    double mid_local = -INFINITY, mid;
    for (PetscInt n : m.mesh.node_sets["right"])
      if (std::abs(m.mesh.x0[2 * n + 1]) < kOnAxis) mid_local = x[2 * n + 1];
    PetscCall(MPIU_Allreduce(&mid_local, &mid, 1, MPIU_REAL, MPIU_MAX, m.comm));
    PetscCall(SetForce(
      m, "right", f_int, [&](PetscInt n, double d[2]) { d[0] = x[2 * n + 1] - mid, d[1] = 0; }, row.load));
    moment_ = row.load;
    PetscFunctionReturn(PETSC_SUCCESS);
  }

private:
  static constexpr double kOnAxis = 1e-9; // mm: a node this close to y = 0 is the middle of its end
  StrainPath strain_;
  bool elastic_release_;      // -springback elastic
  bool reversal_;             // the second stage turns the strip back (a release first)
  double moment_ = 0;         // the moment of the last row measured
  double release_moment_ = 0; // the moment where the release began
};

} // namespace

std::unique_ptr<Scene> MakeBendingScene(const Options &opt) { return std::make_unique<BendingScene>(opt); }

PetscErrorCode ReadBendingOptions(PetscOptionItems *PetscOptionsObject, OptionReader &read, BendingParams &own)
{
  PetscFunctionBeginUser;
  PetscCall(read.Real(PetscOptionsObject, "-bending_strain",
                      "bending scene: the outer fibre's nominal strain at the end of the first stage (y > 0; "
                      "negative: bent the other way)",
                      own.strain));
  PetscCall(RealList(PetscOptionsObject, read, "-bending_cycle",
                     "bending scene: outer-fibre strains the strip is then taken to in turn, each over "
                     "-unload_increments trial increments (bend and unbend: -bending_strain 0.01 -bending_cycle 0)",
                     kMaxStrainCycle, own.cycle));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode CheckBendingOptions(MPI_Comm comm, const BendingParams &own)
{
  const double e = own.strain;
  PetscFunctionBeginUser;
  PetscCheck(std::isfinite(e) && e != 0 && std::fabs(e) < 0.2, comm, PETSC_ERR_USER_INPUT,
             "-bending_strain %g: must be non-zero with |strain| < 0.2", e);
  PetscFunctionReturn(PETSC_SUCCESS);
}

} // namespace tf
