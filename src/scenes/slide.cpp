// A block on a rigid floor (friction check; docs/verification.md, "Contact and friction"): lambda in
// [0, 1] presses its top edge down with a total force -slide_n (top held in
// x); lambda in [1, 2] pushes the top edge sideways by -slide_push; with
// -slide_back, lambda in [2, 3] pushes it back by that much (the slip
// reverses: r6, slide to stick).
// History: stroke = top displacement (mm), load = tangential force T (N/mm);
// slip = mean slip of the bottom on the floor, tool_fx / tool_fy = the
// block's force on the floor.
#include "tubeform/core/option_reader.hpp"
#include "tubeform/mesh/generator.hpp"
#include "tubeform/scenes/common.hpp"
#include "tubeform/scenes/contact_params.hpp"
#include "tubeform/scenes/die_columns.hpp"
#include "tubeform/scenes/scene_params.hpp"
#include "tubeform/tool/shape.hpp"

namespace tf {

namespace {

class SlideScene : public Scene {
public:
  explicit SlideScene(const Options &opt) : opt_(opt), own_(OwnParams<SlideParams>(opt)) {}
  std::vector<std::string> BoundarySets() const override { return {"left", "right", "bottom", "top"}; }
  std::string BuildMesh(const Options &opt, SerialMesh &mesh) const override
  {
    mesh = GenerateRectangle(kWidth, kHeight, (int)opt.mesh_ntheta, (int)opt.mesh_nt);
    return "";
  }
  std::string MeshLayout(const Options &opt) const override
  {
    return "-mesh_ntheta " + std::to_string(opt.mesh_ntheta) + " along x -mesh_nt " + std::to_string(opt.mesh_nt) +
           " through the block";
  }
  LoadPath Path(const Options &opt) const override
  {
    if (OwnParams<SlideParams>(opt).back > 0) return {3.0, opt.driver.dynamics_time, {1.0, 2.0}, {}};
    return {2.0, opt.driver.dynamics_time, {1.0}, {}};
  }
  // While the top is pushed, T and its displacement are work-conjugate.
  double LoadWorkShare(double lambda) const override { return lambda > 1.0 ? 1.0 : 0.0; }
  PetscErrorCode Initialize(Model &, ContactSpec &tools) override
  {
    tools.tools = {BuildFlatPlate(0.0, -kFloorHalfLength, kFloorHalfLength, true)};
    tools.candidates = "bottom";
    tools.params = MakeContactParams(opt_, kVcri);
    return 0;
  }
  PetscErrorCode Load(Model &m, double lambda, double dlambda) override
  {
    PetscFunctionBeginUser;
    const double dn = lambda < 1.0 ? dlambda * own_.n : 0.0;
    const double push = lambda < 1.0 ? 0.0 : lambda < 2.0 ? dlambda * own_.push : -dlambda * own_.back;
    PetscCall(TopLoad(m, -dn, nullptr, true));
    for (PetscInt n : m.mesh.node_sets["top"]) m.system.Prescribe(n, 0, push);
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  PetscErrorCode ExternalForce(Model &m, double lambda, Vec f) override
  {
    PetscFunctionBeginUser;
    PetscCall(VecZeroEntries(f));
    PetscCall(TopLoad(m, -std::min(lambda, 1.0) * own_.n, f, false));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  const char *StrokeName() const override { return "push (mm)"; }
  const char *LoadUnit() const override { return "N/mm (tangential force)"; }
  PetscErrorCode Measure(Model &m, double lambda, Vec f_int, HistoryRow &row) override
  {
    PetscFunctionBeginUser;
    row.stroke = Top(lambda);
    PetscCall(SetForce(
      m, "top", f_int, [](PetscInt, double d[2]) { d[0] = 1, d[1] = 0; }, row.load));
    double local[2] = {0, 0}, g[2];
    for (PetscInt k : m.mesh.node_sets["bottom"])
      if (m.mesh.node_owned[k]) local[0] += m.body.displacement()[2 * k], local[1] += 1;
    PetscCallMPI(MPI_Allreduce(local, g, 2, MPI_DOUBLE, MPI_SUM, m.comm));
    row.slip = g[0] / g[1];
    double force[2], moment;
    PetscCall(m.contact->TotalForce(0, force, &moment));
    const ToolColumns &floor = UpperDieColumns(); // (the scene's tool's columns, the press's upper die's)
    floor(row, kDieFx) = -force[0], floor(row, kDieFy) = -force[1], floor(row, kDieMoment) = -moment;
    row.stage = lambda > 2.0 + kLambdaTol ? 2 : StageOf(lambda); // 2: pushed back
    PetscFunctionReturn(PETSC_SUCCESS);
  }

private:
  // Sideways displacement of the top at lambda.
  double Top(double lambda) const
  {
    if (lambda <= 1.0) return 0.0;
    if (lambda <= 2.0) return (lambda - 1.0) * own_.push;
    return own_.push - (lambda - 2.0) * own_.back;
  }
  static constexpr double kWidth = 10.0, kHeight = 2.0; // block (mm)
  static constexpr double kFloorHalfLength = 1e3;       // the floor reaches far past the block (mm)
  static constexpr double kVcri = 1e-3;                 // default quasi-stick slip (mm)
  static constexpr double kOnEnd = 1e-9;                // a top node this close to an end (of the width) is an end node
  Options opt_;
  SlideParams own_; // (-slide_*)
  // A uniform vertical traction on the top edge with resultant fy (end nodes
  // half weight), into f (if given) and the system (with to_system).
  PetscErrorCode TopLoad(Model &m, double fy, Vec f, bool to_system)
  {
    PetscScalar *a = nullptr;
    PetscFunctionBeginUser;
    const double per = fy / opt_.mesh_ntheta, tol = kOnEnd * kWidth;
    if (f) PetscCall(VecGetArray(f, &a));
    for (PetscInt n : m.mesh.node_sets["top"]) {
      if (!m.mesh.node_owned[n]) continue;
      const double x = m.mesh.x0[2 * n], w = (x < tol || x > kWidth - tol) ? 0.5 : 1.0;
      if (a) a[m.mesh.node_dof[n] + 1] += w * per;
      if (to_system) m.system.AddForce(n, 0.0, w * per);
    }
    if (f) PetscCall(VecRestoreArray(f, &a));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
};

} // namespace

std::unique_ptr<Scene> MakeSlideScene(const Options &opt) { return std::make_unique<SlideScene>(opt); }

PetscErrorCode ReadSlideOptions(PetscOptionItems *PetscOptionsObject, OptionReader &read, SlideParams &s)
{
  PetscFunctionBeginUser;
  PetscCall(read.Real(PetscOptionsObject, "-slide_n", "slide scene: normal force pressing the block (N/mm)", s.n));
  PetscCall(ChooseWord(PetscOptionsObject, read, "-slide_tool",
                       "slide scene: a block on a flat floor, or a quarter ring turned inside a cylinder (arc)",
                       kSlideToolWords, s.tool));
  PetscCall(
    read.Real(PetscOptionsObject, "-slide_push", "slide scene: sideways displacement of the block's top (mm)", s.push));
  PetscCall(read.Real(PetscOptionsObject, "-slide_back",
                      "slide scene (flat): then push the top back by this much (mm; 0: no third stage), "
                      "reversing the slip",
                      s.back));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode CheckSlideOptions(MPI_Comm comm, const SlideParams &s)
{
  PetscFunctionBeginUser;
  PetscCheck(s.n > 0 && s.push > 0, comm, PETSC_ERR_USER_INPUT, "-slide_n %g, -slide_push %g: must be positive", s.n,
             s.push);
  PetscCheck(s.back >= 0 && std::isfinite(s.back), comm, PETSC_ERR_USER_INPUT,
             "-slide_back %g: must be a non-negative distance (mm)", s.back);
  PetscCheck(s.back == 0 || s.tool == SlideTool::Flat, comm, PETSC_ERR_USER_INPUT,
             "-slide_back %g: only the flat slide (-slide_tool flat) has a push-back stage", s.back);
  PetscFunctionReturn(PETSC_SUCCESS);
}

} // namespace tf
