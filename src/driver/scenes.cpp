// The scenes (METHOD.md section 1). Each builds only what it needs.
#include <cmath>

#include "tubeform/core.hpp"
#include "tubeform/driver/problem.hpp"
#include "tubeform/driver/scene_util.hpp"
#include "tubeform/mesh/generator.hpp"
#include "tubeform/mesh/gmsh_reader.hpp"

namespace tf {

// Nodal forces of a uniform pressure on the edges of `set`, on the current
// geometry: each edge pushes its two nodes by -p n L / 2 (n outward from the
// body). With `stiffness_p` != 0 the follower-load stiffness of that pressure
// goes into the system: with n L = (y_b - y_a, x_a - x_b) the nodal force
// changes by (p/2) (du_ya - du_yb, du_xb - du_xa) as the edge moves, and
// moving that to the left-hand side adds its negative to K.
PetscErrorCode AddEdgePressure(Problem &p, const std::string &set, double pressure, Vec f_local, bool to_system, double stiffness_p)
{
  PetscScalar *f;
  Mesh &mesh = p.mesh();
  const auto &x = p.position();

  PetscFunctionBeginUser;
  PetscCall(VecGetArray(f_local, &f));
  for (const auto &edge : mesh.edge_sets[set]) {
    double cx = 0, cy = 0;
    for (int k = 0; k < 4; ++k) {
      const PetscInt n = mesh.cell_nodes[4 * edge.cell + k];
      cx += 0.25 * x[2 * n];
      cy += 0.25 * x[2 * n + 1];
    }
    PetscInt a = edge.node[0], b = edge.node[1];
    const double mx = 0.5 * (x[2 * a] + x[2 * b]) - cx, my = 0.5 * (x[2 * a + 1] + x[2 * b + 1]) - cy;
    if ((x[2 * b + 1] - x[2 * a + 1]) * mx - (x[2 * b] - x[2 * a]) * my < 0) std::swap(a, b); // orient a -> b so n points out
    const double nx = x[2 * b + 1] - x[2 * a + 1], ny = -(x[2 * b] - x[2 * a]); // |n| = edge length
    if (stiffness_p != 0) {
      const double h = 0.5 * stiffness_p;
      const PetscInt nodes[2] = {a, b};
      // dofs (a_x, a_y, b_x, b_y); both nodes get the same rows.
      double k[16] = {0};
      for (int r = 0; r < 2; ++r) {
        k[(2 * r) * 4 + 1] = -h, k[(2 * r) * 4 + 3] = h;         // row x: -(dF_x/d y_a, dF_x/d y_b)
        k[(2 * r + 1) * 4 + 0] = h, k[(2 * r + 1) * 4 + 2] = -h; // row y: -(dF_y/d x_a, dF_y/d x_b)
      }
      PetscCall(p.system().AddBlock(nodes, 2, k));
    }
    for (PetscInt node : {a, b}) {
      const double fx = -0.5 * pressure * nx, fy = -0.5 * pressure * ny;
      f[mesh.node_dof[node]] += fx;
      f[mesh.node_dof[node] + 1] += fy;
      if (to_system) p.system().AddForce(node, fx, fy);
    }
  }
  PetscCall(VecRestoreArray(f_local, &f));
  PetscFunctionReturn(PETSC_SUCCESS);
}

// Mirror-symmetry supports of a quarter model: u_x = 0 on x = 0, u_y = 0 on
// y = 0, written in each node's frame.
PetscErrorCode QuarterSymmetry(Problem &p)
{
  PetscFunctionBeginUser;
  for (PetscInt n : p.mesh().node_sets["x0"]) PetscCheck(p.system().PrescribeAlong(n, 1, 0, 0.0), PETSC_COMM_SELF, PETSC_ERR_PLIB, "symmetry support not along a node frame axis");
  for (PetscInt n : p.mesh().node_sets["y0"]) PetscCheck(p.system().PrescribeAlong(n, 0, 1, 0.0), PETSC_COMM_SELF, PETSC_ERR_PLIB, "symmetry support not along a node frame axis");
  PetscFunctionReturn(PETSC_SUCCESS);
}

// Largest current x and y over the outer surface: C1 and C2 of METHOD.md sec. 6.
PetscErrorCode OuterExtents(Problem &p, HistoryRow &row)
{
  double ext[2] = {0, 0}, g[2];
  PetscFunctionBeginUser;
  for (PetscInt n : p.mesh().node_sets["outer"]) {
    ext[0] = std::max(ext[0], p.position()[2 * n]);
    ext[1] = std::max(ext[1], p.position()[2 * n + 1]);
  }
  PetscCall(MPIU_Allreduce(ext, g, 2, MPIU_REAL, MPIU_MAX, p.comm()));
  row.x_max = g[0];
  row.y_max = g[1];
  row.deviation_ratio = std::max(g[0], g[1]) > 0 ? std::min(g[0], g[1]) / std::max(g[0], g[1]) : 1.0;
  PetscFunctionReturn(PETSC_SUCCESS);
}

std::string TubeMesh(const Options &opt, SerialMesh &mesh)
{
  if (!opt.mesh_file.empty()) return ReadGmsh(opt.mesh_file, mesh);
  mesh = GenerateQuarterAnnulus(opt.tube_ro, opt.tube_t, (int)opt.mesh_nt, (int)opt.mesh_ntheta);
  return "";
}

namespace {

// Thick cylinder under internal pressure (quarter, plane strain).
// -pressure_control load: the pressure is ramped to -pressure_p; history
//   stroke = mean radial displacement of the inner surface (mm), load = pressure (MPa).
// -pressure_control displacement: the inner radial displacement is ramped to
//   -pressure_u (inner nodes carry radial frames); stroke = that displacement,
//   load = the pressure it takes: radial reaction / current inner arc length.
class PressureScene : public Scene {
public:
  explicit PressureScene(const Options &opt) : opt_(opt), displacement_(opt.pressure_control == "displacement") {}
  std::vector<std::string> BoundarySets() const override { return {"inner", "outer", "x0", "y0"}; }
  std::string BuildMesh(const Options &opt, SerialMesh &mesh) const override { return TubeMesh(opt, mesh); }

  PetscErrorCode BeginIncrement(Problem &p, double) override
  {
    // Radial frames on the inner surface (axisymmetry keeps nodes on their rays).
    if (displacement_)
      for (PetscInt n : p.mesh().node_sets["inner"]) p.system().SetFrame(n, std::atan2(p.mesh().x0[2 * n + 1], p.mesh().x0[2 * n]));
    return 0;
  }

  PetscErrorCode Load(Problem &p, double lambda, double dlambda, Vec dforce) override
  {
    PetscFunctionBeginUser;
    if (displacement_)
      for (PetscInt n : p.mesh().node_sets["inner"]) p.system().Prescribe(n, 0, dlambda * opt_.pressure_u);
    else PetscCall(AddEdgePressure(p, "inner", dlambda * opt_.pressure_p, dforce, true, lambda * opt_.pressure_p));
    PetscCall(QuarterSymmetry(p));
    PetscFunctionReturn(PETSC_SUCCESS);
  }

  PetscErrorCode ExternalForce(Problem &p, double lambda, Vec f) override
  {
    PetscFunctionBeginUser;
    PetscCall(VecZeroEntries(f));
    if (!displacement_) PetscCall(AddEdgePressure(p, "inner", lambda * opt_.pressure_p, f, false));
    PetscFunctionReturn(PETSC_SUCCESS);
  }

  PetscErrorCode Measure(Problem &p, double lambda, Vec f_int, HistoryRow &row) override
  {
    double sum[3] = {0, 0, 0}, g[3];
    PetscFunctionBeginUser;
    const Mesh &m = p.mesh();
    const auto &x = p.position();
    for (PetscInt n : p.mesh().node_sets["inner"]) {
      if (!m.node_owned[n]) continue;
      const double r = std::hypot(m.x0[2 * n], m.x0[2 * n + 1]);
      sum[0] += (p.displacement()[2 * n] * m.x0[2 * n] + p.displacement()[2 * n + 1] * m.x0[2 * n + 1]) / r;
      sum[1] += 1;
    }
    for (const auto &e : p.mesh().edge_sets["inner"]) sum[2] += std::hypot(x[2 * e.node[1]] - x[2 * e.node[0]], x[2 * e.node[1] + 1] - x[2 * e.node[0] + 1]);
    PetscCall(MPIU_Allreduce(sum, g, 3, MPIU_REAL, MPIU_SUM, p.comm()));
    row.stroke = g[0] / g[1];
    if (displacement_) {
      double fr;
      const auto radial = [&](PetscInt n, double d[2]) {
        const double r = std::hypot(m.x0[2 * n], m.x0[2 * n + 1]);
        d[0] = m.x0[2 * n] / r, d[1] = m.x0[2 * n + 1] / r; // internal force = the pressure the support applies
      };
      PetscCall(SetForce(p, "inner", f_int, radial, fr));
      row.load = fr / g[2];
    } else row.load = lambda * opt_.pressure_p;
    PetscCall(OuterExtents(p, row));
    PetscFunctionReturn(PETSC_SUCCESS);
  }

private:
  Options opt_;
  bool displacement_;
};

// Homogeneous blocks on the unit square: every boundary node follows a
// prescribed motion, the interior follows by equilibrium.
class BlockScene : public Scene {
public:
  explicit BlockScene(const Options &opt) : opt_(opt) {}
  std::vector<std::string> BoundarySets() const override { return {"left", "right", "bottom", "top"}; }
  std::string BuildMesh(const Options &opt, SerialMesh &mesh) const override
  {
    mesh = GenerateRectangle(1.0, 1.0, (int)opt.mesh_nt, (int)opt.mesh_nt);
    return "";
  }
  PetscErrorCode ExternalForce(Problem &, double, Vec f) override { return VecZeroEntries(f); }

protected:
  Options opt_;
  // Prescribes du = motion(node) on each boundary node, once.
  template <class Motion>
  void PrescribeBoundary(Problem &p, Motion motion)
  {
    std::vector<char> done(p.mesh().num_nodes, 0);
    for (const auto &set : BoundarySets())
      for (PetscInt n : p.mesh().node_sets[set]) {
        if (done[n]) continue;
        done[n] = 1;
        double d[2];
        motion(n, d);
        p.system().Prescribe(n, 0, d[0]);
        p.system().Prescribe(n, 1, d[1]);
      }
  }
};

// Simple shear x = X + gamma Y to -shear_gamma. History: stroke = gamma,
// load = mean sigma_xy (MPa). Hypoelastic Jaumann reference:
// sigma_xy = G sin(gamma), sigma_xx = -sigma_yy = G (1 - cos(gamma)).
class ShearScene : public BlockScene {
public:
  using BlockScene::BlockScene;
  PetscErrorCode Load(Problem &p, double, double dlambda, Vec) override
  {
    const double dgamma = dlambda * opt_.shear_gamma;
    PrescribeBoundary(p, [&](PetscInt n, double d[2]) { d[0] = dgamma * p.position()[2 * n + 1], d[1] = 0; });
    return 0;
  }
  PetscErrorCode Measure(Problem &p, double lambda, Vec, HistoryRow &row) override
  {
    PetscFunctionBeginUser;
    row.stroke = lambda * opt_.shear_gamma;
    PetscCall(PointAverage(p, [](const PointState &s) { return s.sigma[3]; }, row.load));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
};

// Plane-strain uniaxial tension or compression of a block (sigma_yy = 0):
// left edge u_x = 0, bottom edge u_y = 0, right edge u_x = lambda * -tension_strain.
// History: stroke = nominal strain, load = mean sigma_xx (MPa).
class TensionScene : public BlockScene {
public:
  using BlockScene::BlockScene;
  PetscErrorCode Load(Problem &p, double, double dlambda, Vec) override
  {
    for (PetscInt n : p.mesh().node_sets["left"]) p.system().Prescribe(n, 0, 0.0);
    for (PetscInt n : p.mesh().node_sets["bottom"]) p.system().Prescribe(n, 1, 0.0);
    for (PetscInt n : p.mesh().node_sets["right"]) p.system().Prescribe(n, 0, dlambda * opt_.tension_strain);
    return 0;
  }
  PetscErrorCode Measure(Problem &p, double lambda, Vec, HistoryRow &row) override
  {
    PetscFunctionBeginUser;
    row.stroke = lambda * opt_.tension_strain;
    PetscCall(PointAverage(p, [](const PointState &s) { return s.sigma[0]; }, row.load));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
};

// A block stretched in x (uniaxial strain -rotation_strain, lambda in [0, 0.1])
// then turned rigidly about the origin by -rotation_angle (lambda in [0.1, 1]).
// History: stroke = rotation angle so far (degrees), load = mean von Mises stress.
class RotationScene : public BlockScene {
public:
  using BlockScene::BlockScene;
  std::vector<double> Breakpoints() const override { return {kStretch}; }
  PetscErrorCode Load(Problem &p, double lambda, double dlambda, Vec) override
  {
    if (lambda < kStretch - 1e-12) {
      const double de = dlambda / kStretch * opt_.rotation_strain;
      PrescribeBoundary(p, [&](PetscInt n, double d[2]) { d[0] = de * p.mesh().x0[2 * n], d[1] = 0; });
    } else {
      const double dth = dlambda / (1 - kStretch) * opt_.rotation_angle * M_PI / 180, c = std::cos(dth), s = std::sin(dth);
      PrescribeBoundary(p, [&](PetscInt n, double d[2]) {
        const double x = p.position()[2 * n], y = p.position()[2 * n + 1];
        d[0] = (c - 1) * x - s * y, d[1] = s * x + (c - 1) * y;
      });
    }
    return 0;
  }
  PetscErrorCode Measure(Problem &p, double lambda, Vec, HistoryRow &row) override
  {
    PetscFunctionBeginUser;
    row.stroke = lambda <= kStretch ? 0.0 : (lambda - kStretch) / (1 - kStretch) * opt_.rotation_angle;
    PetscCall(PointAverage(p, [](const PointState &s) { return VonMises(s.sigma); }, row.load));
    PetscFunctionReturn(PETSC_SUCCESS);
  }

private:
  static constexpr double kStretch = 0.1;
};

// A strip of thickness t (x) and length L (y) with a sine bow of amplitude e0,
// pinned at the centre nodes of both ends and shortened by -stroke.
// History: stroke = end shortening (mm), load = axial force (N/mm).
class ColumnScene : public Scene {
public:
  explicit ColumnScene(const Options &opt) : opt_(opt) {}
  std::vector<std::string> BoundarySets() const override { return {"left", "right", "bottom", "top"}; }
  std::string BuildMesh(const Options &opt, SerialMesh &mesh) const override
  {
    if (opt.mesh_nt % 2) return "-mesh_nt " + std::to_string(opt.mesh_nt) + ": the column needs an even number of elements through the thickness (a node on the axis)";
    mesh = GenerateRectangle(opt.column_t, opt.column_l, (int)opt.mesh_nt, (int)opt.mesh_ntheta);
    for (int n = 0; n < mesh.num_nodes(); ++n) {
      const double y = mesh.xy[2 * n + 1];
      mesh.xy[2 * n] += -0.5 * opt.column_t + opt.column_imperfection * std::sin(M_PI * y / opt.column_l);
    }
    return "";
  }
  PetscErrorCode Load(Problem &p, double, double dlambda, Vec) override
  {
    for (PetscInt n : Pins(p, "bottom")) p.system().Prescribe(n, 0, 0.0), p.system().Prescribe(n, 1, 0.0);
    for (PetscInt n : Pins(p, "top")) p.system().Prescribe(n, 0, 0.0), p.system().Prescribe(n, 1, -dlambda * opt_.stroke);
    return 0;
  }
  PetscErrorCode ExternalForce(Problem &, double, Vec f) override { return VecZeroEntries(f); }
  PetscErrorCode Measure(Problem &p, double lambda, Vec f_int, HistoryRow &row) override
  {
    PetscFunctionBeginUser;
    row.stroke = lambda * opt_.stroke;
    const auto pins = Pins(p, "top");
    const PetscScalar *f;
    double local = 0;
    PetscCall(VecGetArrayRead(f_int, &f));
    for (PetscInt n : pins) local += PetscRealPart(f[p.mesh().node_dof[n] + 1]);
    PetscCall(VecRestoreArrayRead(f_int, &f));
    PetscCall(MPIU_Allreduce(&local, &row.load, 1, MPIU_REAL, MPIU_SUM, p.comm()));
    row.load = -row.load; // the strip pushes the pin up: compression counts positive
    PetscFunctionReturn(PETSC_SUCCESS);
  }

private:
  Options opt_;
  // The end node on the column's axis (x0 = 0 at both ends, where the bow vanishes).
  static std::vector<PetscInt> Pins(Problem &p, const std::string &end)
  {
    std::vector<PetscInt> pins;
    for (PetscInt n : p.mesh().node_sets[end])
      if (std::abs(p.mesh().x0[2 * n]) < 1e-9) pins.push_back(n);
    return pins;
  }
};

} // namespace

std::unique_ptr<Scene> CreateToolScene(const Options &opt); // tool_scenes.cpp

std::unique_ptr<Scene> CreateScene(const Options &opt)
{
  switch (opt.scene) {
  case SceneKind::Pressure: return std::make_unique<PressureScene>(opt);
  case SceneKind::Shear: return std::make_unique<ShearScene>(opt);
  case SceneKind::Rotation: return std::make_unique<RotationScene>(opt);
  case SceneKind::Tension: return std::make_unique<TensionScene>(opt);
  case SceneKind::Squaring:
  case SceneKind::Flattening:
  case SceneKind::Slide: return CreateToolScene(opt);
  case SceneKind::Column: return std::make_unique<ColumnScene>(opt);
  default: return nullptr;
  }
}

} // namespace tf
