// The scenes (METHOD.md section 1). Each builds only what it needs.
#include <cmath>

#include "tubeform/core.hpp"
#include "tubeform/driver/problem.hpp"
#include "tubeform/mesh/generator.hpp"
#include "tubeform/mesh/gmsh_reader.hpp"

namespace tf {

namespace {

// Nodal forces of a uniform pressure on the edges of `set`, on the current
// geometry: each edge pushes its two nodes by -p n L / 2 (n outward from the
// body). With `stiffness_p` != 0 the follower-load stiffness of that pressure
// goes into the system: with n L = (y_b - y_a, x_a - x_b) the nodal force
// changes by (p/2) (du_ya - du_yb, du_xb - du_xa) as the edge moves, and
// moving that to the left-hand side adds its negative to K.
PetscErrorCode AddEdgePressure(Problem &p, const std::string &set, double pressure, Vec f_local, bool to_system, double stiffness_p = 0)
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
        k[(2 * r) * 4 + 1] = -h, k[(2 * r) * 4 + 3] = h;     // row x: -(dF_x/d y_a, dF_x/d y_b)
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

// Mirror-symmetry supports of a quarter model: u_x = 0 on x = 0, u_y = 0 on y = 0.
void QuarterSymmetry(Problem &p)
{
  for (PetscInt n : p.mesh().node_sets["x0"]) p.system().Prescribe(n, 0, 0.0);
  for (PetscInt n : p.mesh().node_sets["y0"]) p.system().Prescribe(n, 1, 0.0);
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

// Thick cylinder under internal pressure (quarter, plane strain).
// History: stroke = mean radial displacement of the inner surface (mm),
// load = internal pressure (MPa).
class PressureScene : public Scene {
public:
  explicit PressureScene(const Options &opt) : p_final_(opt.pressure_p) {}
  std::vector<std::string> BoundarySets() const override { return {"inner", "outer", "x0", "y0"}; }
  std::string BuildMesh(const Options &opt, SerialMesh &mesh) const override { return TubeMesh(opt, mesh); }

  PetscErrorCode Load(Problem &p, double lambda, double dlambda, Vec dforce) override
  {
    PetscFunctionBeginUser;
    PetscCall(AddEdgePressure(p, "inner", dlambda * p_final_, dforce, true, lambda * p_final_));
    QuarterSymmetry(p);
    PetscFunctionReturn(PETSC_SUCCESS);
  }

  PetscErrorCode ExternalForce(Problem &p, double lambda, Vec f) override
  {
    PetscFunctionBeginUser;
    PetscCall(VecZeroEntries(f));
    PetscCall(AddEdgePressure(p, "inner", lambda * p_final_, f, false));
    PetscFunctionReturn(PETSC_SUCCESS);
  }

  PetscErrorCode Measure(Problem &p, double lambda, HistoryRow &row) override
  {
    double sum[2] = {0, 0}, g[2];
    PetscFunctionBeginUser;
    const Mesh &m = p.mesh();
    for (PetscInt n : p.mesh().node_sets["inner"]) {
      if (!m.node_owned[n]) continue;
      const double r = std::hypot(m.x0[2 * n], m.x0[2 * n + 1]);
      sum[0] += (p.displacement()[2 * n] * m.x0[2 * n] + p.displacement()[2 * n + 1] * m.x0[2 * n + 1]) / r;
      sum[1] += 1;
    }
    PetscCall(MPIU_Allreduce(sum, g, 2, MPIU_REAL, MPIU_SUM, p.comm()));
    row.stroke = g[0] / g[1];
    row.load = lambda * p_final_;
    PetscCall(OuterExtents(p, row));
    PetscFunctionReturn(PETSC_SUCCESS);
  }

private:
  double p_final_;
};

} // namespace

std::unique_ptr<Scene> CreateScene(const Options &opt)
{
  switch (opt.scene) {
  case SceneKind::Pressure: return std::make_unique<PressureScene>(opt);
  default: return nullptr;
  }
}

} // namespace tf
