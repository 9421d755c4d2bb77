// Pure kernels of the incompatible-modes quadrilateral QM6 (no PETSc): the Q4
// displacement plus internal modes u_int = sum_k alpha_k P_k with
// P = (1 - xi^2, 1 - eta^2) on each component (Wilson et al. 1973), with the
// correction of Taylor, Beresford & Wilson (1976): the mode gradients use the
// centre Jacobian, dP/dx = (det J0 / det J) J0^{-T} dP/dxi, so their cell
// integral vanishes and constant-strain patches are exact on distorted cells.
// The 4 internal dofs are condensed per element; they are ordered
// alpha = (x-mode xi, x-mode eta, y-mode xi, y-mode eta), i.e. alpha[2 c + m]
// is component c (0 = x, 1 = y) of mode m (0: 1 - xi^2, 1: 1 - eta^2).
// Voigt order, dof order and Gauss points are those of quad.hpp.
//
// mean_dilatation (-element qm6bar): the volumetric strain at the Gauss points
// is replaced by its cell mean (Hughes 1980, as -element bbar), B-bar over the
// 12 dofs: rows xx, yy, zz get (mean(grad P_s) - grad P_s) / 3. The modes'
// cell mean gradient is zero (Taylor's correction), so they carry deviatoric
// strain only and the pressure is constant per cell. QM6 bends without shear
// locking but its pressure varies inside the cell, which stiffens it in
// near-isochoric plastic flow on coarse meshes; measured on the squaring,
// qm6bar is as close to the converged end-of-stroke load as bbar or closer
// (docs/notes/converging-to-calculix.md).
#pragma once

#include <array>

#include "tubeform/fe/midpoint.hpp"
#include "tubeform/fe/quad.hpp"

namespace tf::fe {

constexpr int kInternal = 4;
// Kii is taken as singular when a pivot falls below this fraction of its
// largest entry (a degenerate cell: the modes cannot be condensed).
constexpr double kPivotTol = 1e-13;

// cond = -Kii^{-1} Kic (4 x 8): internal dofs of an increment, alpha = cond * du.
using Condensation = std::array<std::array<double, kDofs>, kInternal>;
using InternalVec = std::array<double, kInternal>;
using ModeMatrix = std::array<std::array<double, kInternal>, kInternal>;

// K* = Kcc - Kci Kii^{-1} Kic from the 12-dof K = sum_g w det J [ B12^T (C_g - Q(sigma_g)) B12
// + (grad P_s . sigma_g . grad P_t) I over the 6 shape functions (4 nodal + 2 modes) ].
// `geometric` = false drops Q and the initial-stress term. Returns false if
// det J <= 0 at a Gauss point (inverted cell) or Kii is singular.
bool QM6Stiffness(const double xe[2 * kNodes], const Mat4 tangent[kGauss], const Voigt sigma[kGauss], bool geometric,
                  ElemMat &ke, Condensation &cond, bool mean_dilatation = false);

// deps = B12 [du; alpha] (zz = 0) and omega = (L_xy - L_yx) / 2 at Gauss point g,
// L_ij = d(du_i)/dx_j including the modes, gradients on the configuration xe
// (e.g. the mid-increment one). Returns false for an inverted cell.
bool QM6Kinematics(const double xe[2 * kNodes], int g, const ElemVec &du, const InternalVec &alpha, Voigt &deps,
                   double &omega, bool mean_dilatation = false);

// f* = f_c + cond^T f_i with f_c = sum_g w det J B_c^T sigma_g and f_i the same
// over the modes (f_i = 0 for a uniform stress). Returns false for an inverted cell.
bool QM6InternalForce(const double xe[2 * kNodes], const Voigt sigma[kGauss], const Condensation &cond, ElemVec &f,
                      bool mean_dilatation = false);

// The same three on a cell whose geometry geo = ComputeGeometry(xe) is known
// (not inverted): the callers that keep it compute it once per configuration.
// QM6Stiffness still returns false for a singular Kii.
bool QM6Stiffness(const double xe[2 * kNodes], const QuadGeometry &geo, const Mat4 tangent[kGauss],
                  const Voigt sigma[kGauss], bool geometric, ElemMat &ke, Condensation &cond,
                  bool mean_dilatation = false);
void QM6Kinematics(const double xe[2 * kNodes], const QuadGeometry &geo, int g, const ElemVec &du,
                   const InternalVec &alpha, Voigt &deps, double &omega, bool mean_dilatation = false);
// The stiffness that also returns Kii^{-1} (the modes' own stiffness, for
// balancing them: alpha -= Kii^{-1} f_i).
bool QM6Stiffness(const double xe[2 * kNodes], const QuadGeometry &geo, const Mat4 tangent[kGauss],
                  const Voigt sigma[kGauss], bool geometric, ElemMat &ke, Condensation &cond, ModeMatrix *kii_inv,
                  bool mean_dilatation = false);
// The tangent of the equilibrium corrections at an iterate with midpoint
// kinematics (midpoint.hpp): rows as QM6Stiffness's on the configuration of
// `rows` (the forces'), columns those of the mid-increment strain
// (NodeStrainColumns, ModeStrainColumns), condensed; nothing is stored (the
// forces keep their own condensation). False if Kii is singular.
bool QM6Stiffness(const QuadGeometry &rows, const Mat4 tangent[kGauss], const Voigt sigma[kGauss],
                  const MidpointColumns &m, ElemMat &ke, bool mean_dilatation = false);
// f_i = sum_g w det J G_g^T sigma_g: the force on the internal modes (zero when they are in balance).
void QM6ModeForce(const double xe[2 * kNodes], const QuadGeometry &geo, const Voigt sigma[kGauss], InternalVec &fi,
                  bool mean_dilatation = false);
void QM6InternalForce(const double xe[2 * kNodes], const QuadGeometry &geo, const Voigt sigma[kGauss],
                      const Condensation &cond, ElemVec &f, bool mean_dilatation = false);

} // namespace tf::fe
