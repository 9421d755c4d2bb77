// The tool scenes of METHOD.md section 1: `squaring` (quarter tube, upper
// V-die) and `flattening` (quarter ring, flat plate), with unloading.
//
// Load path: lambda in [0, 1] presses the tool to the final stroke; with
// -unload reverse or withdraw, lambda in [1, 2] unloads:
//   reverse  (the paper): every point elastic, the contact forces at the end
//            of loading applied reversed as nodal loads, tools removed;
//   withdraw: the tool moves back and releases the nodes one by one (r5).
// History: stroke = tool stroke U (mm), load = punch load on the full tube,
// 2 x the quarter's vertical tool force (N/mm).
#include <algorithm>
#include <cmath>

#include "tubeform/contact/contact.hpp"
#include "tubeform/core.hpp"
#include "tubeform/driver/problem.hpp"
#include "tubeform/driver/scene_util.hpp"
#include "tubeform/mesh/generator.hpp"

namespace tf {

namespace {

// Outer-surface nodes of the whole mesh (every rank gets all of them).
struct OuterNode {
  double x, y;
  int contact, segment;
};

PetscErrorCode GatherOuter(Problem &p, const ContactSet &c, std::vector<OuterNode> &all)
{
  std::vector<double> mine;
  PetscMPIInt size;
  PetscFunctionBeginUser;
  for (PetscInt n : p.mesh().node_sets["outer"])
    if (p.mesh().node_owned[n]) mine.insert(mine.end(), {p.position()[2 * n], p.position()[2 * n + 1], double(c.InContact(n)), double(c.Segment(n))});
  PetscCallMPI(MPI_Comm_size(p.comm(), &size));
  std::vector<int> counts(size), displs(size);
  int count = (int)mine.size();
  PetscCallMPI(MPI_Allgather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, p.comm()));
  int total = 0;
  for (int r = 0; r < size; ++r) displs[r] = total, total += counts[r];
  std::vector<double> buf(total);
  PetscCallMPI(MPI_Allgatherv(mine.data(), count, MPI_DOUBLE, buf.data(), counts.data(), displs.data(), MPI_DOUBLE, p.comm()));
  all.clear();
  for (int k = 0; k + 3 < total; k += 4) all.push_back({buf[k], buf[k + 1], (int)buf[k + 2], (int)buf[k + 3]});
  // Along the surface, from the x axis to the y axis.
  std::sort(all.begin(), all.end(), [](const OuterNode &a, const OuterNode &b) { return std::atan2(a.y, a.x) < std::atan2(b.y, b.x); });
  PetscFunctionReturn(PETSC_SUCCESS);
}

// Contact parameters from the options; default_vcri when -friction_vcri is 0.
ContactParams MakeContactParams(const Options &opt, double default_vcri)
{
  ContactParams prm;
  prm.mu = opt.friction_mu;
  prm.vcri = opt.friction_vcri > 0 ? opt.friction_vcri : default_vcri;
  prm.dphi_max = opt.rmin_dphi;
  prm.tol = opt.friction_tol;
  prm.group_tol = opt.rmin_group_tol;
  return prm;
}

// Radius of the circle centred on the symmetry axis through a node on the axis
// and its neighbour along the surface: the local corner radius there.
double AxisCornerRadius(double on_axis, double nx, double ny)
{
  // Centre (c, 0): (on_axis - c)^2 = (nx - c)^2 + ny^2.
  const double c = (on_axis * on_axis - nx * nx - ny * ny) / (2 * (on_axis - nx));
  return on_axis - c;
}

class ToolScene : public Scene {
public:
  explicit ToolScene(const Options &opt) : opt_(opt), squaring_(opt.scene == SceneKind::Squaring)
  {
    stroke_ = opt.stroke_corner_radius > 0 ? StrokeForCornerRadius(opt.tube_ro, opt.stroke_corner_radius) : opt.stroke;
    back_ = stroke_; // withdraw: back to the start, so every node has left the tool (by r5)
    if (squaring_) tool_ = BuildVDie(opt.tube_ro, opt.die_r_apex, opt.die_u_close, opt.die_r_edge);
    else tool_ = BuildFlatPlate(opt.tube_ro, -0.1 * opt.tube_ro, 1.5 * opt.tube_ro);
    flank_ = squaring_ && opt.die_r_apex > 0 ? 1 : 0;
  }

  std::vector<std::string> BoundarySets() const override { return {"inner", "outer", "x0", "y0"}; }
  std::string BuildMesh(const Options &opt, SerialMesh &mesh) const override { return TubeMesh(opt, mesh); }
  double PathEnd() const override { return opt_.unload == "none" ? 1.0 : 2.0; }
  double Duration(const Options &opt) const override { return stroke_ / opt.punch_speed; }
  std::vector<double> Breakpoints() const override { return {1.0}; }

  PetscErrorCode Initialize(Problem &p) override
  {
    PetscFunctionBeginUser;
    // Default VCRI: 2 % of the circumferential element size of the outer surface.
    contact_.Setup(p, &tool_, "outer", {{"x0", {1, 0}}, {"y0", {0, 1}}}, MakeContactParams(opt_, 0.02 * opt_.tube_ro * 0.5 * M_PI / opt_.mesh_ntheta));
    PetscCall(contact_.Initialize(p));
    if (opt_.stroke_corner_radius > 0) PetscCall(PetscPrintf(p.comm(), "tubeform: stroke %.4f mm gives an outer corner radius of %.4g mm (perimeter-conserving rounded square)\n", stroke_, opt_.stroke_corner_radius));
    PetscFunctionReturn(PETSC_SUCCESS);
  }

  PetscErrorCode BeginStage(Problem &p, double lambda) override
  {
    PetscFunctionBeginUser;
    if (opt_.unload != "reverse") PetscFunctionReturn(PETSC_SUCCESS);
    // The paper's unloading: contact forces become loads, tools go, all elastic.
    PetscCall(VecDuplicate(p.system().reactions_local(), &reversed_));
    PetscCall(VecZeroEntries(reversed_));
    PetscCall(contact_.AddContactForces(p, reversed_));
    PetscCall(contact_.TotalForce(p, reversed_total_));
    contact_.ReleaseAll();
    p.system().ClearFrames();
    p.SetElasticOnly();
    unloading_ = true;
    PetscFunctionReturn(PETSC_SUCCESS);
  }

  PetscErrorCode BeginIncrement(Problem &p, double lambda) override
  {
    PetscFunctionBeginUser;
    tool_.stroke = Stroke(lambda);
    if (!unloading_) PetscCall(contact_.BeginIncrement(p));
    PetscFunctionReturn(PETSC_SUCCESS);
  }

  PetscErrorCode Load(Problem &p, double lambda, double dlambda, Vec dforce) override
  {
    PetscFunctionBeginUser;
    dU_ = Stroke(lambda + dlambda) - Stroke(lambda);
    if (unloading_) {
      // Reversed contact forces: from F at lambda = 1 to 0 at lambda = 2.
      const PetscScalar *f;
      PetscCall(VecGetArrayRead(reversed_, &f));
      for (PetscInt n = 0; n < p.mesh().num_nodes; ++n) {
        const double fx = -dlambda * PetscRealPart(f[p.mesh().node_dof[n]]), fy = -dlambda * PetscRealPart(f[p.mesh().node_dof[n] + 1]);
        if (fx != 0 || fy != 0) p.system().AddForce(n, fx, fy);
      }
      PetscCall(VecRestoreArrayRead(reversed_, &f));
      PetscCall(VecAXPY(dforce, -dlambda, reversed_));
    } else PetscCall(contact_.Constrain(p, dU_));
    PetscCall(QuarterSymmetry(p));
    PetscFunctionReturn(PETSC_SUCCESS);
  }

  PetscErrorCode ExternalForce(Problem &p, double lambda, Vec f) override
  {
    PetscFunctionBeginUser;
    PetscCall(VecZeroEntries(f));
    if (unloading_) PetscCall(VecAXPY(f, 2.0 - lambda, reversed_));
    else PetscCall(contact_.AddFrictionForces(p, f));
    PetscFunctionReturn(PETSC_SUCCESS);
  }

  bool Iterative() const override { return !unloading_ && contact_.friction(); }
  void ResetIterates() override { contact_.ResetIterates(); }
  void LinearizeAtStart() override { contact_.LinearizeAtStart(); }
  PetscErrorCode UpdateIterates(Problem &p, Vec du, bool &converged) override { return contact_.UpdateIterates(p, du, dU_, converged); }
  PetscErrorCode LimitStep(Problem &p, Vec du, StepLimit &limit) override { return unloading_ ? 0 : contact_.LimitStep(p, du, dU_, limit); }
  PetscErrorCode Switches(Problem &p, Vec du, bool apply, PetscInt &n) override
  {
    n = 0;
    return unloading_ ? 0 : contact_.ReleasePulled(p, du, dU_, apply, n);
  }
  PetscErrorCode CommitIncrement(Problem &p, Vec du, double react_scale, double r, double &w_friction) override
  {
    w_friction = 0;
    return unloading_ ? 0 : contact_.Commit(p, du, react_scale * dU_, react_scale, r, w_friction);
  }

  PetscErrorCode Measure(Problem &p, double lambda, Vec, HistoryRow &row) override
  {
    double force[2];
    PetscInt n;
    PetscFunctionBeginUser;
    row.stroke = Stroke(lambda);
    if (unloading_) {
      for (int k = 0; k < 2; ++k) force[k] = (2.0 - lambda) * reversed_total_[k];
    } else PetscCall(contact_.TotalForce(p, force));
    row.load = -2.0 * force[1]; // full tube: both halves push the die up
    row.tool_fx = -force[0], row.tool_fy = -force[1];
    PetscCall(contact_.Count(p, n));
    row.n_contact = n;
    PetscCall(OuterExtents(p, row));
    if (!unloading_) PetscCall(contact_.Violations(p, row.penetration, row.tension)); // no tools while unloading
    PetscCall(Shape(p, row));
    row.stage = lambda > 1.0 + 1e-12 ? 1 : 0;
    PetscFunctionReturn(PETSC_SUCCESS);
  }

  std::vector<std::pair<std::string, double>> FinalMetrics(const History &h) const override
  {
    // Loaded state: the last row of the loading stage.
    const HistoryRow *loaded = &h.rows().front();
    for (const auto &r : h.rows())
      if (r.stage == 0) loaded = &r;
    const HistoryRow &last = h.rows().back();
    return {{"loaded_c_over_t", loaded->c_over_t}, {"loaded_deviation_ratio", loaded->deviation_ratio}, {"loaded_x_max", loaded->x_max}, {"loaded_y_max", loaded->y_max},
            {"unloaded_c_over_t", last.c_over_t}, {"unloaded_deviation_ratio", last.deviation_ratio}, {"unloaded_x_max", last.x_max}, {"unloaded_y_max", last.y_max}, {"final_stroke_target", stroke_}};
  }

  ~ToolScene() override { (void)VecDestroy(&reversed_); }

private:
  Options opt_;
  bool squaring_;
  Tool tool_;
  ContactSet contact_;
  double stroke_ = 0, back_ = 0, dU_ = 0;
  int flank_ = 0;
  bool unloading_ = false;
  Vec reversed_ = nullptr;
  double reversed_total_[2] = {0, 0};
  double smin_loaded_ = 1e300, smax_loaded_ = -1e300; // flank contact region at the end of loading

  double Stroke(double lambda) const
  {
    if (lambda <= 1.0) return lambda * stroke_;
    return opt_.unload == "withdraw" ? stroke_ - (lambda - 1.0) * back_ : stroke_;
  }

  // C/t (METHOD.md sec. 6): the largest gap between the flank and the outer
  // surface between the outermost nodes touching the flank; and the corner radii.
  PetscErrorCode Shape(Problem &p, HistoryRow &row)
  {
    std::vector<OuterNode> all;
    PetscFunctionBeginUser;
    PetscCall(GatherOuter(p, contact_, all));
    if (all.size() >= 2) {
      row.r_corner_x = AxisCornerRadius(all.front().x, all[1].x, all[1].y);
      row.r_corner_y = AxisCornerRadius(all.back().y, all[all.size() - 2].y, all[all.size() - 2].x);
    }
    if (!squaring_) PetscFunctionReturn(PETSC_SUCCESS);
    const Segment &fl = tool_.segments[flank_];
    const Vec2 off = tool_.Offset(), a = {fl.a[0] + off[0], fl.a[1] + off[1]}, n = fl.n_line, l = {n[1], -n[0]};
    for (const auto &o : all) row.n_contact_apex += o.contact && flank_ == 1 && o.segment == 0;
    double smin = 1e300, smax = -1e300;
    if (unloading_) smin = smin_loaded_, smax = smax_loaded_; // the former contact region
    for (const auto &o : all)
      if (!unloading_ && o.contact && o.segment == flank_) {
        const double s = (o.x - a[0]) * l[0] + (o.y - a[1]) * l[1];
        smin = std::min(smin, s), smax = std::max(smax, s);
      }
    // Loaded: gaps to the flank. Unloaded (no die): the side's deviation from
    // straight over the former contact region, largest minus smallest gap to
    // the final flank line.
    double cmax = -1e300, cmin = 1e300;
    for (const auto &o : all) {
      const double s = (o.x - a[0]) * l[0] + (o.y - a[1]) * l[1];
      if (s < smin || s > smax) continue;
      const double g = (o.x - a[0]) * n[0] + (o.y - a[1]) * n[1];
      cmax = std::max(cmax, g), cmin = std::min(cmin, g);
    }
    if (cmax < cmin) row.c_over_t = 0;
    else row.c_over_t = (unloading_ ? cmax - cmin : std::max(cmax, 0.0)) / opt_.tube_t;
    if (!unloading_) smin_loaded_ = smin, smax_loaded_ = smax;
    PetscFunctionReturn(PETSC_SUCCESS);
  }
};

// A scene whose tool stays put (slide checks): the contact hooks forward to
// the ContactSet with a zero tool step.
class StaticContactScene : public Scene {
public:
  bool Iterative() const override { return contact_.friction(); }
  void ResetIterates() override { contact_.ResetIterates(); }
  void LinearizeAtStart() override { contact_.LinearizeAtStart(); }
  PetscErrorCode UpdateIterates(Problem &p, Vec du, bool &converged) override { return contact_.UpdateIterates(p, du, 0.0, converged); }
  PetscErrorCode LimitStep(Problem &p, Vec du, StepLimit &limit) override { return contact_.LimitStep(p, du, 0.0, limit); }
  PetscErrorCode Switches(Problem &p, Vec du, bool apply, PetscInt &n) override { return contact_.ReleasePulled(p, du, 0.0, apply, n); }
  PetscErrorCode CommitIncrement(Problem &p, Vec du, double react_scale, double r, double &w_friction) override { return contact_.Commit(p, du, 0.0, react_scale, r, w_friction); }

protected:
  ContactSet contact_;
};

// A block on a rigid floor (friction check, METHOD.md sec. 7): lambda in
// [0, 1] presses its top edge down with a total force -slide_n (top held in
// x); lambda in [1, 2] pushes the top edge sideways by -slide_push.
// History: stroke = top displacement (mm), load = tangential force T (N/mm).
class SlideScene : public StaticContactScene {
public:
  explicit SlideScene(const Options &opt) : opt_(opt), floor_(BuildFlatPlate(0.0, -1e3, 1e3, true)) {}
  std::vector<std::string> BoundarySets() const override { return {"left", "right", "bottom", "top"}; }
  std::string BuildMesh(const Options &opt, SerialMesh &mesh) const override
  {
    mesh = GenerateRectangle(kWidth, kHeight, (int)opt.mesh_ntheta, (int)opt.mesh_nt);
    return "";
  }
  std::vector<double> Breakpoints() const override { return {1.0}; }
  double PathEnd() const override { return 2.0; }
  PetscErrorCode Initialize(Problem &p) override
  {
    contact_.Setup(p, &floor_, "bottom", {}, MakeContactParams(opt_, 1e-3));
    return contact_.Initialize(p);
  }
  PetscErrorCode BeginIncrement(Problem &p, double) override { return contact_.BeginIncrement(p); }
  PetscErrorCode Load(Problem &p, double lambda, double dlambda, Vec dforce) override
  {
    PetscFunctionBeginUser;
    PetscCall(contact_.Constrain(p, 0.0));
    const double dn = lambda < 1.0 ? dlambda * opt_.slide_n : 0.0, push = lambda < 1.0 ? 0.0 : dlambda * opt_.slide_push;
    PetscCall(TopLoad(p, -dn, dforce, true));
    for (PetscInt n : p.mesh().node_sets["top"]) p.system().Prescribe(n, 0, push);
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  PetscErrorCode ExternalForce(Problem &p, double lambda, Vec f) override
  {
    PetscFunctionBeginUser;
    PetscCall(VecZeroEntries(f));
    PetscCall(TopLoad(p, -std::min(lambda, 1.0) * opt_.slide_n, f, false));
    PetscCall(contact_.AddFrictionForces(p, f));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  PetscErrorCode Measure(Problem &p, double lambda, Vec f_int, HistoryRow &row) override
  {
    PetscFunctionBeginUser;
    row.stroke = lambda <= 1.0 ? 0.0 : (lambda - 1.0) * opt_.slide_push;
    PetscCall(SetForce(p, "top", f_int, [](PetscInt, double d[2]) { d[0] = 1, d[1] = 0; }, row.load));
    PetscInt n;
    PetscCall(contact_.Count(p, n));
    row.n_contact = n;
    PetscCall(contact_.Violations(p, row.penetration, row.tension));
    // Mean slip of the bottom on the floor, in x_max's place.
    double local[2] = {0, 0}, g[2];
    for (PetscInt k : p.mesh().node_sets["bottom"])
      if (p.mesh().node_owned[k]) local[0] += p.displacement()[2 * k], local[1] += 1;
    PetscCallMPI(MPI_Allreduce(local, g, 2, MPI_DOUBLE, MPI_SUM, p.comm()));
    row.x_max = g[0] / g[1];
    double force[2];
    PetscCall(contact_.TotalForce(p, force));
    row.y_max = force[1]; // the floor's normal force on the block (= -slide_n when pressed)
    row.deviation_ratio = force[0];
    row.stage = lambda > 1.0 + 1e-12 ? 1 : 0;
    PetscFunctionReturn(PETSC_SUCCESS);
  }

private:
  static constexpr double kWidth = 10.0, kHeight = 2.0;
  Options opt_;
  Tool floor_;
  // A uniform vertical traction on the top edge with resultant fy (end nodes half weight).
  PetscErrorCode TopLoad(Problem &p, double fy, Vec f, bool to_system)
  {
    PetscScalar *a;
    PetscFunctionBeginUser;
    const double per = fy / opt_.mesh_ntheta;
    PetscCall(VecGetArray(f, &a));
    for (PetscInt n : p.mesh().node_sets["top"]) {
      if (!p.mesh().node_owned[n]) continue;
      const double x = p.mesh().x0[2 * n], w = (x < 1e-9 || x > kWidth - 1e-9) ? 0.5 : 1.0;
      a[p.mesh().node_dof[n] + 1] += w * per;
      if (to_system) p.system().AddForce(n, 0.0, w * per);
    }
    PetscCall(VecRestoreArray(f, &a));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
};

// Friction on an arc: a quarter ring (outer radius R = -tube_ro, wall -tube_t)
// inside a rigid cylinder of radius R (a concave arc tool). lambda in [0, 1]:
// an internal pressure pushes it onto the cylinder (inner nodes held in the
// tangential direction); lambda in [1, 2]: the inner surface is turned about
// the centre by -slide_push / R. Coulomb: the moment needed is
// mu R sum f_n = mu R p r_i pi/2 (sum f_n = p x inner arc length).
// History: stroke = turn of the inner surface (rad), load = moment (N mm/mm).
class ArcSlideScene : public StaticContactScene {
public:
  explicit ArcSlideScene(const Options &opt) : opt_(opt)
  {
    Segment arc;
    arc.kind = Segment::Arc;
    arc.c = {0, 0};
    arc.radius = opt.tube_ro;
    arc.t0 = -M_PI / 3;
    arc.t1 = M_PI / 2 + M_PI / 3;
    arc.concave = true;
    tool_.name = "cylinder";
    tool_.segments = {arc};
  }
  std::vector<std::string> BoundarySets() const override { return {"inner", "outer", "x0", "y0"}; }
  std::string BuildMesh(const Options &opt, SerialMesh &mesh) const override { return TubeMesh(opt, mesh); }
  std::vector<double> Breakpoints() const override { return {1.0}; }
  double PathEnd() const override { return 2.0; }
  PetscErrorCode Initialize(Problem &p) override
  {
    contact_.Setup(p, &tool_, "outer", {}, MakeContactParams(opt_, 1e-3));
    return contact_.Initialize(p);
  }
  PetscErrorCode BeginIncrement(Problem &p, double) override
  {
    PetscFunctionBeginUser;
    for (PetscInt n : p.mesh().node_sets["inner"]) p.system().SetFrame(n, std::atan2(p.position()[2 * n + 1], p.position()[2 * n]));
    PetscCall(contact_.BeginIncrement(p));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  PetscErrorCode Load(Problem &p, double lambda, double dlambda, Vec dforce) override
  {
    PetscFunctionBeginUser;
    PetscCall(contact_.Constrain(p, 0.0));
    const double ri = opt_.tube_ro - opt_.tube_t;
    if (lambda < 1.0) PetscCall(AddEdgePressure(p, "inner", dlambda * opt_.slide_n, dforce, true, lambda * opt_.slide_n));
    const double turn = lambda < 1.0 ? 0.0 : dlambda * opt_.slide_push / opt_.tube_ro;
    for (PetscInt n : p.mesh().node_sets["inner"]) p.system().Prescribe(n, 1, turn * ri); // tangential (frame l = radial)
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  PetscErrorCode ExternalForce(Problem &p, double lambda, Vec f) override
  {
    PetscFunctionBeginUser;
    PetscCall(VecZeroEntries(f));
    PetscCall(AddEdgePressure(p, "inner", std::min(lambda, 1.0) * opt_.slide_n, f, false));
    PetscCall(contact_.AddFrictionForces(p, f));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  PetscErrorCode Measure(Problem &p, double lambda, Vec f_int, HistoryRow &row) override
  {
    PetscFunctionBeginUser;
    row.stroke = lambda <= 1.0 ? 0.0 : (lambda - 1.0) * opt_.slide_push / opt_.tube_ro;
    // Moment about the centre of the internal forces at the inner nodes (their supports).
    const auto &x = p.position();
    PetscCall(SetForce(p, "inner", f_int, [&](PetscInt n, double d[2]) { d[0] = -x[2 * n + 1], d[1] = x[2 * n]; }, row.load));
    PetscInt n;
    PetscCall(contact_.Count(p, n));
    row.n_contact = n;
    PetscCall(contact_.Violations(p, row.penetration, row.tension));
    PetscCall(contact_.NormalForceSum(p, row.y_max)); // sum of f_n, in y_max's place
    row.stage = lambda > 1.0 + 1e-12 ? 1 : 0;
    PetscFunctionReturn(PETSC_SUCCESS);
  }

private:
  Options opt_;
  Tool tool_;
};

} // namespace

std::unique_ptr<Scene> CreateToolScene(const Options &opt)
{
  if (opt.scene == SceneKind::Slide && opt.slide_tool == "arc") return std::make_unique<ArcSlideScene>(opt);
  if (opt.scene == SceneKind::Slide) return std::make_unique<SlideScene>(opt);
  return std::make_unique<ToolScene>(opt);
}

} // namespace tf
