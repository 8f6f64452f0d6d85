// timeseries.csv: one row per recorded step: time, kinetic and strain energy,
// for each body the mean stress and strain (Voigt order, tensor shear), the
// reaction of each constrained node set along each constrained axis
// (columns reaction.<set>.<axis>), and the error norms of a reference
// solution so far (columns error.<name>).
// Each row is flushed as it is written, so the file is never cut mid-row.
#pragma once
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "engine/diagnostics.hpp"

namespace flowmpm {

// "<set>.<axis>" for each reaction of `row`.
std::vector<std::string> reaction_names(const Diagnostics& row);

class TimeseriesCsv {
 public:
  // Creates (truncates) the file and writes the header; throws
  // std::runtime_error naming the path.
  // `reactions` names the columns "<set>.<axis>" in the order of
  // Diagnostics::reactions (reaction_names()).
  TimeseriesCsv(const std::filesystem::path& path, const std::vector<std::string>& body_names,
                const std::vector<std::string>& reactions = {}, const std::vector<std::string>& error_names = {});
  // One row: the diagnostics of a step and the error norms so far, in the
  // order of the error names.
  void write(const Diagnostics& row, const std::vector<double>& errors = {});

 private:
  std::ofstream out_;
  std::size_t body_count_, reaction_count_, error_count_;
  std::string path_;  // for error messages
};

}  // namespace flowmpm
