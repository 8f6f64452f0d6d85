// The bookkeeping of a sweep run: which cases are still to run, sweep.csv
// (rewritten after every finished case, so that an interrupted sweep
// leaves a valid table) and the progress lines. The same for cases run on
// threads, on MPI ranks or in a scheduler's shard. See
// docs/guide/sweeps.md.
#pragma once
#include <chrono>
#include <cstddef>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include <spdlog/logger.h>

#include "app/sweep_row.hpp"

namespace flowmpm {

// The cases one process takes: those whose number is `index` modulo
// `count` (--shard index/count); all of them when count is 1.
struct SweepShard {
  std::size_t index = 0;
  std::size_t count = 1;
  bool takes(std::size_t i) const { return i % count == index; }
  bool whole() const { return count == 1; }
};

struct SweepSummary {
  std::size_t completed = 0;  // including the skipped ones
  std::size_t failed = 0;
  std::size_t skipped = 0;  // completed by an earlier run of the sweep
  std::size_t missing = 0;  // --collect: cases with no row of this sweep
  bool interrupted = false;
};

// sweep.csv: the rows present, in case order; one column per varied key,
// a `rank` column if any row was run on an MPI rank, and one error column
// per error name of any row.
std::string sweep_csv(const Sweep& sweep, const std::vector<std::optional<SweepRow>>& rows);

class SweepTable {
 public:
  // Reads the rows of the cases `shard` takes from their sweep_row.txt: the
  // completed ones are kept (skipped), the others are to run. Writes nothing.
  SweepTable(const Sweep& sweep, SweepShard shard, std::shared_ptr<spdlog::logger> log);
  SweepTable(const SweepTable&) = delete;
  SweepTable& operator=(const SweepTable&) = delete;

  // The cases to run, in case order.
  const std::vector<std::size_t>& todo() const { return todo_; }

  // Logs what the sweep holds and how the cases to run will run (`how`,
  // e.g. "2 at a time on 1 thread each"), creates cases/ and, for the
  // whole sweep, writes sweep.csv (a shard writes no table: --collect).
  void start(const std::string& how);

  // Case i finished: its row goes into sweep.csv and the progress line; a
  // failed case is logged with its message. Thread-safe.
  void record(std::size_t i, const SweepRow& row);

  // Logs the totals; `interrupted` says whether the run was stopped.
  SweepSummary finish(bool interrupted);

 private:
  const Sweep& sweep_;
  SweepShard shard_;
  std::shared_ptr<spdlog::logger> log_;
  std::size_t taken_ = 0;  // cases the shard takes
  std::vector<std::optional<SweepRow>> rows_;
  std::vector<std::size_t> todo_;
  std::mutex mutex_;  // guards rows_, summary_, ran_, the progress line and sweep.csv
  SweepSummary summary_;
  std::size_t ran_ = 0;
  std::chrono::steady_clock::time_point start_, last_progress_;
};

}  // namespace flowmpm
