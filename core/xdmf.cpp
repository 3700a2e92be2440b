#include "core/xdmf.hpp"

#include "core/atomic_file.hpp"

#include <sstream>
#include <stdexcept>

namespace revsph {

namespace {

void data_item(std::ostringstream& out, const std::string& indent, const XdmfSnapshot& snapshot,
               const XdmfParticleSet& set, const XdmfField& field) {
  out << indent << "<DataItem Dimensions=\"" << set.count;
  if (field.components > 1) {
    out << " " << field.components;
  }
  out << "\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">" << snapshot.file
      << ":/particles/" << set.name << "/" << field.name << "</DataItem>\n";
}

// 3 components are a vector to ParaView; 2D vectors (and tensors) are kept as matrices with
// their own number of components, which ParaView shows as multi-component arrays.
const char* attribute_type(int components) {
  return components == 1 ? "Scalar" : components == 3 ? "Vector" : "Matrix";
}

} // namespace

std::string xdmf_document(int dimension, const std::vector<XdmfSnapshot>& snapshots) {
  std::ostringstream out;
  out.precision(17);
  out << "<?xml version=\"1.0\" ?>\n"
      << "<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>\n"
      << "<Xdmf Version=\"2.0\">\n"
      << "  <Domain>\n"
      << "    <Grid Name=\"run\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
  for (const XdmfSnapshot& snapshot : snapshots) {
    out << "      <Grid Name=\"step " << snapshot.step
        << "\" GridType=\"Collection\" CollectionType=\"Spatial\">\n"
        << "        <Time Value=\"" << snapshot.time << "\"/>\n";
    for (const XdmfParticleSet& set : snapshot.sets) {
      if (set.count == 0) {
        continue;
      }
      out << "        <Grid Name=\"" << set.name << "\" GridType=\"Uniform\">\n"
          << "          <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"" << set.count
          << "\" NodesPerElement=\"1\"/>\n"
          << "          <Geometry GeometryType=\""
          << (dimension == 1   ? "X_Y_Z"
              : dimension == 2 ? "XY"
                               : "XYZ")
          << "\">\n";
      bool has_position = false;
      for (const XdmfField& field : set.fields) {
        if (field.name == "position") {
          data_item(out, "            ", snapshot, set, field);
          if (dimension == 1) {
            // XDMF has no one-coordinate geometry: y = z = 0 x, as function items of x.
            for (int axis = 1; axis < 3; ++axis) {
              out << "            <DataItem ItemType=\"Function\" Function=\"0 * $0\" "
                  << "Dimensions=\"" << set.count << "\">\n";
              data_item(out, "              ", snapshot, set, field);
              out << "            </DataItem>\n";
            }
          }
          has_position = true;
        }
      }
      if (!has_position) {
        throw std::invalid_argument("XDMF: particle set " + set.name + " has no position");
      }
      out << "          </Geometry>\n";
      for (const XdmfField& field : set.fields) {
        if (field.name == "position") {
          continue;
        }
        out << "          <Attribute Name=\"" << field.name << "\" AttributeType=\""
            << attribute_type(field.components) << "\" Center=\"Node\">\n";
        data_item(out, "            ", snapshot, set, field);
        out << "          </Attribute>\n";
      }
      out << "        </Grid>\n";
    }
    out << "      </Grid>\n";
  }
  out << "    </Grid>\n"
      << "  </Domain>\n"
      << "</Xdmf>\n";
  return out.str();
}

void write_xdmf(const std::filesystem::path& path, int dimension,
                const std::vector<XdmfSnapshot>& snapshots) {
  write_file_atomically(path, xdmf_document(dimension, snapshots));
}

} // namespace revsph
