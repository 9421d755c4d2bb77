#include "tubeform/mesh/gmsh_reader.hpp"

#include <algorithm>
#include <climits>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <unordered_map>

namespace tf {

namespace {

struct Reader {
  std::ifstream in;
  std::string path;
  std::string error;
  size_t max_count = 0; // no count in the file can exceed its size in bytes (each item takes some)

  bool fail(const std::string &why)
  {
    if (error.empty()) error = "mesh file '" + path + "': " + why;
    return false;
  }
  // Advances to the line "$<name>"; false at end of file.
  bool seek(const std::string &name)
  {
    std::string line;
    while (std::getline(in, line)) {
      while (!line.empty() && (line.back() == '\r' || line.back() == ' ')) line.pop_back();
      if (line == "$" + name) return true;
    }
    return false;
  }
  // A count of `what` in `section`: a whole number from 0 to what the file's size can hold. Counts
  // steer loops and allocations, so a negative, unreadable or absurd one stops the reading.
  bool count(std::istream &s, size_t &n, const char *section, const char *what)
  {
    long long v = -1;
    if (!(s >> v)) return fail(std::string("truncated ") + section + " section (no number of " + what + ")");
    if (v < 0 || static_cast<unsigned long long>(v) > max_count)
      return fail(std::string(section) + ": number of " + what + " " + std::to_string(v) +
                  " is negative or larger than the file can hold");
    n = static_cast<size_t>(v);
    return true;
  }
  // An integer field (a tag, a dimension, a type) within the range of int.
  bool integer(std::istream &s, int &v, const char *section)
  {
    long long x = 0;
    if (!(s >> x)) return fail(std::string("truncated ") + section + " section");
    if (x < INT_MIN || x > INT_MAX)
      return fail(std::string(section) + ": number " + std::to_string(x) + " out of range");
    v = static_cast<int>(x);
    return true;
  }
};

// Reads the $PhysicalNames (names of the physical curves, dimension 1) and the
// $Entities section (the physical tags each curve carries).
bool ReadEntities(Reader &r, std::unordered_map<int, std::string> &curve_names,
                  std::unordered_map<int, std::vector<int>> &curve_physicals)
{
  r.in.clear();
  r.in.seekg(0);
  if (r.seek("PhysicalNames")) {
    size_t n = 0;
    if (!r.count(r.in, n, "$PhysicalNames", "names")) return false;
    for (size_t k = 0; k < n; ++k) {
      int dim, tag;
      std::string name;
      if (!r.integer(r.in, dim, "$PhysicalNames") || !r.integer(r.in, tag, "$PhysicalNames")) return false;
      std::getline(r.in, name);
      const auto a = name.find('"'), b = name.rfind('"');
      if (a == std::string::npos || b <= a) return r.fail("malformed $PhysicalNames entry");
      name = name.substr(a + 1, b - a - 1);
      if (std::any_of(name.begin(), name.end(), [](char c) { return static_cast<unsigned char>(c) < ' '; }))
        return r.fail("$PhysicalNames: a name holds a control character");
      if (dim == 1) curve_names[tag] = name;
    }
  }
  r.in.clear();
  r.in.seekg(0);
  if (!r.seek("Entities")) return r.fail("no $Entities section");
  size_t np, nc, ns, nv;
  const char *what = "$Entities";
  if (!r.count(r.in, np, what, "points") || !r.count(r.in, nc, what, "curves") ||
      !r.count(r.in, ns, what, "surfaces") || !r.count(r.in, nv, what, "volumes"))
    return false;
  std::string line;
  std::getline(r.in, line);
  for (size_t k = 0; k < np && r.in; ++k) std::getline(r.in, line);
  for (size_t k = 0; k < nc && r.in; ++k) {
    std::getline(r.in, line);
    std::istringstream ls(line);
    int tag;
    double box[6];
    size_t nphys;
    if (!r.integer(ls, tag, what)) return false;
    for (double &b : box)
      if (!(ls >> b)) return r.fail("truncated curve " + std::to_string(tag) + " in the $Entities section");
    if (!r.count(ls, nphys, what, "physical tags of a curve")) return false;
    for (size_t q = 0; q < nphys; ++q) {
      int ph;
      if (!r.integer(ls, ph, what)) return false;
      curve_physicals[tag].push_back(ph == INT_MIN ? INT_MAX : std::abs(ph));
    }
  }
  if (!r.in) return r.fail("truncated $Entities section");
  return true;
}

// Reads the $Nodes section into mesh.xy, renumbered 0..n-1 in file order.
bool ReadNodes(Reader &r, SerialMesh &mesh, std::unordered_map<long long, int> &node_index)
{
  if (!r.seek("Nodes")) return r.fail("no $Nodes section");
  const char *what = "$Nodes";
  size_t nblocks, nnodes;
  long long mintag, maxtag;
  if (!r.count(r.in, nblocks, what, "blocks") || !r.count(r.in, nnodes, what, "nodes")) return false;
  if (!(r.in >> mintag >> maxtag)) return r.fail("truncated $Nodes section");
  mesh.xy.clear();
  mesh.xy.reserve(2 * nnodes);
  for (size_t b = 0; b < nblocks; ++b) {
    int edim, etag, parametric;
    size_t n;
    if (!r.integer(r.in, edim, what) || !r.integer(r.in, etag, what) || !r.integer(r.in, parametric, what) ||
        !r.count(r.in, n, what, "nodes in a block"))
      return false;
    if (parametric) return r.fail("parametric node blocks are not supported");
    std::vector<long long> tags(n);
    for (auto &t : tags)
      if (!(r.in >> t)) return r.fail("truncated $Nodes section");
    for (size_t k = 0; k < n; ++k) {
      double x, y, z;
      if (!(r.in >> x >> y >> z)) return r.fail("truncated $Nodes section");
      if (mesh.xy.size() / 2 >= static_cast<size_t>(INT_MAX)) return r.fail("too many nodes");
      node_index[tags[k]] = static_cast<int>(mesh.xy.size() / 2);
      mesh.xy.push_back(x);
      mesh.xy.push_back(y);
    }
  }
  return true;
}

// The $MeshFormat line: only 4.1 ASCII is accepted.
bool ReadFormat(Reader &r)
{
  if (!r.seek("MeshFormat")) {
    r.error = "mesh file '" + r.path + "' is not a Gmsh mesh (no $MeshFormat)";
    return false;
  }
  double version = 0;
  int filetype = -1, datasize = 0;
  if (!(r.in >> version >> filetype >> datasize)) return r.fail("unreadable $MeshFormat line");
  if (!(version >= 4.09 && version <= 4.11) || filetype != 0)
    return r.fail("only Gmsh format 4.1 ASCII is supported (re-export with 'gmsh -format msh41 -save')");
  return true;
}

// What the $Elements section refers to: the node numbers (ReadNodes) and the physical curves (ReadEntities).
struct ElementContext {
  const std::unordered_map<long long, int> &node_index;
  const std::unordered_map<int, std::string> &curve_names;
  const std::unordered_map<int, std::vector<int>> &curve_physicals;
};

// One block of the $Elements section: quads become cells, lines in named physical curves become edges,
// triangles are counted into `triangles`.
bool ReadElementBlock(Reader &r, const ElementContext &ctx, SerialMesh &mesh, size_t &triangles)
{
  const char *what = "$Elements";
  int edim, etag, etype;
  size_t n;
  if (!r.integer(r.in, edim, what) || !r.integer(r.in, etag, what) || !r.integer(r.in, etype, what) ||
      !r.count(r.in, n, what, "elements in a block"))
    return false;
  const int nper = etype == 1 ? 2 : etype == 2 ? 3 : etype == 3 ? 4 : etype == 15 ? 1 : -1;
  if (nper < 0)
    return r.fail("element type " + std::to_string(etype) +
                  " is not supported (use 4-node quads, 'Recombine' in the .geo)");
  for (size_t k = 0; k < n; ++k) {
    long long tag;
    if (!(r.in >> tag)) return r.fail("truncated $Elements section");
    int ids[4];
    for (int q = 0; q < nper; ++q) {
      long long nt;
      if (!(r.in >> nt)) return r.fail("truncated $Elements section");
      auto it = ctx.node_index.find(nt);
      if (it == ctx.node_index.end())
        return r.fail("element " + std::to_string(tag) + " refers to unknown node " + std::to_string(nt));
      ids[q] = it->second;
    }
    if (etype == 3)
      mesh.quads.insert(mesh.quads.end(), ids, ids + 4);
    else if (etype == 2 && edim == 2)
      ++triangles;
    else if (etype == 1) {
      auto ph = ctx.curve_physicals.find(etag);
      if (ph == ctx.curve_physicals.end()) continue;
      for (int p : ph->second) {
        auto nm = ctx.curve_names.find(p);
        const std::string name = nm != ctx.curve_names.end() ? nm->second : std::to_string(p);
        mesh.edge_sets[name].push_back({ids[0], ids[1]});
      }
    }
  }
  return true;
}

// The $Elements section into mesh.quads and mesh.edge_sets; a mesh with triangles is refused.
bool ReadElements(Reader &r, const ElementContext &ctx, SerialMesh &mesh)
{
  if (!r.seek("Elements")) return r.fail("no $Elements section");
  const char *what = "$Elements";
  size_t nblocks, nelem;
  long long mintag, maxtag;
  if (!r.count(r.in, nblocks, what, "blocks") || !r.count(r.in, nelem, what, "elements")) return false;
  if (!(r.in >> mintag >> maxtag)) return r.fail("truncated $Elements section");
  mesh.quads.clear();
  mesh.edge_sets.clear();
  size_t triangles = 0;
  for (size_t b = 0; b < nblocks; ++b)
    if (!ReadElementBlock(r, ctx, mesh, triangles)) return false;
  if (triangles) {
    r.error = "mesh file '" + r.path + "' has " + std::to_string(triangles) +
              " triangles: only quadrilateral meshes are supported (add 'Recombine Surface' to the .geo)";
    return false;
  }
  return true;
}

// Keeps only the nodes the cells use (geometry points may carry nodes of their own), renumbered in the
// order the cells first use them.
bool KeepCellNodes(Reader &r, SerialMesh &mesh)
{
  std::vector<int> renum(mesh.num_nodes(), -1);
  std::vector<double> xy;
  for (int &id : mesh.quads) {
    if (renum[id] < 0) {
      renum[id] = static_cast<int>(xy.size() / 2);
      xy.push_back(mesh.xy[2 * id]);
      xy.push_back(mesh.xy[2 * id + 1]);
    }
    id = renum[id];
  }
  for (auto &set : mesh.edge_sets)
    for (auto &e : set.second) {
      if (renum[e[0]] < 0 || renum[e[1]] < 0)
        return r.fail("boundary set '" + set.first + "' has an edge not on any quadrilateral");
      e = {renum[e[0]], renum[e[1]]};
    }
  mesh.xy.swap(xy);
  return true;
}

} // namespace

std::string ReadGmsh(const std::string &path, SerialMesh &mesh)
{
  Reader r;
  r.path = path;
  r.in.open(path);
  if (!r.in) return "mesh file '" + path + "' cannot be opened (missing or unreadable)";
  r.in.seekg(0, std::ios::end);
  const std::streamoff bytes = r.in.tellg();
  r.max_count = bytes > 0 ? static_cast<size_t>(bytes) : 0;
  r.in.seekg(0);

  // The format; physical names of dimension 1 (curves); which physical tags each curve carries; the nodes; the
  // elements; the nodes the cells use.
  std::unordered_map<int, std::string> curve_names;
  std::unordered_map<int, std::vector<int>> curve_physicals;
  std::unordered_map<long long, int> node_index;
  if (!ReadFormat(r) || !ReadEntities(r, curve_names, curve_physicals) || !ReadNodes(r, mesh, node_index) ||
      !ReadElements(r, {node_index, curve_names, curve_physicals}, mesh) || !KeepCellNodes(r, mesh))
    return r.error;

  // Gmsh may write cells clockwise: re-order so that every area is positive.
  for (int c = 0; c < mesh.num_cells(); ++c)
    if (mesh.cell_area(c) < 0.0) std::swap(mesh.quads[4 * c + 1], mesh.quads[4 * c + 3]);
  return "";
}

} // namespace tf
