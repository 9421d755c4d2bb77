// The ParaView index beside the result file (<output>.xmf, XDMF 2): a temporal
// collection of the field steps. Each step is the body's grid (the initial
// coordinates and the fields: "Warp By Vector" with displacement_u shows the
// deformed shape) and, in a tool scene, one grid per tool: its outline as
// lines at the start, with its motion as displacement_u, so that the same
// warp moves it. A step's time is lambda x the time scale. It is written as
// <name>.xmf.partial and renamed with the results (ResultWriter::Place).
#include <fstream>

#include "tubeform/io/output.hpp"

namespace tf {

bool ResultWriter::WriteXdmf() const
{
  std::string h5 = path_;
  const auto slash = h5.rfind('/');
  if (slash != std::string::npos) h5 = h5.substr(slash + 1);
  std::ofstream x(XdmfPath() + ".partial");
  const PetscInt nv = mesh_->num_global_nodes, nc = mesh_->num_global_cells, nt = (PetscInt)times_.size();
  x << "<?xml version=\"1.0\" ?>\n<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>\n<Xdmf Version=\"2.0\">\n<Domain>\n";
  x << "<Grid Name=\"tubeform\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
  for (PetscInt k = 0; k < nt; ++k) {
    // Step k of the (steps, n[, comps]) dataset `path`.
    const auto hyperslab = [&](const std::string &path, PetscInt n, int comps, PetscInt steps) {
      x << "   <DataItem ItemType=\"HyperSlab\" Dimensions=\"" << n << (comps > 1 ? " " + std::to_string(comps) : "")
        << "\">\n";
      x << "    <DataItem Dimensions=\"3 " << (comps > 1 ? 3 : 2) << "\" Format=\"XML\">" << k << " 0"
        << (comps > 1 ? " 0" : "") << " 1 1" << (comps > 1 ? " 1" : "") << " 1 " << n
        << (comps > 1 ? " " + std::to_string(comps) : "") << "</DataItem>\n";
      x << "    <DataItem Format=\"HDF\" Dimensions=\"" << steps << " " << n
        << (comps > 1 ? " " + std::to_string(comps) : "") << "\">" << h5 << ":" << path
        << "</DataItem>\n   </DataItem>\n";
    };
    if (tools_.empty()) {
      x << " <Grid Name=\"step" << k << "\" GridType=\"Uniform\">\n";
      x << "  <Time Value=\"" << times_[k] * time_scale_ << "\"/>\n";
    } else {
      x << " <Grid Name=\"step" << k << "\" GridType=\"Collection\" CollectionType=\"Spatial\">\n";
      x << "  <Time Value=\"" << times_[k] * time_scale_ << "\"/>\n";
      x << " <Grid Name=\"body\" GridType=\"Uniform\">\n";
    }
    x << "  <Topology TopologyType=\"Quadrilateral\" NumberOfElements=\"" << nc << "\">\n";
    x << "   <DataItem Format=\"HDF\" DataType=\"Int\" Dimensions=\"" << nc << " 4\">" << h5
      << ":/viz/topology/cells</DataItem>\n  </Topology>\n";
    x << "  <Geometry GeometryType=\"XY\">\n";
    x << "   <DataItem Format=\"HDF\" Dimensions=\"" << nv << " 2\">" << h5
      << ":/geometry/vertices</DataItem>\n  </Geometry>\n";
    for (const auto &[name, comps] : node_names_) {
      x << "  <Attribute Name=\"" << name << "\" AttributeType=\"" << (comps == 2 ? "Vector" : "Scalar")
        << "\" Center=\"Node\">\n";
      hyperslab("/vertex_fields/" + name, nv, comps, nt);
      x << "  </Attribute>\n";
    }
    for (const auto &name : cell_names_) {
      x << "  <Attribute Name=\"" << name << "\" AttributeType=\"Scalar\" Center=\"Cell\">\n";
      hyperslab("/cell_fields/" + name + "_c", nc, 1, nt);
      x << "  </Attribute>\n";
    }
    x << " </Grid>\n";
    if (tools_.empty()) continue;
    for (const auto &t : tools_) {
      if (k < t.first || k > t.last) continue; // a pass's dies are shown while they are in place
      x << " <Grid Name=\"" << t.name << "\" GridType=\"Uniform\">\n";
      x << "  <Topology TopologyType=\"Polyline\" NodesPerElement=\"2\" NumberOfElements=\"" << t.lines << "\">\n";
      x << "   <DataItem Format=\"HDF\" DataType=\"Int\" Dimensions=\"" << t.lines << " 2\">" << h5 << ":/tools/"
        << t.name << "/lines</DataItem>\n  </Topology>\n";
      x << "  <Geometry GeometryType=\"XY\">\n";
      x << "   <DataItem Format=\"HDF\" Dimensions=\"" << t.points << " 2\">" << h5 << ":/tools/" << t.name
        << "/vertices</DataItem>\n  </Geometry>\n";
      x << "  <Attribute Name=\"displacement_u\" AttributeType=\"Vector\" Center=\"Node\">\n";
      hyperslab("/tools/" + t.name + "/displacement", (PetscInt)t.points, 2, t.last + 1);
      x << "  </Attribute>\n";
      x << " </Grid>\n";
    }
    x << " </Grid>\n";
  }
  x << "</Grid>\n</Domain>\n</Xdmf>\n";
  x.close();
  return !x.fail();
}

} // namespace tf
