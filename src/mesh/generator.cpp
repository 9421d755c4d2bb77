#include "tubeform/mesh/generator.hpp"

#include <cmath>

namespace tf {

SerialMesh GenerateQuarterAnnulus(double ro, double t, int nt, int ntheta)
{
  SerialMesh m;
  const double ri = ro - t;
  const auto id = [nt](int i, int j) { return i + (nt + 1) * j; };
  m.xy.resize(2 * (nt + 1) * (ntheta + 1));
  for (int j = 0; j <= ntheta; ++j) {
    const double th = 0.5 * M_PI * j / ntheta;
    // Exact end values keep symmetry-plane nodes exactly on the axes.
    const double c = (j == ntheta) ? 0.0 : std::cos(th), s = (j == 0) ? 0.0 : std::sin(th);
    for (int i = 0; i <= nt; ++i) {
      const double r = ri + t * i / nt;
      m.xy[2 * id(i, j)] = r * c;
      m.xy[2 * id(i, j) + 1] = r * s;
    }
  }
  for (int j = 0; j < ntheta; ++j)
    for (int i = 0; i < nt; ++i)
      m.quads.insert(m.quads.end(), {id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
  for (int j = 0; j < ntheta; ++j) {
    m.edge_sets["inner"].push_back({id(0, j), id(0, j + 1)});
    m.edge_sets["outer"].push_back({id(nt, j), id(nt, j + 1)});
  }
  for (int i = 0; i < nt; ++i) {
    m.edge_sets["y0"].push_back({id(i, 0), id(i + 1, 0)});
    m.edge_sets["x0"].push_back({id(i, ntheta), id(i + 1, ntheta)});
  }
  return m;
}

SerialMesh GenerateHalfAnnulus(double ro, double t, int nt, int ntheta)
{
  // The quarter and its mirror image below the x axis, node for node: the half model of a symmetric case
  // sees exactly mirrored coordinates.
  const SerialMesh q = GenerateQuarterAnnulus(ro, t, nt, ntheta);
  SerialMesh m;
  const auto id = [nt](int i, int j) { return i + (nt + 1) * j; }; // j = 0 .. 2 ntheta from -90 to 90 degrees
  m.xy.resize(2 * (nt + 1) * (2 * ntheta + 1));
  for (int j = 0; j <= 2 * ntheta; ++j) {
    const int jq = j < ntheta ? ntheta - j : j - ntheta;
    for (int i = 0; i <= nt; ++i) {
      m.xy[2 * id(i, j)] = q.xy[2 * id(i, jq)];
      m.xy[2 * id(i, j) + 1] = j < ntheta ? -q.xy[2 * id(i, jq) + 1] : q.xy[2 * id(i, jq) + 1];
    }
  }
  for (int j = 0; j < 2 * ntheta; ++j)
    for (int i = 0; i < nt; ++i)
      m.quads.insert(m.quads.end(), {id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
  for (int j = 0; j < 2 * ntheta; ++j) {
    m.edge_sets["inner"].push_back({id(0, j), id(0, j + 1)});
    m.edge_sets["outer"].push_back({id(nt, j), id(nt, j + 1)});
  }
  for (int i = 0; i < nt; ++i) {
    m.edge_sets["x0"].push_back({id(i, 0), id(i + 1, 0)});
    m.edge_sets["x0"].push_back({id(i, 2 * ntheta), id(i + 1, 2 * ntheta)});
  }
  return m;
}

SerialMesh GenerateFullAnnulus(double ro, double t, int nt, int ntheta)
{
  // The half and its mirror image left of the y axis, node for node: j = 0 .. 4 ntheta - 1 from -90 degrees
  // counter-clockwise, the last ring of cells closing on the first ring of nodes.
  const SerialMesh h = GenerateHalfAnnulus(ro, t, nt, ntheta);
  SerialMesh m;
  const int around = 4 * ntheta;
  const auto id = [nt, around](int i, int j) { return i + (nt + 1) * (j % around); };
  m.xy.resize(2 * (nt + 1) * around);
  for (int j = 0; j < around; ++j) {
    const int jh = j <= 2 * ntheta ? j : around - j; // the left half mirrors the right: x -> -x
    for (int i = 0; i <= nt; ++i) {
      m.xy[2 * id(i, j)] = j <= 2 * ntheta ? h.xy[2 * id(i, jh)] : -h.xy[2 * id(i, jh)];
      m.xy[2 * id(i, j) + 1] = h.xy[2 * id(i, jh) + 1];
    }
  }
  for (int j = 0; j < around; ++j)
    for (int i = 0; i < nt; ++i)
      m.quads.insert(m.quads.end(), {id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
  for (int j = 0; j < around; ++j) {
    m.edge_sets["inner"].push_back({id(0, j), id(0, j + 1)});
    m.edge_sets["outer"].push_back({id(nt, j), id(nt, j + 1)});
  }
  return m;
}

SerialMesh GenerateRectangle(double lx, double ly, int nx, int ny)
{
  SerialMesh m;
  const auto id = [nx](int i, int j) { return i + (nx + 1) * j; };
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) m.xy.insert(m.xy.end(), {lx * i / nx, ly * j / ny});
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      m.quads.insert(m.quads.end(), {id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
  for (int i = 0; i < nx; ++i) {
    m.edge_sets["bottom"].push_back({id(i, 0), id(i + 1, 0)});
    m.edge_sets["top"].push_back({id(i, ny), id(i + 1, ny)});
  }
  for (int j = 0; j < ny; ++j) {
    m.edge_sets["left"].push_back({id(0, j), id(0, j + 1)});
    m.edge_sets["right"].push_back({id(nx, j), id(nx, j + 1)});
  }
  return m;
}

} // namespace tf
