// Structured mesh of the quarter annulus x >= 0, y >= 0.
#pragma once

#include "tubeform/mesh/serial_mesh.hpp"

namespace tf {

// nt elements through the wall, ntheta around the quarter. Node (i, j), with i
// the radial index from the inner surface and j the angular index from the
// x axis, has id i + (nt + 1) j. Cells are counter-clockwise. Boundary sets:
// inner (r = ro - t), outer (r = ro), y0 (theta = 0), x0 (theta = 90 deg).
SerialMesh GenerateQuarterAnnulus(double ro, double t, int nt, int ntheta);
// The half annulus x >= 0: the quarter's nodes and their mirror images below
// the x axis (2 ntheta elements around, from -90 to 90 degrees); sets inner,
// outer, and x0 (both ends, on x = 0).
SerialMesh GenerateHalfAnnulus(double ro, double t, int nt, int ntheta);
// The whole annulus: the half's nodes and their mirror images left of the y
// axis (4 ntheta elements around, from -90 degrees counter-clockwise); sets
// inner and outer only.
SerialMesh GenerateFullAnnulus(double ro, double t, int nt, int ntheta);

// A rectangle [0, lx] x [0, ly] of nx x ny cells with sets
// "left", "right", "bottom", "top" (used by block scenes and tests).
SerialMesh GenerateRectangle(double lx, double ly, int nx, int ny);

} // namespace tf
