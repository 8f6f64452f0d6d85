// Runs a case from start to end: the time loop, output steps, progress and
// the summary. The one entry point the program, the tests and the bench use.
#pragma once
#include <atomic>
#include <exception>
#include <filesystem>
#include <optional>
#include <string>

#include "io/case/case_file.hpp"
#include "io/results/summary_json.hpp"

namespace flowmpm {

// Whether a run continues from the checkpoint in its output directory
// (docs/guide/checkpoint_restart.md).
enum class Restart {
  no,               // start afresh, replacing an earlier run's checkpoint
  from_checkpoint,  // continue from it; CaseError if there is none or it does not fit
  if_checkpoint,    // continue from it if it fits, else start afresh (a sweep's case)
};

struct RunOptions {
  int threads = 1;                // the threads the run reports (set by the caller)
  bool write_results = true;      // results.h5, results.xdmf, timeseries.csv, summary.json
  double progress_seconds = 5.0;  // seconds between progress lines
  double setup_seconds = 0.0;     // time spent before run_case (reading the case)
  // Log to the program's console as well as to run.log (a sweep's cases
  // log to their run.log only).
  bool log_to_console = true;
  // Set from a signal handler to stop the run after the current step; the
  // run then writes a checkpoint (with write_results).
  const std::atomic<bool>* interrupt = nullptr;
  Restart restart = Restart::no;
};

// Runs the case, logging to the console and, with write_results, to
// run.log in the output directory. Throws SimulationError (after logging it
// and writing the summary with a failed status) if the solution breaks down
// or the run is interrupted, CaseError for what only the built system can
// tell about the case and for a checkpoint it cannot restart from (nothing
// is then written).
RunSummary run_case(const Case& c, const RunOptions& options);

// Logs the model a case builds, without running it ("flowmpm check").
void describe_case(const Case& c);

// A failure in one line: what() or, for std::bad_alloc, "out of memory".
std::string failure_text(const std::exception& e);

}  // namespace flowmpm
