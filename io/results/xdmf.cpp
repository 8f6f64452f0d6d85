#include "io/results/xdmf.hpp"

#include <algorithm>
#include <stdexcept>
#include <string_view>

#include "io/results/atomic_file.hpp"
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

// A reference to one dataset of an HDF5 file.
std::string data_item(const std::string& h5_path, const std::string& dimensions,
                      const char* number_type, int precision) {
  return "<DataItem Format=\"HDF\" Dimensions=\"" + dimensions + "\" NumberType=\"" +
         number_type + "\" Precision=\"" + std::to_string(precision) + "\">" + h5_path +
         "</DataItem>";
}

// XDMF's attribute type for a field of `components` per particle. Tensors
// are "Matrix": the six values as stored, xx yy zz xy yz xz, which is the
// order under which ParaView labels a 6-component array (XX YY ZZ XY YZ XZ)
// in both its readers. "Tensor6" would not do: the legacy reader expands it
// to 9 components numbered 0-8 (checked with pvpython; tests/pv_check.py).
const char* attribute_type(int components) {
  return components == 1 ? "Scalar" : components == 3 ? "Vector" : "Matrix";
}

}  // namespace

void xdmf_document(const std::string& h5_name, const ResultsH5& results, const TextSink& sink) {
  const std::vector<OutputField>& fields = results.fields();
  if (!results.written().empty() &&
      std::ranges::none_of(fields, [](const OutputField& f) { return std::string_view(f.name) == "position"; }))
    throw std::invalid_argument("XDMF needs the position field: it is the grid's geometry");
  const std::string file = xml_escape(h5_name);

  sink(
      "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n"
      "<Xdmf Version=\"3.0\">\n"
      "  <Domain>\n"
      "    <Grid Name=\"particles\" GridType=\"Collection\" CollectionType=\"Temporal\">\n");
  std::string out;  // one step's grid at a time
  for (const ResultsH5::WrittenStep& step : results.written()) {
    out.clear();
    const std::string step_file = xml_escape(ResultsH5::step_file(step.step));
    const std::string count = std::to_string(step.count);
    const auto dimensions = [&](int components) {
      return components == 1 ? count : count + " " + std::to_string(components);
    };
    out += "      <Grid Name=\"step_" + ResultsH5::step_label(step.step) + "\" GridType=\"Uniform\">\n";
    out += "        <Time Value=\"" + exact_text(step.time) + "\"/>\n";
    // One vertex per particle. ParaView's default (Xdmf3) reader makes cells
    // only from a connectivity array: the first `count` entries of the
    // shared /particle_index, through a HyperSlab (start 0, stride 1).
    out += "        <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"" + count +
           "\" NodesPerElement=\"1\">\n";
    out += "          <DataItem ItemType=\"HyperSlab\" Dimensions=\"" + count + "\">\n";
    out += "            <DataItem Dimensions=\"3 1\" Format=\"XML\">0 1 " + count + "</DataItem>\n";
    out += "            " +
           data_item(file + ":" + ResultsH5::particle_index, std::to_string(results.index_length()), "Int", 4) +
           "\n";
    out += "          </DataItem>\n";
    out += "        </Topology>\n";
    out += "        <Geometry GeometryType=\"XYZ\">\n";
    out += "          " + data_item(step_file + ":/position", dimensions(3), "Float", 8) +
           "\n";
    out += "        </Geometry>\n";
    for (const OutputField& f : fields) {
      if (std::string_view(f.name) == "position") continue;
      out += "        <Attribute Name=\"" + std::string(f.name) + "\" AttributeType=\"" +
             attribute_type(f.components) + "\" Center=\"Node\">\n";
      out += "          " +
             data_item(step_file + ":/" + f.name, dimensions(f.components), f.integer ? "Int" : "Float",
                       f.integer ? 4 : 8) +
             "\n";
      out += "        </Attribute>\n";
    }
    out += "      </Grid>\n";
    sink(out);
  }
  sink(
      "    </Grid>\n"
      "  </Domain>\n"
      "</Xdmf>\n");
}

std::string xdmf_document(const std::string& h5_name, const ResultsH5& results) {
  std::string text;
  xdmf_document(h5_name, results, [&](std::string_view piece) { text += piece; });
  return text;
}

void write_xdmf(const std::filesystem::path& path, const std::string& h5_name,
                const ResultsH5& results) {
  write_file_atomically(path, [&](const TextSink& sink) { xdmf_document(h5_name, results, sink); });
}

}  // namespace flowmpm
