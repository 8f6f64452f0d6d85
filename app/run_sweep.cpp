#include "app/run_sweep.hpp"

#include <algorithm>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

#include <spdlog/spdlog.h>
#include <tbb/task_arena.h>

#include "io/results/atomic_file.hpp"

namespace flowmpm {

std::shared_ptr<spdlog::logger> sweep_logger() { return spdlog::default_logger()->clone("sweep"); }

SweepSummary run_sweep(const Sweep& sweep, const SweepOptions& options) {
  // The sweep logs its progress at the level set for the program; the
  // cases log to their own run.log only.
  const auto log = sweep_logger();
  const auto interrupted = [&] { return options.interrupt && options.interrupt->load(); };

  SweepTable table(sweep, options.shard, log);
  const std::vector<std::size_t>& todo = table.todo();
  // No more jobs than cases to run, so that each job gets its share of threads.
  const int jobs = static_cast<int>(
      std::min(static_cast<std::size_t>(std::max(1, options.jobs)), std::max<std::size_t>(1, todo.size())));
  const int threads = std::max(1, options.threads / jobs);
  table.start(std::to_string(jobs) + " at a time on " + std::to_string(threads) + " thread" +
              (threads == 1 ? "" : "s") + " each");

  std::mutex mutex;  // guards error
  std::atomic<std::size_t> next{0};
  std::atomic<bool> stop{false};
  std::exception_ptr error;
  auto worker = [&] {
    tbb::task_arena arena(threads);
    while (!stop && !interrupted()) {
      const std::size_t k = next++;
      if (k >= todo.size()) return;
      try {
        const auto row = run_sweep_case(sweep, todo[k], arena, threads, options.interrupt);
        if (!row) return;  // interrupted: left to run again
        table.record(todo[k], *row);
      } catch (...) {
        const std::lock_guard lock(mutex);
        if (!error) error = std::current_exception();
        stop = true;
      }
    }
  };
  std::vector<std::thread> pool;
  for (int j = 0; j < jobs; ++j) pool.emplace_back(worker);
  for (std::thread& t : pool) t.join();
  if (error) std::rethrow_exception(error);
  return table.finish(interrupted());
}

SweepSummary collect_sweep(const Sweep& sweep) {
  const auto log = sweep_logger();
  const std::size_t n = sweep.cases.size();
  std::vector<std::optional<SweepRow>> rows(n);
  std::vector<std::string> missing, failed;
  SweepSummary summary;
  for (std::size_t i = 0; i < n; ++i) {
    rows[i] = read_sweep_row(sweep, i);
    if (!rows[i]) {
      missing.push_back(sweep.cases[i].id);
    } else if (!rows[i]->completed) {
      failed.push_back(sweep.cases[i].id);
      log->warn("sweep: {} failed: {}", case_label(sweep, i), rows[i]->message);
    }
  }
  summary.completed = n - missing.size() - failed.size();
  summary.failed = failed.size();
  summary.missing = missing.size();
  const auto some = [](const std::vector<std::string>& ids) {
    std::string out;
    for (std::size_t k = 0; k < ids.size() && k < 20; ++k) out += (k ? ", " : "") + ids[k];
    return ids.size() > 20 ? out + ", ..." : out;
  };
  if (!missing.empty()) {
    log->warn("sweep: {} case{} not run yet, or run with another base case or other overrides: {}", missing.size(),
              missing.size() == 1 ? "" : "s", some(missing));
  }
  const std::filesystem::path csv = sweep.output / "sweep.csv";
  std::filesystem::create_directories(sweep.output);
  write_file_atomically(csv, sweep_csv(sweep, rows));
  log->info("sweep: collected {} of {} cases: {} completed, {} failed{}, {} missing; table in {}",
            n - missing.size(), n, summary.completed, summary.failed, failed.empty() ? "" : " (" + some(failed) + ")",
            summary.missing, csv.string());
  return summary;
}

}  // namespace flowmpm
