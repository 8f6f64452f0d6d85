// timeseries.csv: one row per recorded step: time, the energy balance's
// terms (kinetic, stored and dissipated energy, the work of gravity, of the
// constraints and of the expansion strains, all J) and its error (J: the
// change of the balance since the start), for each body the mean stress and
// strain (Voigt order, tensor shear; columns <body>.stress_xx, ..., or in
// axisymmetric analysis <body>.stress_rr, _zz, _tt, _zt, _rt, _rz), the
// reaction of each constrained node set along each constrained axis
// (columns reaction.<set>.<axis>), and the error norms of a reference
// solution so far (columns error.<name>).
// Each row is flushed as it is written, so the file is never cut mid-row.
#pragma once
#include <filesystem>
#include <cstdint>
#include <fstream>
#include <string>
#include <vector>

#include "core/voigt.hpp"
#include "engine/diagnostics.hpp"

namespace flowmpm {

// The column names of `row`'s reactions and contact columns
// ("reaction.<set>.<axis>", "contact.<pair>.normal", ...: Reaction::column).
std::vector<std::string> reaction_names(const Diagnostics& row);

class TimeseriesCsv {
 public:
  // Creates (truncates) the file and writes the header; throws
  // std::runtime_error naming the path.
  // `reactions` names the columns after the bodies' in the order of
  // Diagnostics::reactions (reaction_names()); `components` the stress and
  // strain components in Voigt order (axisymmetric_component_names in
  // axisymmetric analysis).
  TimeseriesCsv(const std::filesystem::path& path, const std::vector<std::string>& body_names,
                const std::vector<std::string>& reactions = {}, const std::vector<std::string>& error_names = {},
                const TensorComponentNames& components = voigt_component_names);
  // Where a run restarted from a checkpoint takes up an existing file: its
  // rows up to step `last_step`, `keep` of them, under the header these
  // columns give. Rows after `last_step` were written after the checkpoint
  // and are dropped.
  struct Continuation {
    std::size_t keep = 0;
    std::int64_t last_step = 0;
  };
  // The header and the rows kept; throws std::runtime_error naming the file
  // and what it lacks when it cannot be continued so. Reads only.
  static std::string kept_text(const std::filesystem::path& path, const std::vector<std::string>& body_names,
                               const std::vector<std::string>& reactions, const std::vector<std::string>& error_names,
                               const Continuation& from,
                               const TensorComponentNames& components = voigt_component_names);
  // Rewrites the file with kept_text(...) (atomically) and appends to it.
  TimeseriesCsv(const std::filesystem::path& path, const std::vector<std::string>& body_names,
                const std::vector<std::string>& reactions, const std::vector<std::string>& error_names,
                const Continuation& from, const TensorComponentNames& components = voigt_component_names);
  // One row: the diagnostics of a step, the energy balance's error (J) and
  // the error norms so far, in the order of the error names.
  void write(const Diagnostics& row, double balance_error, const std::vector<double>& errors = {});

 private:
  std::ofstream out_;
  std::size_t body_count_, reaction_count_, error_count_;
  std::string path_;  // for error messages
};

}  // namespace flowmpm
