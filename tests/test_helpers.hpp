// Shared by the tests: reading shipped cases and writing scratch ones.
#pragma once
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "app/run_case.hpp"
#include "engine/schemes.hpp"
#include "engine/simulation.hpp"
#include "io/case/case_file.hpp"

namespace flowmpm::testing {

inline std::filesystem::path config(const std::string& relative) {
  return std::filesystem::path(FLOWMPM_SOURCE_DIR) / "configs" / relative;
}

// Writes `text` to a case file in a scratch directory and reads it.
inline Case case_from_text(const std::string& name, const std::string& text,
                           const std::vector<std::string>& overrides = {}) {
  const auto dir = std::filesystem::temp_directory_path() / "flowmpm-tests";
  std::filesystem::create_directories(dir);
  const auto file = dir / (name + ".toml");
  std::ofstream(file) << text;
  return read_case(file, overrides);
}

// Runs a case in this process; results are written only if `write`.
inline RunSummary run(const Case& c, bool write = false) {
  RunOptions options;
  options.write_results = write;
  return run_case(c, options);
}

// Runs a case that should fail: the SimulationError's message, empty if
// the run completed.
inline std::string run_failure(const Case& c) {
  try {
    run(c);
  } catch (const SimulationError& e) {
    return e.what();
  }
  return "";
}

// The simulation of a case, as run_case builds it, to step by hand.
template <int D, class Shape>
Simulation<D, Shape> simulation(const Case& c, std::function<void(Stage)> observer = {}) {
  return Simulation<D, Shape>(c.system, c.scheme->wiring, c.time_step.fixed_dt(), std::move(observer));
}

// A run's timeseries.csv: its header (as written, and split at the commas)
// and its rows, each split; both empty where the file cannot be read.
struct Timeseries {
  std::string header_line;
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
};

inline Timeseries read_timeseries(const std::filesystem::path& file) {
  auto split = [](const std::string& text) {
    std::vector<std::string> cells;
    std::istringstream s(text);
    for (std::string cell; std::getline(s, cell, ',');) cells.push_back(cell);
    return cells;
  };
  Timeseries t;
  std::ifstream in(file);
  if (!std::getline(in, t.header_line)) return t;
  t.header = split(t.header_line);
  for (std::string line; std::getline(in, line);) t.rows.push_back(split(line));
  return t;
}

}  // namespace flowmpm::testing
