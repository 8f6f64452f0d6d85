#include "io/results/summary_json.hpp"

#include <cmath>

#include "io/results/atomic_file.hpp"
#include "core/number_text.hpp"
#include "core/voigt.hpp"
#include "io/results/quoted_string.hpp"

namespace flowmpm {
namespace {

// 17 significant digits (every double reads back exactly); JSON has no NaN
// or infinity, so those are written as null.
std::string number(double value) { return std::isfinite(value) ? exact_text(value) : "null"; }

// {"xx": ..., "yy": ..., "zz": ..., "yz": ..., "xz": ..., "xy": ...}, or
// with the axisymmetric names (rr zz tt zt rt rz), as timeseries.csv.
std::string voigt(const std::array<double, 6>& values, const TensorComponentNames& names) {
  std::string out = "{";
  for (std::size_t i = 0; i < 6; ++i)
    out += std::string(i == 0 ? "" : ", ") + "\"" + names[i] + "\": " + number(values[i]);
  return out + "}";
}

}  // namespace

std::string status_text(const RunSummary& s) {
  switch (s.status) {
    case RunStatus::running: return "running";
    case RunStatus::completed: return "completed";
    case RunStatus::interrupted: return "interrupted at step " + std::to_string(s.steps);
    case RunStatus::failed: return "failed: " + s.failure;
  }
  return "unknown";
}

std::string summary_json(const RunSummary& s) {
  std::string out = "{\n";
  const auto field = [&out](const char* key, const std::string& value) {
    out += std::string("  \"") + key + "\": " + value + ",\n";
  };
  field("case", quoted_string(s.case_name));
  field("case_file", quoted_string(s.case_file));
  field("status", quoted_string(status_text(s)));
  field("scheme", quoted_string(s.scheme));
  field("shape_function", quoted_string(s.shape_function));
  field("velocity_update", quoted_string(s.velocity_update));
  field("dimension", std::to_string(s.dimension));
  field("threads", std::to_string(s.threads));
  field("particles", std::to_string(s.particles));
  field("nodes", std::to_string(s.nodes));
  field("steps", std::to_string(s.steps));
  field("dt", number(s.dt));
  field("end_time", number(s.end_time));
  field("setup_seconds", number(s.setup_seconds));
  field("step_loop_seconds", number(s.step_loop_seconds));
  field("output_seconds", number(s.output_seconds));
  field("reference_seconds", number(s.reference_seconds));
  field("particle_steps_per_second", number(s.particle_steps_per_second));
  field("kinetic_energy", number(s.kinetic_energy));
  field("stored_energy", number(s.stored_energy));
  field("dissipated_energy", number(s.dissipated_energy));
  field("gravity_work", number(s.gravity_work));
  field("boundary_work", number(s.boundary_work));
  field("expansion_work", number(s.expansion_work));
  field("load_work", number(s.load_work));
  field("energy_error", number(s.energy_error));
  if (s.energy_warning) field("energy_warning", quoted_string(*s.energy_warning));
  if (s.damping_dissipated) field("damping_dissipated", number(*s.damping_dissipated));
  if (s.contact_work) field("contact_work", number(*s.contact_work));

  out += "  \"bodies\": [";
  for (std::size_t i = 0; i < s.bodies.size(); ++i) {
    const BodySummary& body = s.bodies[i];
    out += i == 0 ? "\n" : ",\n";
    out += "    {\n";
    out += "      \"name\": " + quoted_string(body.name) + ",\n";
    const TensorComponentNames& names = tensor_component_names(s.axisymmetric);
    out += "      \"mean_stress\": " + voigt(body.mean_stress, names) + ",\n";
    out += "      \"mean_strain\": " + voigt(body.mean_strain, names) + "\n";
    out += "    }";
  }
  out += s.bodies.empty() ? "],\n" : "\n  ],\n";

  // {"name": value, ...}, one per line.
  const auto object = [&out](const char* key, const std::map<std::string, double>& values) {
    out += std::string("  \"") + key + "\": {";
    bool first = true;
    for (const auto& [name, value] : values) {
      out += first ? "\n" : ",\n";
      out += "    " + quoted_string(name) + ": " + number(value);
      first = false;
    }
    out += values.empty() ? "}" : "\n  }";
  };
  object("errors", s.errors);
  if (!s.measures.empty()) {
    out += ",\n";
    object("measures", s.measures);
  }
  return out + "\n}\n";
}

void write_summary(const std::filesystem::path& path, const RunSummary& summary) {
  write_file_atomically(path, summary_json(summary));
}

}  // namespace flowmpm
