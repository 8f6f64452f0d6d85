// A case file (TOML) read into typed, validated structs. Nothing downstream
// looks up a string: the run is built from this Case alone. Units are SI
// throughout (m, s, kg, Pa). See docs/reference/README.md for every key.
#pragma once
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "discretisation/system_spec.hpp"
#include "engine/schemes.hpp"
#include "engine/time_step.hpp"
#include "verification/reference.hpp"

namespace flowmpm {

struct OutputSpec {
  std::filesystem::path directory;
  std::int64_t every = 0;           // steps between output steps (0: about 20 over the run)
  std::vector<std::string> fields;  // names of output fields to write (engine/snapshot.hpp)
  std::int64_t checkpoint_every = 0;  // steps between checkpoints (0: only when interrupted)
};

struct Case {
  std::string name;
  std::filesystem::path file;
  std::vector<std::string> overrides;  // the --set KEY=VALUE it was read with
  // Of the file's text and the overrides (io/case/digest.hpp): a checkpoint
  // continues only the case that wrote it.
  std::string digest;
  SystemSpec system;             // what the discrete system is built from
  const Scheme* scheme = nullptr;  // one of schemes()
  // The time step's choice as read (analysis.dt, cfl, steps, end_time) and
  // its owner, which checked it against the scene's limits.
  TimeControl time_control;
  TimeStep time_step;
  // Blow-up guard: a kinetic energy above guard_energy_factor times the
  // initial energy plus the work done on the bodies (checked every step), a
  // particle faster than guard_speed_factor times the fastest wave speed, or
  // a non-finite value, stops the run; the state is kept every guard_every
  // steps (0: never) so that the last good one can be written.
  double guard_energy_factor = 2.0;
  double guard_speed_factor = 10.0;
  std::int64_t guard_every = 10;
  OutputSpec output;
  std::optional<Reference> reference;
};

// Sets a case's time step past the reader (the tests' cases beyond the
// limit): its owner is rebuilt for `control` (a fixed step's end_time
// follows from its steps) and the first step's dt set; its problem() is not
// checked.
void set_time_control(Case& c, TimeControl control);

// Reads and validates a case. `overrides` are "dotted.key=VALUE" strings
// (VALUE in TOML syntax) applied before validation, as from --set.
// Throws CaseError with a message naming file, line, key and what was
// expected.
Case read_case(const std::filesystem::path& file, const std::vector<std::string>& overrides = {});

}  // namespace flowmpm
