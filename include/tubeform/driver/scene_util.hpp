// Pieces shared by the scenes: loads, supports and measurements of the
// quarter-tube models.
#pragma once

#include <petscvec.h>

#include <string>

#include "tubeform/driver/problem.hpp"

namespace tf {

// Uniform pressure on the edges of a boundary set (current geometry), with its
// follower-load stiffness into the system when stiffness_p != 0.
PetscErrorCode AddEdgePressure(Problem &p, const std::string &set, double pressure, Vec f_local, bool to_system, double stiffness_p = 0);
// u_x = 0 on x = 0, u_y = 0 on y = 0, in each node's frame.
PetscErrorCode QuarterSymmetry(Problem &p);
// C1 = x_max, C2 = y_max of the outer surface and their ratio.
PetscErrorCode OuterExtents(Problem &p, HistoryRow &row);
// The tube mesh of the options: structured or -mesh_file.
std::string TubeMesh(const Options &opt, SerialMesh &mesh);

// Sum over ranks of each rank's element contributions at the nodes of a set
// (owned and ghost: every contribution is counted once), dotted with `dir(n)`.
template <class Dir>
PetscErrorCode SetForce(Problem &p, const std::string &set, Vec f_local, Dir dir, double &total)
{
  const PetscScalar *f;
  double local = 0;
  PetscFunctionBeginUser;
  PetscCall(VecGetArrayRead(f_local, &f));
  for (PetscInt n : p.mesh().node_sets[set]) {
    double d[2];
    dir(n, d);
    local += d[0] * PetscRealPart(f[p.mesh().node_dof[n]]) + d[1] * PetscRealPart(f[p.mesh().node_dof[n] + 1]);
  }
  PetscCall(VecRestoreArrayRead(f_local, &f));
  PetscCall(MPIU_Allreduce(&local, &total, 1, MPIU_REAL, MPIU_SUM, p.comm()));
  PetscFunctionReturn(PETSC_SUCCESS);
}

// Volume-free average over all Gauss points of a function of the point state.
template <class F>
PetscErrorCode PointAverage(Problem &p, F f, double &avg)
{
  double local[2] = {0, 0}, g[2];
  PetscFunctionBeginUser;
  for (const auto &ps : p.state()) local[0] += f(ps), local[1] += 1;
  PetscCall(MPIU_Allreduce(local, g, 2, MPIU_REAL, MPIU_SUM, p.comm()));
  avg = g[0] / g[1];
  PetscFunctionReturn(PETSC_SUCCESS);
}

} // namespace tf
