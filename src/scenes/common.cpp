#include "tubeform/scenes/common.hpp"

#include <algorithm>

#include "tubeform/mesh/generator.hpp"
#include "tubeform/mesh/gmsh_reader.hpp"

namespace tf {

// Each edge pushes its two nodes by -p n L / 2 (n outward from the body). With
// n L = (y_b - y_a, x_a - x_b) the nodal force changes by
// (p/2) (du_ya - du_yb, du_xb - du_xa) as the edge moves; moving that to the
// left-hand side adds its negative to K.
PetscErrorCode AddEdgePressure(Model &m, const std::string &set, double pressure, Vec f_local, bool to_system,
                               double stiffness_p)
{
  PetscScalar *f = nullptr;
  Mesh &mesh = m.mesh;
  const auto &x = m.body.position();

  PetscFunctionBeginUser;
  if (f_local) PetscCall(VecGetArray(f_local, &f));
  for (const auto &edge : mesh.edge_sets[set]) {
    double cx = 0, cy = 0;
    for (int k = 0; k < 4; ++k) {
      const PetscInt n = mesh.cell_nodes[4 * edge.cell + k];
      cx += 0.25 * x[2 * n];
      cy += 0.25 * x[2 * n + 1];
    }
    PetscInt a = edge.node[0], b = edge.node[1];
    const double mx = 0.5 * (x[2 * a] + x[2 * b]) - cx, my = 0.5 * (x[2 * a + 1] + x[2 * b + 1]) - cy;
    // Orient a -> b so that n points out of the cell.
    if ((x[2 * b + 1] - x[2 * a + 1]) * mx - (x[2 * b] - x[2 * a]) * my < 0) std::swap(a, b);
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
      PetscCall(m.system.AddBlock(nodes, 2, k));
    }
    for (PetscInt node : {a, b}) {
      const double fx = -0.5 * pressure * nx, fy = -0.5 * pressure * ny;
      if (f) {
        f[mesh.node_dof[node]] += fx;
        f[mesh.node_dof[node] + 1] += fy;
      }
      if (to_system) m.system.AddForce(node, fx, fy);
    }
  }
  if (f_local) PetscCall(VecRestoreArray(f_local, &f));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode HoldAlong(Model &m, const std::string &set, double dx, double dy)
{
  PetscFunctionBeginUser;
  for (PetscInt n : m.mesh.node_sets[set])
    PetscCheck(m.system.PrescribeAlong(n, dx, dy, 0.0), PETSC_COMM_SELF, PETSC_ERR_PLIB,
               "the support of node set %s is not along a node frame axis", set.c_str());
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode QuarterSymmetry(Model &m)
{
  PetscFunctionBeginUser;
  PetscCall(HoldAlong(m, "x0", 1, 0));
  PetscCall(HoldAlong(m, "y0", 0, 1));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode OuterExtents(Model &m, HistoryRow &row, TubePart part, const TurnMap &press)
{
  // (the half and full models' tube may sit anywhere along y)
  double ext[4] = {0, -kNever, -kNever, -kNever}, g[4];
  PetscFunctionBeginUser;
  const auto &x = m.body.position();
  for (PetscInt n : m.mesh.node_sets["outer"]) {
    const Vec2 p = press({x[2 * n], x[2 * n + 1]});
    ext[0] = std::max(ext[0], p[0]);
    ext[1] = std::max(ext[1], p[1]);
    ext[2] = std::max(ext[2], -p[1]);
    ext[3] = std::max(ext[3], -p[0]);
  }
  PetscCall(MPIU_Allreduce(ext, g, 4, MPIU_REAL, MPIU_MAX, m.comm));
  row.x_max = part == TubePart::Full ? 0.5 * (g[0] + g[3]) : g[0];
  row.y_max = part != TubePart::Quarter ? 0.5 * (g[1] + g[2]) : g[1];
  row.deviation_ratio = row.y_max > 0 ? row.x_max / row.y_max : 1.0; // C1 / C2
  PetscFunctionReturn(PETSC_SUCCESS);
}

std::vector<std::pair<std::string, double>> PassMetrics(const History &h)
{
  std::vector<std::pair<std::string, double>> m;
  int passes = 1; // (pass k presses in stage 2k: the passes the history reached)
  for (const HistoryRow &r : h.rows()) passes = std::max(passes, (int)(r.stage / 2) + 1);
  for (int p = 0; p < passes; ++p) {
    const HistoryRow *loaded = &h.rows().front(), *unloaded = loaded;
    for (const auto &r : h.rows()) {
      if (r.stage == 2 * p) loaded = &r;
      if (r.stage <= 2 * p + 1) unloaded = &r;
    }
    const std::string pre = p == 0 ? "" : Formatted("pass%d_", p + 1);
    for (auto [name, row] : {std::pair{"loaded_", loaded}, {"unloaded_", unloaded}})
      for (auto [what, v] : {std::pair{"c_over_t", row->c_over_t},
                             {"deviation_ratio", row->deviation_ratio},
                             {"x_max", row->x_max},
                             {"y_max", row->y_max}})
        m.push_back({pre + name + what, v});
  }
  return m;
}

// A half or full model's mesh reaches at least this share of its extent on one side of an axis on the other.
constexpr double kHalfCover = 0.9;

std::string TubeMesh(const Options &opt, SerialMesh &mesh, TubePart part)
{
  if (!opt.mesh_file.empty()) {
    const std::string error = ReadGmsh(opt.mesh_file, mesh);
    if (!error.empty() || part == TubePart::Quarter) return error;
    // The half model's mesh reaches below the x axis as far as above it (a quarter would hang from nothing),
    // the full model's left of the y axis as far as right of it.
    double low[2] = {0, 0}, high[2] = {0, 0};
    for (size_t k = 0; k < mesh.xy.size(); ++k)
      low[k % 2] = std::min(low[k % 2], mesh.xy[k]), high[k % 2] = std::max(high[k % 2], mesh.xy[k]);
    if (low[1] >= -kHalfCover * high[1])
      return "-mesh_file " + opt.mesh_file + ": the " + (part == TubePart::Full ? "full" : "half") +
             " model (-model, or a lower die that is not the upper one's mirror) needs the tube from -90 to 90 " +
             "degrees at least; this mesh does not reach below the x axis";
    if (part == TubePart::Full && low[0] >= -kHalfCover * high[0])
      return "-mesh_file " + opt.mesh_file + ": -model full needs the whole tube; this mesh does not reach left " +
             "of the y axis";
    return "";
  }
  const int nt = (int)opt.mesh_nt, ntheta = (int)opt.mesh_ntheta;
  mesh = part == TubePart::Full   ? GenerateFullAnnulus(opt.tube_ro, opt.tube_t, nt, ntheta)
         : part == TubePart::Half ? GenerateHalfAnnulus(opt.tube_ro, opt.tube_t, nt, ntheta)
                                  : GenerateQuarterAnnulus(opt.tube_ro, opt.tube_t, nt, ntheta);
  return "";
}

} // namespace tf
