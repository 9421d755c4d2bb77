// The linearization of the mid-increment (Hughes-Winget) kinematics at an
// iterate: the columns of the equilibrium corrections' tangent (docs/theory.md,
// 5a). Pure (no PETSc).
//
// The strain and spin of an increment du are those of the velocity gradient on
// the mid configuration x + du/2, L = L_N + L_P: the nodes' part
// L_N = G (I + G/2)^-1 (G = d(du)/dX on the start configuration) and QM6's
// modes' part L_P = sum alpha (x) grad_mid P (mode gradients with the centre's
// Jacobian). A change dc of the nodal increment moves the mid configuration by
// dc/2; with H = grad_mid(dc) at the point and H0 at the cell centre
//     dL = (I - L_N/2) H - L_P H0 / 2 + L_P (tr H0 - tr H) / 2,
// and a change of the modes d alpha gives dL = d alpha (x) grad_mid P. With the
// mean dilatation the cell's volumetric strain is (A1 - A0) / Am, A1, A0, Am
// the cell's areas at the end, start and middle of the increment, and
//     d mean = (dA1 - mean dAm) / Am,   dA1 = grad A(x1) dc,  dAm = grad A(xm) dc / 2
// (grad A the shoelace formula's). The tangent's rows are those of the
// configuration the forces are taken on (ElementStiffness, QM6Stiffness); with
// these columns it is unsymmetric.
#pragma once

#include <array>

#include "tubeform/fe/quad.hpp"

namespace tf::fe {

// A velocity gradient L_ij = d(du_i)/dx_j: {L_xx, L_xy, L_yx, L_yy}.
using Gradient = std::array<double, 4>;

// What the columns of a cell's tangent at an iterate need.
struct MidpointColumns {
  QuadGeometry mid;        // the mid configuration's geometry (grad_mid N_a at the Gauss points)
  double h0[kNodes][2];    // grad_mid N_a at the cell centre
  double a[kGauss][2][2];  // I - L_N/2 at each Gauss point
  double lp[kGauss][2][2]; // L_P at each Gauss point
  double dmean[kDofs];     // d(mean volumetric strain) / d(du): the mean dilatation's columns
};

// From the start corners xs, the nodal increment du and the iterate's mid
// velocity gradients at the Gauss points l[g] (QM6's modes included). False if
// the mid cell is inverted.
bool LinearizeMidpoint(const double xs[2 * kNodes], const ElemVec &du, const Gradient l[kGauss], MidpointColumns &m);

// The Voigt strains (rows) of a unit x and y displacement (columns) at Gauss
// point g: of node a, or of a mode with mid gradient h; with the mean
// dilatation the point's volumetric strain is replaced by the mean's.
void NodeStrainColumns(const MidpointColumns &m, int g, int a, bool mean_dilatation, double col[kVoigt][2]);
void ModeStrainColumns(const double h[2], bool mean_dilatation, double col[kVoigt][2]);

// ElementStiffness (q4, bbar) with these columns: rows on the configuration of
// `rows` (the forces'), columns those of NodeStrainColumns.
void MidpointElementStiffness(const QuadGeometry &rows, Formulation f, const Mat4 tangent[kGauss],
                              const Voigt sigma[kGauss], const MidpointColumns &m, ElemMat &ke);

} // namespace tf::fe
