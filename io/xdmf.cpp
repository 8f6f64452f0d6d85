#include "io/xdmf.hpp"

#include <algorithm>
#include <stdexcept>
#include <string_view>

#include "io/atomic_file.hpp"
#include "core/number_text.hpp"

namespace flowmpm {
namespace {

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

// XDMF's attribute type for a field of `components` per particle. Tensors
// are "Matrix": the six values as stored, in our Voigt order. XDMF's
// "Tensor6" means xx xy xz yy yz zz, and ParaView's legacy reader builds a
// wrong 3 x 3 tensor from our order (checked with pvpython).
const char* attribute_type(int components) {
  return components == 1 ? "Scalar" : components == 3 ? "Vector" : "Matrix";
}

}  // namespace

std::string xdmf_document(const std::string& h5_name, const ResultsH5& results) {
  const std::vector<OutputField>& fields = results.fields();
  if (!results.written().empty() &&
      std::ranges::none_of(fields, [](const OutputField& f) { return std::string_view(f.name) == "position"; }))
    throw std::invalid_argument("XDMF needs the position field: it is the grid's geometry");
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
    out += "        <Time Value=\"" + exact_text(step.time) + "\"/>\n";
    out += "        <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"" + count +
           "\" NodesPerElement=\"1\"/>\n";
    out += "        <Geometry GeometryType=\"XYZ\">\n";
    out += "          " + data_item(file + ":" + group + "/position", dimensions(3), "Float", 8) +
           "\n";
    out += "        </Geometry>\n";
    for (const OutputField& f : fields) {
      if (std::string_view(f.name) == "position") continue;
      out += "        <Attribute Name=\"" + std::string(f.name) + "\" AttributeType=\"" +
             attribute_type(f.components) + "\" Center=\"Node\">\n";
      out += "          " +
             data_item(file + ":" + group + "/" + f.name, dimensions(f.components), f.integer ? "Int" : "Float",
                       f.integer ? 4 : 8) +
             "\n";
      out += "        </Attribute>\n";
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
