// summary.json: what ran, how fast and what came out; written atomically
// (temporary file renamed into place) at the end of a run.
#pragma once
#include <array>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace flowmpm {

struct BodySummary {
  std::string name;
  std::array<double, 6> mean_stress{};  // Pa, Voigt order, tensor shear
  std::array<double, 6> mean_strain{};
};

// Where a run stands; summary.json writes it as "running", "completed",
// "interrupted at step N" or "failed: <message>".
enum class RunStatus { running, completed, interrupted, failed };

struct RunSummary {
  std::string case_name, case_file, scheme, shape_function, velocity_update;
  RunStatus status = RunStatus::completed;
  std::string failure;  // with failed: the message
  int dimension = 3;
  bool axisymmetric = false;  // the bodies' means then named rr zz tt zt rt rz
  int threads = 1;
  std::size_t particles = 0, nodes = 0;
  std::int64_t steps = 0;
  double dt = 0.0, end_time = 0.0;       // s; dt 0 when automatic
  double setup_seconds = 0.0;            // case read, particles generated and sorted
  double step_loop_seconds = 0.0;        // wall time of the step loop, output excluded
  double output_seconds = 0.0;           // wall time spent writing results
  double reference_seconds = 0.0;        // wall time spent measuring errors
  double particle_steps_per_second = 0.0;
  // The energy balance's terms at the end (J; engine/energy_balance.hpp)
  // and its error: the largest change of the balance over the recorded
  // steps relative to the largest energy present (NaN without energy).
  double kinetic_energy = 0.0, stored_energy = 0.0, dissipated_energy = 0.0;
  double gravity_work = 0.0, boundary_work = 0.0, expansion_work = 0.0, load_work = 0.0;
  double energy_error = 0.0;
  // Where energy_error ends above energy_warning_threshold: the warning
  // the log gave, with its likely cause and remedy.
  static constexpr double energy_warning_threshold = 0.10;
  std::optional<std::string> energy_warning;
  // With damping: the energy it removed (J, >= 0; per unit thickness in 2D),
  // part of dissipated_energy (docs/guide/loads.md).
  std::optional<double> damping_dissipated;
  // With contact: the contact's work on the bodies (J; WorkDone::contact).
  std::optional<double> contact_work;
  std::vector<BodySummary> bodies;
  // Error norms against a reference solution, by name (empty without one).
  std::map<std::string, double> errors;
  // What a reference measures without a closed form to compare with
  // (docs/validation/README.md), by name; empty without one.
  std::map<std::string, double> measures;
};

// summary.json's "status".
std::string status_text(const RunSummary& summary);

// The JSON text (pretty-printed, numbers with 17 significant digits,
// non-finite numbers written as null).
std::string summary_json(const RunSummary& summary);

// Writes summary_json(...) to `path` atomically.
void write_summary(const std::filesystem::path& path, const RunSummary& summary);

}  // namespace flowmpm
