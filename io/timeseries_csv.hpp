// timeseries.csv: one row per recorded step: time, kinetic and strain energy,
// for each body the mean stress and strain (Voigt order, tensor shear), and
// the error norms of a reference solution so far (columns error.<name>).
// Each row is flushed as it is written, so the file is never cut mid-row.
#pragma once
#include <array>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace flowmpm {

struct BodyMeans {
  std::array<double, 6> stress{};  // Pa, volume-weighted mean
  std::array<double, 6> strain{};  // -, volume-weighted mean
};

struct TimeseriesRow {
  std::int64_t step = 0;
  double time = 0.0;            // s
  double kinetic_energy = 0.0;  // J
  double strain_energy = 0.0;   // J
  std::vector<BodyMeans> bodies;  // in the order of the body names
  std::vector<double> errors;     // in the order of the error names
};

class TimeseriesCsv {
 public:
  // Creates (truncates) the file and writes the header; throws
  // std::runtime_error naming the path.
  TimeseriesCsv(const std::filesystem::path& path, std::vector<std::string> body_names,
                std::vector<std::string> error_names = {});
  void write(const TimeseriesRow& row);

 private:
  std::ofstream out_;
  std::size_t body_count_, error_count_;
  std::string path_;  // for error messages
};

}  // namespace flowmpm
