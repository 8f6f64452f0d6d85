#include "io/results/timeseries_csv.hpp"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <stdexcept>

#include "core/number_text.hpp"
#include "core/voigt.hpp"
#include "io/results/atomic_file.hpp"
#include "io/results/csv_text.hpp"

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

std::string header_of(const std::vector<std::string>& body_names, const std::vector<std::string>& reactions,
                      const std::vector<std::string>& error_names, const TensorComponentNames& components) {
  std::string header =
      "step,time,kinetic_energy,stored_energy,dissipated_energy,gravity_work,boundary_work,expansion_work,load_work,"
      "energy_balance_error";
  for (const std::string& name : body_names)
    for (const char* quantity : {".stress_", ".strain_"})
      for (const char* component : components)
        header += "," + csv_field(name + quantity + component);
  for (const std::string& name : reactions) header += "," + csv_field(name);
  for (const std::string& name : error_names) header += "," + csv_field("error." + name);
  return header + '\n';
}

}  // namespace

std::string TimeseriesCsv::kept_text(const std::filesystem::path& path, const std::vector<std::string>& body_names,
                                     const std::vector<std::string>& reactions,
                                     const std::vector<std::string>& error_names, const Continuation& from,
                                     const TensorComponentNames& components) {
  const auto lacks = [&](const std::string& what) {
    throw std::runtime_error(path.string() + ": " + what + ", so the run cannot continue from the checkpoint");
  };
  std::ifstream in(path, std::ios::binary);
  if (!in.is_open()) lacks("not found");
  const std::string header = header_of(body_names, reactions, error_names, components);
  std::string line;
  if (!std::getline(in, line) || line + '\n' != header) lacks("its header is not the one this case writes");
  std::string kept = header;
  std::size_t rows = 0;
  std::int64_t last = -1;
  // Whole rows only (a row cut short has no newline and comes last).
  while (std::getline(in, line) && !in.eof()) {
    const std::int64_t step = std::strtoll(line.c_str(), nullptr, 10);
    if (step > from.last_step) break;
    kept += line + '\n';
    ++rows;
    last = step;
  }
  if (rows != from.keep || (rows > 0 && last != from.last_step)) {
    lacks("holds " + std::to_string(rows) + " rows up to step " + std::to_string(from.last_step) + ", not the " +
          std::to_string(from.keep) + " the checkpoint was written after");
  }
  return kept;
}

TimeseriesCsv::TimeseriesCsv(const std::filesystem::path& path, const std::vector<std::string>& body_names,
                             const std::vector<std::string>& reactions, const std::vector<std::string>& error_names,
                             const Continuation& from, const TensorComponentNames& components)
    : body_count_(body_names.size()),
      reaction_count_(reactions.size()),
      error_count_(error_names.size()),
      path_(path.string()) {
  write_file_atomically(path, kept_text(path, body_names, reactions, error_names, from, components));
  errno = 0;
  out_.open(path, std::ios::out | std::ios::app);
  if (!out_) fail("cannot open", path_);
}

std::vector<std::string> reaction_names(const Diagnostics& row) {
  std::vector<std::string> names;
  for (const Reaction& r : row.reactions) names.push_back(r.column());
  return names;
}

TimeseriesCsv::TimeseriesCsv(const std::filesystem::path& path, const std::vector<std::string>& body_names,
                             const std::vector<std::string>& reactions, const std::vector<std::string>& error_names,
                             const TensorComponentNames& components)
    : body_count_(body_names.size()),
      reaction_count_(reactions.size()),
      error_count_(error_names.size()),
      path_(path.string()) {
  errno = 0;
  out_.open(path, std::ios::out | std::ios::trunc);
  if (!out_) fail("cannot open", path_);
  const std::string header = header_of(body_names, reactions, error_names, components);
  errno = 0;
  if (!out_.write(header.data(), static_cast<std::streamsize>(header.size())).flush())
    fail("cannot write", path_);
}

void TimeseriesCsv::write(const Diagnostics& row, double balance_error, const std::vector<double>& errors) {
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
  for (const double value : {row.time, row.kinetic_energy, row.stored_energy, row.dissipated_energy,
                             row.work.gravity, row.work.boundary, row.work.expansion, row.work.load, balance_error})
    add(value);
  for (const BodyMeans& body : row.bodies)
    for (const auto* values : {&body.stress, &body.strain})
      for (const double value : *values) add(value);
  for (const Reaction& r : row.reactions) add(r.value);
  for (const double value : errors) add(value);
  line += '\n';
  errno = 0;
  if (!out_.write(line.data(), static_cast<std::streamsize>(line.size())).flush())
    fail("cannot write", path_);
}

}  // namespace flowmpm
