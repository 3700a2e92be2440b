#include "core/xdmf.hpp"

#include "core/atomic_file.hpp"

#include <regex>
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

// 3 components are a vector to ParaView; tensors are matrices with their own number of
// components, which ParaView shows as multi-component arrays.
const char* attribute_type(int components) {
  return components == 1 ? "Scalar" : components == 3 ? "Vector" : "Matrix";
}

// A 2D vector as the 3-component vector ParaView's glyphs and Calculator expect: its two columns
// (hyperslabs of the (N, 2) dataset) joined with a zero z, JOIN($0, $1, 0 * $0).
void padded_vector(std::ostringstream& out, const std::string& indent, const XdmfSnapshot& snapshot,
                   const XdmfParticleSet& set, const XdmfField& field) {
  out << indent << "<DataItem ItemType=\"Function\" Function=\"JOIN($0, $1, 0 * $0)\" "
      << "Dimensions=\"" << set.count << " 3\">\n";
  for (int column = 0; column < 2; ++column) {
    out << indent << "  <DataItem ItemType=\"HyperSlab\" Dimensions=\"" << set.count
        << " 1\" Type=\"HyperSlab\">\n"
        << indent << "    <DataItem Dimensions=\"3 2\" Format=\"XML\">0 " << column << " 1 1 "
        << set.count << " 1</DataItem>\n";
    data_item(out, indent + "    ", snapshot, set, field);
    out << indent << "  </DataItem>\n";
  }
  out << indent << "</DataItem>\n";
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
        const bool planar_vector = dimension == 2 && field.components == 2;
        out << "          <Attribute Name=\"" << field.name << "\" AttributeType=\""
            << attribute_type(planar_vector ? 3 : field.components) << "\" Center=\"Node\">\n";
        if (planar_vector) {
          padded_vector(out, "            ", snapshot, set, field);
        } else {
          data_item(out, "            ", snapshot, set, field);
        }
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

std::vector<std::string> xdmf_snapshot_files(const std::string& document) {
  // data_item's text: FILE:/particles/SET/FIELD.
  static const std::regex item(">([^<>]+\\.h5):/particles/");
  std::vector<std::string> files;
  for (auto match = std::sregex_iterator(document.begin(), document.end(), item);
       match != std::sregex_iterator(); ++match) {
    const std::string file = (*match)[1].str();
    if (files.empty() || files.back() != file) { // one snapshot's items are together
      files.push_back(file);
    }
  }
  return files;
}

} // namespace revsph
