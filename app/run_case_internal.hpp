// What the files of a run share (app/run_case.cpp, its services and its
// log): the source commit, the run's logger, the checkpoint of a case and
// the command that continues it, and the model's description in the log.
#pragma once
#include <spdlog/spdlog.h>

#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "app/run_case.hpp"
#include "engine/simulation_base.hpp"
#include "engine/state_records.hpp"

namespace flowmpm::run_internal {

// The git commit the program was built from, "" where unknown.
const char* source_commit();

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

// Logs the model: grid, bodies, fields stored, node sets, transport, loads,
// damping, memory and the time step (app/log_model.cpp).
void log_model(spdlog::logger& log, const Case& c, const SimulationBase& sim);

}  // namespace flowmpm::run_internal
