// The helpers of a run that app/run_case.cpp and its services share
// (app/run_case_internal.hpp).
#include <spdlog/sinks/basic_file_sink.h>
#include <spdlog/sinks/dist_sink.h>

#include <algorithm>

#include "app/run_case_internal.hpp"
#include "core/errors.hpp"
#include "io/results/checkpoint_file.hpp"

#include "flowmpm_build_info.hpp"

namespace flowmpm::run_internal {

const char* source_commit() { return FLOWMPM_COMMIT; }

std::shared_ptr<spdlog::logger> run_logger(const std::optional<std::filesystem::path>& file, bool console,
                                           bool truncate) {
  const auto& program = spdlog::default_logger();
  std::vector<spdlog::sink_ptr> sinks;
  if (console) {
    sinks.push_back(std::make_shared<spdlog::sinks::dist_sink_mt>(program->sinks()));
    sinks.back()->set_level(program->level());
  }
  if (file) {
    try {
      sinks.push_back(std::make_shared<spdlog::sinks::basic_file_sink_mt>(file->string(), truncate));
    } catch (const spdlog::spdlog_ex& e) {
      throw std::runtime_error("cannot write " + file->string() + ": " + e.what());
    }
    sinks.back()->set_level(spdlog::level::info);
  }
  auto log = std::make_shared<spdlog::logger>("run", sinks.begin(), sinks.end());
  log->set_level(std::min(program->level(), spdlog::level::info));
  log->set_pattern("[%H:%M:%S.%e] %^%l%$ %v");
  log->flush_on(spdlog::level::info);
  return log;
}

namespace {
// "name" from FILE --set KEY=VALUE ..., for messages about a checkpoint's case.
std::string case_text(const std::string& name, const std::string& file, const std::string& overrides) {
  return "'" + name + "' from " + file + overrides;
}
}  // namespace

std::string overrides_text(const Case& c) {
  std::string text;
  for (const std::string& o : c.overrides) text += " --set " + o;
  return text;
}

std::string restart_command(const Case& c) {
  return "flowmpm run " + c.file.string() + overrides_text(c) + " --restart " + c.output.directory.string();
}

StateRecords checkpoint_of(const Case& c) {
  const auto path = c.output.directory / checkpoint_file_name;
  if (!std::filesystem::is_regular_file(path)) {
    throw CaseError(c.output.directory.string() + ": no checkpoint to restart from (no " + checkpoint_file_name +
                    " there; a run writes one every output.checkpoint_every steps and when it is interrupted)");
  }
  StateRecords records = read_checkpoint(path);
  std::string digest, name, file, overrides;
  try {
    const StateReader read(records);
    read("case.digest", digest);
    read("case.name", name);
    read("case.file", file);
    read("case.overrides", overrides);
  } catch (const std::runtime_error& e) {
    throw CaseError(path.string() + ": not a checkpoint of a flowmpm run (" + e.what() + ")");
  }
  if (digest != c.digest) {
    throw CaseError(path.string() + ": a checkpoint of another case: it was written for " +
                    case_text(name, file, overrides) + " (digest " + digest + "), this is " +
                    case_text(c.name, c.file.string(), overrides_text(c)) + " (digest " + c.digest +
                    "); restart with the case file and --set options it was written for, or run without --restart");
  }
  return records;
}

}  // namespace flowmpm::run_internal
