// One finished case of a sweep: its row of sweep.csv, and the sweep_row.txt
// in its folder that records what it ran and that row. Every way of running
// a sweep (threads, MPI ranks, scheduler shards) runs a case through
// run_sweep_case and reads back rows through read_sweep_row, so that they
// all write the same folders and tables. See docs/guide/sweeps.md.
#pragma once
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <string_view>

#include <tbb/task_arena.h>

#include "io/case/sweep_file.hpp"

namespace flowmpm {

struct SweepRow {
  bool completed = false;
  std::size_t particles = 0;
  std::int64_t steps = 0;
  double wall_seconds = 0.0;  // the run's step loop
  double particle_steps_per_second = 0.0;
  std::map<std::string, double> errors;
  std::string message;      // why it failed
  std::optional<int> rank;  // the MPI rank that ran it (runs with --mpi only)
};

// cases/<id>/ of the sweep's output.
std::filesystem::path case_directory(const Sweep& sweep, std::size_t i);

// "case 003 (analysis.dt=0.001, analysis.scheme=\"usl\")": the case and
// its overrides, for messages.
std::string case_label(const Sweep& sweep, std::size_t i);

// The text of sweep_row.txt (TOML): the base case's digest, the overrides and
// the row, every number written so that it reads back exactly.
std::string sweep_row_text(const Sweep& sweep, std::size_t i, const SweepRow& row);

// The row that `text` records for case i, if it was written for this case
// (the same base case digest and overrides); nullopt for anything else (an
// edited base case, other overrides, not a row at all).
std::optional<SweepRow> parse_sweep_row(std::string_view text, const Sweep& sweep, std::size_t i);

// The row of case i's sweep_row.txt (parse_sweep_row); nullopt if absent.
std::optional<SweepRow> read_sweep_row(const Sweep& sweep, std::size_t i);

// Runs case i in `arena` on `threads` threads, in its folder, and writes its
// sweep_row.txt. A case without a row that has a checkpoint of its own in
// its folder (it was interrupted) continues from it. A failure of the run is the row's (completed = false, with
// the message), not the sweep's. A run stopped by `interrupt` returns
// nullopt and writes no row: the case is left to run again.
std::optional<SweepRow> run_sweep_case(const Sweep& sweep, std::size_t i, tbb::task_arena& arena, int threads,
                                       const std::atomic<bool>* interrupt, std::optional<int> rank = std::nullopt);

}  // namespace flowmpm
