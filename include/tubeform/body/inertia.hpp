// Inertia of the body as a regularization of the incremental problem
// (docs/theory.md, "Inertia"): row-sum lumped masses per cell (initial
// configuration: mass is conserved), node velocities and accelerations, and
// backward Euler in time,
//   (K + M / dt^2) du = dF + M (a0 + v0 / dt),  v = du / dt,  a = (v - v0) / dt.
#pragma once

#include <petscvec.h>

#include <vector>

#include "tubeform/assembly/system.hpp"
#include "tubeform/body/body.hpp"

namespace tf {

class Inertia {
public:
  Inertia() = default;
  Inertia(const Inertia &) = delete;
  Inertia &operator=(const Inertia &) = delete;
  ~Inertia() { (void)VecDestroy(&mass_global_); }

  // The masses of the body's cells for density rho; `active`: inertia enters
  // the increments from the start (else only once Activate is called).
  PetscErrorCode Setup(const Body &body, double rho, bool active);
  bool active() const { return active_; }
  void Activate() { active_ = true; }

  // M / dt^2 on the diagonal of the system (after the body's tangent).
  PetscErrorCode AddMass(System &system, double dt) const;
  // The backward-Euler load M (a0 + v0 / dt) of a step dt into the system.
  void AddLoad(System &system, double dt) const;
  // Collective: new velocity and acceleration after the increment du over dt.
  // Returns the work of the inertia forces over it (trapezoidal, like the
  // external work). Before Activate (-dynamics auto) only the velocity of the
  // quasi-static path is kept (the motion inertia starts from).
  PetscErrorCode Advance(Vec du, double dt, double &dw_inertia);
  // Adds M a (per-cell contributions, global frame) to a local force vector.
  PetscErrorCode AddForce(Vec f_local) const;
  // Collective: kinetic energy 1/2 v.M.v.
  PetscErrorCode KineticEnergy(double &w) const;
  // Collective: writes or reads the motion (velocities, accelerations, active).
  PetscErrorCode Persist(Archive &ar)
  {
    PetscFunctionBeginUser;
    ar.Group("/inertia");
    PetscCall(ar.Value("active", active_));
    PetscCall(ar.NodeData("v", v_, 2));
    PetscCall(ar.NodeData("a", a_, 2));
    PetscFunctionReturn(PETSC_SUCCESS);
  }

private:
  const Body *body_ = nullptr;
  bool active_ = false;
  std::vector<double> mass_;  // kNodes per local cell
  Vec mass_global_ = nullptr; // lumped mass per dof (both dofs of a node), summed over the ranks
  std::vector<double> v_, a_; // 2 per local node, global frame

  // Calls f(node, m) for every node of every local cell with the cell's
  // lumped mass share: contributions that sum to M over the ranks.
  template <class F>
  void ForEachMassShare(F &&f) const
  {
    const Mesh &mesh = body_->mesh();
    for (PetscInt e = 0; e < mesh.num_cells; ++e)
      for (int a = 0; a < fe::kNodes; ++a) f(mesh.cell_nodes[fe::kNodes * e + a], mass_[fe::kNodes * e + a]);
  }
};

} // namespace tf
