#include "io/timeseries_csv.hpp"

#include <cerrno>
#include <cstring>
#include <stdexcept>

#include "core/number_text.hpp"
#include "core/voigt.hpp"
#include "io/csv_text.hpp"

namespace flowmpm {
namespace {

// errno is cleared before each stream operation, so it names the cause only
// when the operation set it.
[[noreturn]] void fail(const char* what, const std::string& path) {
  const int error = errno;
  std::string message = std::string(what) + " " + path;
  if (error != 0) message += std::string(": ") + std::strerror(error);
  throw std::runtime_error(message);
}

}  // namespace

std::vector<std::string> reaction_names(const Diagnostics& row) {
  std::vector<std::string> names;
  for (const Reaction& r : row.reactions) names.push_back(r.node_set + "." + "xyz"[r.axis]);
  return names;
}

TimeseriesCsv::TimeseriesCsv(const std::filesystem::path& path, const std::vector<std::string>& body_names,
                             const std::vector<std::string>& reactions, const std::vector<std::string>& error_names)
    : body_count_(body_names.size()),
      reaction_count_(reactions.size()),
      error_count_(error_names.size()),
      path_(path.string()) {
  errno = 0;
  out_.open(path, std::ios::out | std::ios::trunc);
  if (!out_) fail("cannot open", path_);
  std::string header = "step,time,kinetic_energy,strain_energy";
  for (const std::string& name : body_names)
    for (const char* quantity : {".stress_", ".strain_"})
      for (const char* component : voigt_component_names)
        header += "," + csv_field(name + quantity + component);
  for (const std::string& name : reactions) header += "," + csv_field("reaction." + name);
  for (const std::string& name : error_names) header += "," + csv_field("error." + name);
  header += '\n';
  errno = 0;
  if (!out_.write(header.data(), static_cast<std::streamsize>(header.size())).flush())
    fail("cannot write", path_);
}

void TimeseriesCsv::write(const Diagnostics& row, const std::vector<double>& errors) {
  if (row.bodies.size() != body_count_)
    throw std::invalid_argument("timeseries row for " + path_ + " has " +
                                std::to_string(row.bodies.size()) + " bodies, expected " +
                                std::to_string(body_count_));
  if (row.reactions.size() != reaction_count_)
    throw std::invalid_argument("timeseries row for " + path_ + " has " + std::to_string(row.reactions.size()) +
                                " reactions, expected " + std::to_string(reaction_count_));
  if (errors.size() != error_count_)
    throw std::invalid_argument("timeseries row for " + path_ + " has " + std::to_string(errors.size()) +
                                " error norms, expected " + std::to_string(error_count_));
  std::string line = std::to_string(row.step);
  const auto add = [&line](double value) {
    line += ',';
    append_exact(line, value);
  };
  for (const double value : {row.time, row.kinetic_energy, row.strain_energy}) add(value);
  for (const BodyMeans& body : row.bodies)
    for (const auto* values : {&body.stress, &body.strain})
      for (const double value : *values) add(value);
  for (const Reaction& r : row.reactions) add(r.force);
  for (const double value : errors) add(value);
  line += '\n';
  errno = 0;
  if (!out_.write(line.data(), static_cast<std::streamsize>(line.size())).flush())
    fail("cannot write", path_);
}

}  // namespace flowmpm
