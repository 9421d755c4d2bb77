// Homogeneous blocks on the unit square: every boundary node follows a
// prescribed motion, the interior follows by equilibrium (shear, tension,
// rotation scenes).
#pragma once

#include <vector>

#include "tubeform/mesh/generator.hpp"
#include "tubeform/scenes/common.hpp"

namespace tf {

class BlockScene : public Scene {
public:
  explicit BlockScene(const Options &opt) : opt_(opt) {}
  std::vector<std::string> BoundarySets() const override { return {"left", "right", "bottom", "top"}; }
  std::string BuildMesh(const Options &opt, SerialMesh &mesh) const override
  {
    mesh = GenerateRectangle(1.0, 1.0, (int)opt.mesh_nt, (int)opt.mesh_nt);
    return "";
  }
  std::string MeshLayout(const Options &opt) const override
  {
    return "-mesh_nt " + std::to_string(opt.mesh_nt) + " x " + std::to_string(opt.mesh_nt) + " on the unit square";
  }
  LoadPath Path(const Options &opt) const override { return {1.0, opt.driver.dynamics_time, {}, {}}; }
  PetscErrorCode ExternalForce(Model &, double, Vec f) override { return VecZeroEntries(f); }

protected:
  Options opt_;
  // Prescribes du = motion(node) on each boundary node, once.
  template <class Motion>
  void PrescribeBoundary(Model &m, Motion motion)
  {
    std::vector<char> done(m.mesh.num_nodes, 0);
    for (const auto &set : BoundarySets())
      for (PetscInt n : m.mesh.node_sets[set]) {
        if (done[n]) continue;
        done[n] = 1;
        double d[2];
        motion(n, d);
        m.system.Prescribe(n, 0, d[0]);
        m.system.Prescribe(n, 1, d[1]);
      }
  }
};

} // namespace tf
