// What app/run_case.cpp shares with the run's time loop. The loop
// (app/run_simulation.hpp) is the program's longest compilation: it is
// compiled once per dimension, each in its own translation unit
// (app/run_case_dimension.cpp.in), so that the three build side by side,
// and the helpers below once, in app/run_case.cpp.
#pragma once
#include <spdlog/spdlog.h>

#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "app/run_case.hpp"
#include "engine/stable_time_step.hpp"
#include "engine/state_records.hpp"

namespace flowmpm::run_internal {

// The run and the description ("flowmpm check") of a case of dimension D,
// for its shape function; instantiated in app/run_case_dimension.cpp.in.
template <int D>
RunSummary run_case_in(const Case& c, const RunOptions& options);
template <int D>
void describe_case_in(const Case& c);

// The git commit the program was built from, "" where unknown.
const char* source_commit();

// The particle fields a system stores, for the log.
std::string stored_fields(int dimension, bool heat, bool solvent);

// With transport: both time-step limits and which one governs, for the log.
std::string time_step_limits(const TimeStepLimit& limits);

// The run's logger: with `console`, the program's console output at the
// level the default logger has (through a sink of its own that filters at
// that level), and with `file`, every info line in that file (run.log),
// which a restart appends to and a fresh run `truncate`s.
std::shared_ptr<spdlog::logger> run_logger(const std::optional<std::filesystem::path>& file, bool console,
                                           bool truncate);

// " --set KEY=VALUE ..." for the case's overrides.
std::string overrides_text(const Case& c);

// The command that continues a run from its checkpoint.
std::string restart_command(const Case& c);

// The checkpoint in the case's output directory, if it is one of this case;
// throws CaseError naming the file and why not.
StateRecords checkpoint_of(const Case& c);

}  // namespace flowmpm::run_internal
