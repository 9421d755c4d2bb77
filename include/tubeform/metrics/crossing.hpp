// Where the body's surface crosses itself: the tube's wall meeting itself, which the solver does not model as
// contact (docs/theory.md, "Contact and friction"). The driver stops the run there.
#pragma once

#include <petscsys.h>

#include <string>
#include <vector>

#include "tubeform/core/core.hpp"
#include "tubeform/mesh/mesh.hpp"

namespace tf {

// A straight edge of the surface: its end points and their input node numbers.
struct SurfaceEdge {
  Vec2 a{}, b{};
  long na = -1, nb = -1;
};

// Two edges that cross: where, and their end nodes (input numbers).
struct SelfCrossing {
  bool found = false;
  Vec2 at{};
  long nodes[4] = {-1, -1, -1, -1};
};

// Pure: a pair of edges sharing no node whose interiors cross (each edge's ends strictly on either side of the
// other's line: edges that only touch or lie on one line do not count), the one of the lowest node numbers; none
// if the surface does not cross itself. Edges sorted by their least x, each compared with those whose x ranges
// overlap its own.
SelfCrossing FindSelfCrossing(std::vector<SurfaceEdge> edges);

// Collective: the edges of the edge sets `sets` (each edge once: it bounds one local cell) at the coordinates x
// (2 per local node), gathered on every rank, and FindSelfCrossing of them (the same answer on every rank).
PetscErrorCode SurfaceSelfCrossing(const Mesh &mesh, const std::vector<double> &x, const std::vector<std::string> &sets,
                                   SelfCrossing &c);

} // namespace tf
