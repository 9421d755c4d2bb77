// Unit tests of the pure kernels: shape functions, element matrices, B-bar,
// the elastic law, the mesh generator and the Gmsh reader. No MPI needed.
#include <cstdio>
#include <fstream>
#include <string>

#include "check.hpp"
#include "tubeform/fe/quad.hpp"
#include "tubeform/material/elastic.hpp"
#include "tubeform/mesh/generator.hpp"
#include "tubeform/mesh/gmsh_reader.hpp"

using namespace tf;

static void ShapeFunctionTests()
{
  // Partition of unity and zero-sum derivatives at arbitrary points.
  for (double xi : {-0.7, 0.1, 0.9})
    for (double eta : {-0.3, 0.5}) {
      double n[4], dn[4][2], s = 0, sx = 0, sy = 0;
      fe::ShapeFunctions(xi, eta, n, dn);
      for (int a = 0; a < 4; ++a) s += n[a], sx += dn[a][0], sy += dn[a][1];
      CHECK_NEAR(s, 1.0, 1e-15);
      CHECK_NEAR(sx, 0.0, 1e-15);
      CHECK_NEAR(sy, 0.0, 1e-15);
    }
}

// A distorted cell; gradients of a linear field must be reproduced exactly.
static const double kCell[8] = {0.1, -0.2, 2.3, 0.1, 1.9, 1.7, -0.3, 1.2};

static void GeometryTests()
{
  fe::QuadGeometry geo;
  CHECK(fe::ComputeGeometry(kCell, geo));
  SerialMesh one;
  one.xy.assign(kCell, kCell + 8);
  one.quads = {0, 1, 2, 3};
  CHECK_NEAR(geo.area, one.cell_area(0), 1e-13);
  // Linear field f = 3 x - 2 y: grad f exact at every Gauss point.
  for (int g = 0; g < fe::kGauss; ++g) {
    double gx = 0, gy = 0;
    for (int a = 0; a < 4; ++a) {
      const double f = 3 * kCell[2 * a] - 2 * kCell[2 * a + 1];
      gx += f * geo.dndx[g][a][0], gy += f * geo.dndx[g][a][1];
    }
    CHECK_NEAR(gx, 3.0, 1e-13);
    CHECK_NEAR(gy, -2.0, 1e-13);
  }
  // A clockwise cell is rejected.
  const double cw[8] = {0, 0, 0, 1, 1, 1, 1, 0};
  CHECK(!fe::ComputeGeometry(cw, geo));
}

static void StiffnessTests(fe::Formulation f)
{
  fe::QuadGeometry geo;
  fe::ComputeGeometry(kCell, geo);
  Mat4 c[4];
  Voigt s[4];
  for (auto &m : c) m = IsotropicElasticMatrix(200.0, 0.3);
  // A prestress activates the geometric terms; rigid translations must
  // still produce no force and K must stay symmetric.
  for (auto &v : s) v = {10.0, -4.0, 2.0, 3.0};
  fe::ElemMat k;
  fe::ElementStiffness(geo, f, c, s, true, k);
  double kmax = 0;
  for (int i = 0; i < 8; ++i)
    for (int j = 0; j < 8; ++j) kmax = std::max(kmax, std::fabs(k[i][j]));
  for (int i = 0; i < 8; ++i)
    for (int j = 0; j < 8; ++j) CHECK_NEAR(k[i][j], k[j][i], 1e-12 * kmax);
  for (int comp = 0; comp < 2; ++comp)
    for (int i = 0; i < 8; ++i) {
      double r = 0;
      for (int a = 0; a < 4; ++a) r += k[i][2 * a + comp];
      CHECK_NEAR(r, 0.0, 1e-12 * kmax);
    }
  // Without prestress an infinitesimal rotation is also force free.
  for (auto &v : s) v = {0, 0, 0, 0};
  fe::ElementStiffness(geo, f, c, s, true, k);
  for (int i = 0; i < 8; ++i) {
    double r = 0;
    for (int a = 0; a < 4; ++a) r += k[i][2 * a] * (-kCell[2 * a + 1]) + k[i][2 * a + 1] * kCell[2 * a];
    CHECK_NEAR(r, 0.0, 1e-12 * kmax);
  }
  // Uniform strain: the internal force equals K u and the strain is exact.
  fe::ElemVec du;
  for (int a = 0; a < 4; ++a)
    du[2 * a] = 0.01 * kCell[2 * a] + 0.004 * kCell[2 * a + 1], du[2 * a + 1] = -0.002 * kCell[2 * a + 1];
  for (int g = 0; g < 4; ++g) {
    Voigt de;
    double w;
    fe::IncrementKinematics(geo, g, f, du, de, w);
    CHECK_NEAR(de[0], 0.01, 1e-14);
    CHECK_NEAR(de[1], -0.002, 1e-14);
    CHECK_NEAR(de[2], 0.0, 1e-14);
    CHECK_NEAR(de[3], 0.004, 1e-14);
    CHECK_NEAR(w, 0.002, 1e-14);
  }
}

static void BBarTests()
{
  // B-bar: the volumetric strain is the same at every Gauss point and equals
  // the cell mean of the standard one, for any nodal field.
  fe::QuadGeometry geo;
  fe::ComputeGeometry(kCell, geo);
  const fe::ElemVec du = {0.3, -0.1, 0.7, 0.2, -0.4, 0.9, 0.05, -0.6};
  double mean = 0, vol[4];
  for (int g = 0; g < 4; ++g) {
    Voigt de, ds;
    double w;
    fe::IncrementKinematics(geo, g, fe::Formulation::BBar, du, de, w);
    fe::IncrementKinematics(geo, g, fe::Formulation::Q4, du, ds, w);
    vol[g] = de[0] + de[1] + de[2];
    mean += geo.wdet[g] * (ds[0] + ds[1]) / geo.area;
    // Deviatoric parts agree.
    const double ms = (ds[0] + ds[1] + ds[2]) / 3, mb = vol[g] / 3;
    for (int r = 0; r < 3; ++r) CHECK_NEAR(de[r] - mb, ds[r] - ms, 1e-14);
    CHECK_NEAR(de[3], ds[3], 1e-15);
  }
  for (int g = 0; g < 4; ++g) CHECK_NEAR(vol[g], mean, 1e-14);
}

static void ElasticTests()
{
  // Energy density of D eps equals eps . D eps / 2.
  const Elastic m(75000, 0.34);
  const Voigt eps = {1e-3, -4e-4, 0.0, 6e-4};
  const Mat4 d = IsotropicElasticMatrix(75000, 0.34);
  Voigt s{};
  double w = 0;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) s[r] += d[r][c] * eps[c];
  for (int r = 0; r < 4; ++r) w += 0.5 * s[r] * eps[r];
  CHECK_NEAR(m.ElasticEnergy(s), w, 1e-12 * w);
  // Plane strain uniaxial stress check: E' = E / (1 - nu^2) relates sxx to exx when syy = 0.
  const double e = 75000, nu = 0.34, lam = e * nu / ((1 + nu) * (1 - 2 * nu)), mu = e / (2 * (1 + nu));
  CHECK_NEAR(d[0][0] - d[0][1] * d[1][0] / d[1][1], e / (1 - nu * nu), 1e-9 * e);
  CHECK_NEAR(d[0][1], lam, 1e-9);
  CHECK_NEAR(d[3][3], mu, 1e-9);
  // Jaumann update: a small spin turns a uniaxial stress by the spin angle.
  Voigt sig = {100, 0, 0, 0};
  JaumannUpdate({0, 0, 0, 0}, 0.0, -1e-4, sig);
  CHECK_NEAR(sig[3], 100 * 1e-4, 1e-12); // rotation by +1e-4 rad gives sxy = s theta
}

static void GeneratorTests()
{
  // The polygonal quarter annulus: area = ntheta/2 (ro^2 - ri^2) sin(dtheta).
  const double ro = 17.5, t = 1.5, ri = ro - t;
  for (int nth : {4, 48}) {
    const SerialMesh m = GenerateQuarterAnnulus(ro, t, 3, nth);
    double area = 0;
    for (int c = 0; c < m.num_cells(); ++c) area += m.cell_area(c);
    CHECK_NEAR(area, 0.5 * nth * (ro * ro - ri * ri) * std::sin(0.5 * M_PI / nth), 1e-10);
    CHECK(m.num_nodes() == 4 * (nth + 1));
    CHECK(m.validate({"inner", "outer", "x0", "y0"}).empty());
    CHECK(m.node_set("inner").size() == (size_t)nth + 1);
    CHECK(m.node_set("x0").size() == 4);
    CHECK(m.node_set("y0").size() == 4);
    for (int n : m.node_set("x0")) CHECK(m.xy[2 * n] == 0.0);
    for (int n : m.node_set("y0")) CHECK(m.xy[2 * n + 1] == 0.0);
  }
}

static void GmshTests(const std::string &dir)
{
  SerialMesh m;
  const std::string path = dir + "/meshes/thick_cylinder_4x8.msh";
  CHECK(ReadGmsh(path, m).empty());
  CHECK(m.num_cells() == 32);
  CHECK(m.num_nodes() == 45);
  CHECK(m.validate({"inner", "outer", "x0", "y0"}).empty());
  CHECK(m.node_set("inner").size() == 9);
  CHECK(m.node_set("y0").size() == 5);
  CHECK(m.node_set("outer").size() == 9);
  for (int n : m.node_set("outer")) CHECK_NEAR(std::hypot(m.xy[2 * n], m.xy[2 * n + 1]), 20.0, 1e-12);
  // Bad files give one-line reasons naming the file.
  const std::string missing = ReadGmsh(dir + "/meshes/no_such_file.msh", m);
  CHECK(missing.find("no_such_file.msh") != std::string::npos);
  const std::string tmp = "test_kernels_v2.msh";
  std::ofstream(tmp) << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n";
  const std::string v2 = ReadGmsh(tmp, m);
  CHECK(v2.find("4.1") != std::string::npos);
  std::remove(tmp.c_str());
  std::ofstream(tmp) << "not a mesh\n";
  CHECK(ReadGmsh(tmp, m).find("not a Gmsh mesh") != std::string::npos);
  std::remove(tmp.c_str());
}

int main(int argc, char **argv)
{
  const std::string source_dir = argc > 1 ? argv[1] : ".";
  ShapeFunctionTests();
  GeometryTests();
  StiffnessTests(fe::Formulation::Q4);
  StiffnessTests(fe::Formulation::BBar);
  BBarTests();
  ElasticTests();
  GeneratorTests();
  GmshTests(source_dir);
  return ReportChecks("test_kernels");
}
