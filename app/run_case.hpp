// Runs a case from start to end: the time loop, output steps, progress and
// the summary. The one entry point the program, the tests and the bench use.
#pragma once
#include <atomic>
#include <filesystem>
#include <optional>

#include "io/case_file.hpp"
#include "io/summary_json.hpp"

namespace flowmpm {

struct RunOptions {
  int threads = 1;                // the threads the run reports (set by the caller)
  bool write_results = true;      // results.h5, results.xdmf, timeseries.csv, summary.json
  double progress_seconds = 5.0;  // seconds between progress lines
  double setup_seconds = 0.0;     // time spent before run_case (reading the case)
  // Set from a signal handler to stop the run after the current step.
  const std::atomic<bool>* interrupt = nullptr;
};

// Runs the case. Throws SimulationError (after writing the summary with a
// failed status) if the solution breaks down.
RunSummary run_case(const Case& c, const RunOptions& options);

// Logs the model a case builds, without running it ("flowmpm check").
void describe_case(const Case& c);

}  // namespace flowmpm
