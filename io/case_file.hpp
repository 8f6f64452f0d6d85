// A case file (TOML) read into typed, validated structs. Nothing downstream
// looks up a string: the run is built from this Case alone. Units are SI
// throughout (m, s, kg, Pa). See README.md "Case files" for every key.
#pragma once
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "discretisation/system_spec.hpp"
#include "verification/reference.hpp"

namespace flowmpm {

struct OutputSpec {
  std::filesystem::path directory;
  std::int64_t every = 0;           // steps between output steps (0: about 20 over the run)
  std::vector<std::string> fields;  // names of output fields to write (engine/snapshot.hpp)
};

struct Case {
  std::string name;
  std::filesystem::path file;
  SystemSpec system;                      // what the discrete system is built from
  std::string scheme = "usl";             // a name of scheme_names()
  std::string velocity_update = "flip";   // "flip", "pic" or "blend" (system.flip_fraction)
  double dt = 0.0;             // s; with dt_auto, the first step's
  bool dt_auto = false;        // dt = cfl h_min / (c_max + |v|_max), every step
  double cfl = 0.5;            // with dt_auto
  std::int64_t steps = 0;      // 0 with dt_auto: run until end_time
  double end_time = 0.0;       // s
  // Blow-up guard: a particle faster than guard_speed_factor times the
  // fastest wave speed, or a non-finite value, stops the run; the state is
  // kept every guard_every steps (0: never) so that the last good one can
  // be written.
  double guard_speed_factor = 10.0;
  std::int64_t guard_every = 10;
  OutputSpec output;
  std::optional<Reference> reference;
};

// Reads and validates a case. `overrides` are "dotted.key=VALUE" strings
// (VALUE in TOML syntax) applied before validation, as from --set.
// Throws CaseError with a message naming file, line, key and what was
// expected.
Case read_case(const std::filesystem::path& file, const std::vector<std::string>& overrides = {});

}  // namespace flowmpm
