// Runs the cases of a sweep in-process, several side by side, and writes
// <output>/sweep.csv. Each case runs in <output>/cases/<id> and leaves a
// sweep_row.txt there; running the sweep again skips the cases already
// completed with the same base case and overrides. See README.md
// "Parameter sweeps".
#pragma once
#include <atomic>
#include <cstddef>

#include "io/sweep_file.hpp"

namespace flowmpm {

struct SweepOptions {
  int jobs = 1;     // cases run at once
  int threads = 1;  // threads in all; each case gets max(1, threads / jobs)
  // Set from a signal handler: the running cases stop after their current
  // step and are left to run again; no new case starts.
  const std::atomic<bool>* interrupt = nullptr;
};

struct SweepSummary {
  std::size_t completed = 0;  // including the skipped ones
  std::size_t failed = 0;
  std::size_t skipped = 0;    // completed by an earlier run of the sweep
  bool interrupted = false;
};

// Runs every case not already completed. The sweep logs its progress at
// the level the default logger has; each case logs to its run.log only. A failed case is recorded in sweep.csv and the
// others go on. Throws std::runtime_error if sweep.csv or a sweep_row.txt
// cannot be written.
SweepSummary run_sweep(const Sweep& sweep, const SweepOptions& options);

}  // namespace flowmpm
