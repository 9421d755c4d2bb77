#include "tubeform/mesh/gmsh_reader.hpp"

#include <algorithm>
#include <fstream>
#include <sstream>
#include <unordered_map>

namespace tf {

namespace {

struct Reader {
  std::ifstream in;
  std::string path;
  std::string error;

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
};

} // namespace

std::string ReadGmsh(const std::string &path, SerialMesh &mesh)
{
  Reader r;
  r.path = path;
  r.in.open(path);
  if (!r.in) return "mesh file '" + path + "' cannot be opened (missing or unreadable)";

  // Format line: only 4.1 ASCII is accepted.
  if (!r.seek("MeshFormat")) return "mesh file '" + path + "' is not a Gmsh mesh (no $MeshFormat)";
  double version = 0;
  int filetype = -1, datasize = 0;
  if (!(r.in >> version >> filetype >> datasize)) return "mesh file '" + path + "': unreadable $MeshFormat line";
  if (version < 4.09 || version > 4.11 || filetype != 0)
    return "mesh file '" + path +
           "': only Gmsh format 4.1 ASCII is supported (re-export with 'gmsh -format msh41 -save')";

  // Physical names of dimension 1 (curves).
  std::unordered_map<int, std::string> curve_names;
  r.in.clear();
  r.in.seekg(0);
  if (r.seek("PhysicalNames")) {
    int n = 0;
    r.in >> n;
    for (int k = 0; k < n; ++k) {
      int dim, tag;
      std::string name;
      r.in >> dim >> tag;
      std::getline(r.in, name);
      const auto a = name.find('"'), b = name.rfind('"');
      if (a == std::string::npos || b <= a) return "mesh file '" + path + "': malformed $PhysicalNames entry";
      if (dim == 1) curve_names[tag] = name.substr(a + 1, b - a - 1);
    }
  }

  // Entities: which physical tags each curve carries.
  std::unordered_map<int, std::vector<int>> curve_physicals;
  r.in.clear();
  r.in.seekg(0);
  if (!r.seek("Entities")) return "mesh file '" + path + "': no $Entities section";
  {
    size_t np, nc, ns, nv;
    r.in >> np >> nc >> ns >> nv;
    std::string line;
    std::getline(r.in, line);
    for (size_t k = 0; k < np; ++k) std::getline(r.in, line);
    for (size_t k = 0; k < nc; ++k) {
      std::getline(r.in, line);
      std::istringstream ls(line);
      int tag;
      double box[6];
      size_t nphys;
      ls >> tag;
      for (double &b : box) ls >> b;
      ls >> nphys;
      for (size_t q = 0; q < nphys; ++q) {
        int ph;
        ls >> ph;
        curve_physicals[tag].push_back(std::abs(ph));
      }
    }
    if (!r.in) return "mesh file '" + path + "': truncated $Entities section";
  }

  // Nodes, renumbered 0..n-1 in file order.
  std::unordered_map<size_t, int> node_index;
  if (!r.seek("Nodes")) return "mesh file '" + path + "': no $Nodes section";
  {
    size_t nblocks, nnodes, mintag, maxtag;
    r.in >> nblocks >> nnodes >> mintag >> maxtag;
    mesh.xy.clear();
    mesh.xy.reserve(2 * nnodes);
    for (size_t b = 0; b < nblocks; ++b) {
      int edim, etag, parametric;
      size_t n;
      r.in >> edim >> etag >> parametric >> n;
      if (parametric) return "mesh file '" + path + "': parametric node blocks are not supported";
      std::vector<size_t> tags(n);
      for (auto &t : tags) r.in >> t;
      for (size_t k = 0; k < n; ++k) {
        double x, y, z;
        r.in >> x >> y >> z;
        node_index[tags[k]] = static_cast<int>(mesh.xy.size() / 2);
        mesh.xy.push_back(x);
        mesh.xy.push_back(y);
      }
    }
    if (!r.in) return "mesh file '" + path + "': truncated $Nodes section";
  }

  // Elements: quads become cells, lines in named physical curves become edges.
  if (!r.seek("Elements")) return "mesh file '" + path + "': no $Elements section";
  {
    size_t nblocks, nelem, mintag, maxtag;
    r.in >> nblocks >> nelem >> mintag >> maxtag;
    mesh.quads.clear();
    mesh.edge_sets.clear();
    size_t unsupported = 0;
    for (size_t b = 0; b < nblocks; ++b) {
      int edim, etag, etype;
      size_t n;
      r.in >> edim >> etag >> etype >> n;
      const int nper = etype == 1 ? 2 : etype == 2 ? 3 : etype == 3 ? 4 : etype == 15 ? 1 : -1;
      if (nper < 0)
        return "mesh file '" + path + "': element type " + std::to_string(etype) +
               " is not supported (use 4-node quads, 'Recombine' in the .geo)";
      for (size_t k = 0; k < n; ++k) {
        size_t tag;
        r.in >> tag;
        int ids[4];
        for (int q = 0; q < nper; ++q) {
          size_t nt;
          r.in >> nt;
          auto it = node_index.find(nt);
          if (it == node_index.end())
            return "mesh file '" + path + "': element " + std::to_string(tag) + " refers to unknown node " +
                   std::to_string(nt);
          ids[q] = it->second;
        }
        if (etype == 3)
          mesh.quads.insert(mesh.quads.end(), ids, ids + 4);
        else if (etype == 2 && edim == 2)
          ++unsupported;
        else if (etype == 1) {
          auto ph = curve_physicals.find(etag);
          if (ph == curve_physicals.end()) continue;
          for (int p : ph->second) {
            auto nm = curve_names.find(p);
            const std::string name = nm != curve_names.end() ? nm->second : std::to_string(p);
            mesh.edge_sets[name].push_back({ids[0], ids[1]});
          }
        }
      }
    }
    if (!r.in) return "mesh file '" + path + "': truncated $Elements section";
    if (unsupported)
      return "mesh file '" + path + "' has " + std::to_string(unsupported) +
             " triangles: only quadrilateral meshes are supported (add 'Recombine Surface' to the .geo)";
  }

  // Keep only the nodes the cells use (geometry points may carry nodes of their own).
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
        return "mesh file '" + path + "': boundary set '" + set.first + "' has an edge not on any quadrilateral";
      e = {renum[e[0]], renum[e[1]]};
    }
  mesh.xy.swap(xy);

  // Gmsh may write cells clockwise: re-order so that every area is positive.
  for (int c = 0; c < mesh.num_cells(); ++c)
    if (mesh.cell_area(c) < 0.0) std::swap(mesh.quads[4 * c + 1], mesh.quads[4 * c + 3]);
  return "";
}

} // namespace tf
