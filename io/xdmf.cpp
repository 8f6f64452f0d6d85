#include "io/xdmf.hpp"

#include <charconv>
#include <stdexcept>

#include "io/atomic_file.hpp"

namespace flowmpm {
namespace {

// 17 significant digits: every double reads back exactly.
std::string number(double value) {
  char buffer[32];
  const auto result =
      std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::general, 17);
  return std::string(buffer, result.ptr);
}

std::string xml_escape(const std::string& text) {
  std::string out;
  for (const char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      default: out += c;
    }
  }
  return out;
}

// A reference to one dataset of a step group in the HDF5 file.
std::string data_item(const std::string& h5_path, const std::string& dimensions,
                      const char* number_type, int precision) {
  return "<DataItem Format=\"HDF\" Dimensions=\"" + dimensions + "\" NumberType=\"" +
         number_type + "\" Precision=\"" + std::to_string(precision) + "\">" + h5_path +
         "</DataItem>";
}

// One column of an n x 6 dataset as a scalar attribute: an XDMF hyperslab
// (start, stride, count per dimension) of the HDF5 dataset.
std::string column_attribute(const std::string& name, const std::string& h5_path, const std::string& count,
                             int column) {
  return "        <Attribute Name=\"" + name + "\" AttributeType=\"Scalar\" Center=\"Node\">\n"
         "          <DataItem ItemType=\"HyperSlab\" Dimensions=\"" + count + " 1\" Type=\"HyperSlab\">\n"
         "            <DataItem Dimensions=\"3 2\" Format=\"XML\">0 " + std::to_string(column) + " 1 1 " + count +
         " 1</DataItem>\n"
         "            " + data_item(h5_path, count + " 6", "Float", 8) + "\n"
         "          </DataItem>\n"
         "        </Attribute>\n";
}

struct AttributeField {
  bool enabled;
  const char* name;
  const char* attribute_type;
  int components;
  const char* number_type;
  int precision;
};

}  // namespace

std::string xdmf_document(const std::string& h5_name, const ResultsH5& results) {
  const OutputFields& f = results.fields();
  if (!f.position)
    throw std::invalid_argument("XDMF needs the position field: it is the grid's geometry");
  const AttributeField attributes[] = {
      {f.velocity, "velocity", "Vector", 3, "Float", 8},
      {f.stress, "stress", "Tensor6", 6, "Float", 8},
      {f.strain, "strain", "Tensor6", 6, "Float", 8},
      {f.volume, "volume", "Scalar", 1, "Float", 8},
      {f.mass, "mass", "Scalar", 1, "Float", 8},
      {f.material, "material", "Scalar", 1, "Int", 4},
  };
  const std::string file = xml_escape(h5_name);

  std::string out =
      "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n"
      "<Xdmf Version=\"3.0\">\n"
      "  <Domain>\n"
      "    <Grid Name=\"particles\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
  for (const ResultsH5::WrittenStep& step : results.written()) {
    const std::string group = ResultsH5::group_name(step.step);
    const std::string count = std::to_string(step.count);
    const auto dimensions = [&](int components) {
      return components == 1 ? count : count + " " + std::to_string(components);
    };
    out += "      <Grid Name=\"step_" + group.substr(group.rfind('/') + 1) +
           "\" GridType=\"Uniform\">\n";
    out += "        <Time Value=\"" + number(step.time) + "\"/>\n";
    out += "        <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"" + count +
           "\" NodesPerElement=\"1\"/>\n";
    out += "        <Geometry GeometryType=\"XYZ\">\n";
    out += "          " + data_item(file + ":" + group + "/position", dimensions(3), "Float", 8) +
           "\n";
    out += "        </Geometry>\n";
    for (const AttributeField& a : attributes) {
      if (!a.enabled) continue;
      out += "        <Attribute Name=\"" + std::string(a.name) + "\" AttributeType=\"" +
             a.attribute_type + "\" Center=\"Node\">\n";
      out += "          " +
             data_item(file + ":" + group + "/" + a.name, dimensions(a.components), a.number_type,
                       a.precision) +
             "\n";
      out += "        </Attribute>\n";
    }
    // ParaView labels a 6-component array XX YY ZZ XY YZ XZ, not in our
    // Voigt order: each component is also given as a named scalar.
    for (const char* field : {"stress", "strain"}) {
      if (std::string(field) == "stress" ? !f.stress : !f.strain) continue;
      const char* components[] = {"xx", "yy", "zz", "yz", "xz", "xy"};
      for (int k = 0; k < 6; ++k) {
        out += column_attribute(std::string(field) + "_" + components[k], file + ":" + group + "/" + field, count, k);
      }
    }
    out += "      </Grid>\n";
  }
  out +=
      "    </Grid>\n"
      "  </Domain>\n"
      "</Xdmf>\n";
  return out;
}

void write_xdmf(const std::filesystem::path& path, const std::string& h5_name,
                const ResultsH5& results) {
  write_file_atomically(path, xdmf_document(h5_name, results));
}

}  // namespace flowmpm
