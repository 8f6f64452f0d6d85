// Runs the cases of a sweep in-process, several side by side, and writes
// <output>/sweep.csv. Each case runs in <output>/cases/<id> and leaves a
// sweep_row.txt there; running the sweep again skips the cases already
// completed with the same base case and overrides. A shard runs only its
// share of the cases (a scheduler's job array runs the shards) and
// collect_sweep builds sweep.csv from the cases' folders afterwards. See
// docs/guide/sweeps.md and docs/guide/cluster.md.
#pragma once
#include <atomic>
#include <memory>

#include <spdlog/spdlog.h>

#include "app/sweep_table.hpp"
#include "io/case/sweep_file.hpp"

namespace flowmpm {

struct SweepOptions {
  int jobs = 1;     // cases run at once
  int threads = 1;  // threads in all; each case gets max(1, threads / jobs)
  SweepShard shard;  // the cases to run; a shard other than the whole writes no sweep.csv
  // Set from a signal handler: the running cases stop after their current
  // step and are left to run again; no new case starts.
  const std::atomic<bool>* interrupt = nullptr;
};

// Runs every case of the shard not already completed. The sweep logs its
// progress at the level the default logger has; each case logs to its
// run.log only. A failed case is recorded and the others go on. Throws
// std::runtime_error if sweep.csv or a sweep_row.txt cannot be written.
SweepSummary run_sweep(const Sweep& sweep, const SweepOptions& options);

// Builds sweep.csv from the rows in cases/*/sweep_row.txt that belong to
// this sweep (the same base case and overrides), completed or failed, and
// logs the cases that have none (missing) or failed. Runs nothing.
SweepSummary collect_sweep(const Sweep& sweep);

// The sweep's own logger ("sweep"), at the level the default logger has.
std::shared_ptr<spdlog::logger> sweep_logger();

}  // namespace flowmpm
