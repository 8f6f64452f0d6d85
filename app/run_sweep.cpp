#include "app/run_sweep.hpp"

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cmath>
#include <exception>
#include <map>
#include <mutex>
#include <optional>
#include <set>
#include <sstream>
#include <thread>
#include <vector>

#include <spdlog/spdlog.h>
#include <tbb/task_arena.h>

#include "app/run_case.hpp"
#include "io/atomic_file.hpp"
#include "io/csv_text.hpp"

namespace flowmpm {
namespace {

using Clock = std::chrono::steady_clock;
namespace fs = std::filesystem;

constexpr const char* row_file = "sweep_row.txt";

// What sweep.csv says about one finished case.
struct SweepRow {
  bool completed = false;
  std::size_t particles = 0;
  std::int64_t steps = 0;
  double wall_seconds = 0.0;  // the run's step loop
  double particle_steps_per_second = 0.0;
  std::map<std::string, double> errors;
  std::string message;  // why it failed
};

std::string listed(const std::vector<std::string>& overrides) {
  std::string out;
  for (const std::string& o : overrides) out += (out.empty() ? "" : ", ") + o;
  return out.empty() ? "the base case" : out;
}

// sweep_row.txt (TOML): what the case ran (the base case's digest and the
// overrides) and its row, every number written so that it reads back exactly.
std::string row_file_text(const Sweep& sweep, const SweepCase& sc, const SweepRow& row) {
  toml::array overrides;
  for (const std::string& o : sc.overrides) overrides.push_back(o);
  toml::table errors;
  for (const auto& [name, value] : row.errors) errors.insert(name, value);
  toml::table t;
  t.insert("base_digest", sweep.base_digest);
  t.insert("overrides", std::move(overrides));
  t.insert("status", row.completed ? "completed" : "failed");
  t.insert("particles", static_cast<std::int64_t>(row.particles));
  t.insert("steps", row.steps);
  t.insert("wall_seconds", row.wall_seconds);
  t.insert("particle_steps_per_second", row.particle_steps_per_second);
  t.insert("message", row.message);
  t.insert("errors", std::move(errors));
  std::ostringstream text;
  text << "# flowmpm sweep, case " << sc.id << "\n" << toml::toml_formatter{t} << "\n";
  return text.str();
}

// The row of an earlier run of this case, if it completed with the same base
// case and overrides; anything else (absent, failed, an edited base case,
// other overrides, unreadable) runs the case again.
std::optional<SweepRow> completed_row(const fs::path& file, const Sweep& sweep, const SweepCase& sc) {
  if (!fs::is_regular_file(file)) return std::nullopt;
  toml::table t;
  try {
    t = toml::parse_file(file.string());
  } catch (const toml::parse_error&) {
    return std::nullopt;
  }
  if (t["base_digest"].value<std::string>() != sweep.base_digest) return std::nullopt;
  const toml::array* overrides = t["overrides"].as_array();
  if (!overrides || overrides->size() != sc.overrides.size()) return std::nullopt;
  for (std::size_t i = 0; i < sc.overrides.size(); ++i) {
    if (overrides->get(i)->value<std::string>() != sc.overrides[i]) return std::nullopt;
  }
  const auto particles = t["particles"].value<std::int64_t>();
  const auto steps = t["steps"].value<std::int64_t>();
  const auto wall = t["wall_seconds"].value<double>();
  const auto rate = t["particle_steps_per_second"].value<double>();
  const toml::table* errors = t["errors"].as_table();
  if (t["status"].value<std::string>() != "completed" || !particles || !steps || !wall || !rate || !errors) {
    return std::nullopt;
  }
  SweepRow row;
  row.completed = true;
  row.particles = static_cast<std::size_t>(*particles);
  row.steps = *steps;
  row.wall_seconds = *wall;
  row.particle_steps_per_second = *rate;
  for (auto&& [name, value] : *errors) {
    const auto v = value.value<double>();
    if (!v) return std::nullopt;
    row.errors.emplace(std::string(name.str()), *v);
  }
  return row;
}

std::string csv_number(double value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value < 0.0 ? "-inf" : "inf";
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

// sweep.csv: the finished cases in case order, one error column per error
// name of any of them.
std::string sweep_csv(const Sweep& sweep, const std::vector<std::optional<SweepRow>>& rows) {
  std::set<std::string> error_names;
  for (const auto& row : rows) {
    if (!row) continue;
    for (const auto& [name, value] : row->errors) error_names.insert(name);
  }
  std::string out = "case";
  for (const std::string& key : sweep.keys) out += "," + csv_field(key);
  out += ",status,particles,steps,wall_seconds,particle_steps_per_second";
  for (const std::string& name : error_names) out += "," + csv_field(name);
  out += ",message\n";
  for (std::size_t i = 0; i < rows.size(); ++i) {
    if (!rows[i]) continue;
    const SweepRow& row = *rows[i];
    out += sweep.cases[i].id;
    for (const std::string& value : sweep.cases[i].values) out += "," + csv_field(value);
    if (row.completed) {
      out += ",completed," + std::to_string(row.particles) + "," + std::to_string(row.steps) + "," +
             csv_number(row.wall_seconds) + "," + csv_number(row.particle_steps_per_second);
    } else {
      out += ",failed,,,,";
    }
    for (const std::string& name : error_names) {
      const auto it = row.errors.find(name);
      out += "," + (it == row.errors.end() ? std::string() : csv_number(it->second));
    }
    out += "," + (row.message.empty() ? std::string() : csv_quoted(row.message)) + "\n";
  }
  return out;
}

// Runs one case in `arena`; a failure of the run is the row's, not the sweep's.
SweepRow run_one(const SweepCase& sc, const fs::path& dir, tbb::task_arena& arena, int threads,
                 const std::atomic<bool>* interrupt) {
  Case c = sc.c;
  c.output.directory = dir;
  RunOptions options;
  options.threads = threads;
  options.log_to_console = false;
  options.interrupt = interrupt;
  SweepRow row;
  try {
    RunSummary s;
    arena.execute([&] { s = run_case(c, options); });
    row.completed = true;
    row.particles = s.particles;
    row.steps = s.steps;
    row.wall_seconds = s.step_loop_seconds;
    row.particle_steps_per_second = s.particle_steps_per_second;
    row.errors = s.errors;
  } catch (const std::exception& e) {
    row.message = e.what();
  }
  return row;
}

}  // namespace

SweepSummary run_sweep(const Sweep& sweep, const SweepOptions& options) {
  // The sweep logs its progress at the level set for the program; the
  // cases log to their own run.log only.
  const auto log = spdlog::default_logger()->clone("sweep");
  const auto interrupted = [&] { return options.interrupt && options.interrupt->load(); };

  const std::size_t n = sweep.cases.size();
  const fs::path csv_file = sweep.output / "sweep.csv";
  auto case_dir = [&](std::size_t i) { return sweep.output / "cases" / sweep.cases[i].id; };

  SweepSummary summary;
  std::vector<std::optional<SweepRow>> rows(n);
  std::vector<std::size_t> todo;
  for (std::size_t i = 0; i < n; ++i) {
    rows[i] = completed_row(case_dir(i) / row_file, sweep, sweep.cases[i]);
    if (rows[i]) {
      ++summary.skipped;
    } else {
      todo.push_back(i);
    }
  }
  summary.completed = summary.skipped;

  // No more jobs than cases to run, so that each job gets its share of threads.
  const int jobs = static_cast<int>(
      std::min(static_cast<std::size_t>(std::max(1, options.jobs)), std::max<std::size_t>(1, todo.size())));
  const int threads = std::max(1, options.threads / jobs);
  log->info("sweep: {} case{} of {} from {}, output in {}", n, n == 1 ? "" : "s", sweep.base.string(),
            sweep.file.string(), sweep.output.string());
  if (summary.skipped > 0) {
    log->info("sweep: {} case{} already completed, skipped", summary.skipped, summary.skipped == 1 ? "" : "s");
  }
  if (!todo.empty()) {
    log->info("sweep: running {} case{}, {} at a time on {} thread{} each", todo.size(),
              todo.size() == 1 ? "" : "s", jobs, threads, threads == 1 ? "" : "s");
  }

  fs::create_directories(sweep.output / "cases");
  write_file_atomically(csv_file, sweep_csv(sweep, rows));

  std::mutex mutex;  // guards rows, summary, the progress line and sweep.csv
  std::atomic<std::size_t> next{0};
  std::atomic<bool> stop{false};
  std::exception_ptr error;
  std::size_t ran = 0;
  const auto start = Clock::now();
  auto last_progress = start;

  auto finish = [&](std::size_t i, const SweepRow& row) {
    write_file_atomically(case_dir(i) / row_file, row_file_text(sweep, sweep.cases[i], row));
    const std::lock_guard lock(mutex);
    rows[i] = row;
    ++ran;
    ++(row.completed ? summary.completed : summary.failed);
    if (!row.completed) {
      log->warn("sweep: case {} ({}) failed: {}", sweep.cases[i].id, listed(sweep.cases[i].overrides), row.message);
    }
    write_file_atomically(csv_file, sweep_csv(sweep, rows));
    const auto now = Clock::now();
    const double elapsed = std::chrono::duration<double>(now - start).count();
    if (ran == todo.size() || now - last_progress >= std::chrono::seconds(1)) {
      last_progress = now;
      const double eta = elapsed / static_cast<double>(ran) * static_cast<double>(todo.size() - ran);
      log->info("sweep: {}/{} done ({} failed, {} skipped), {:.1f} s elapsed, ETA {:.0f} s",
                summary.skipped + ran, n, summary.failed, summary.skipped, elapsed, eta);
    }
  };

  auto worker = [&] {
    tbb::task_arena arena(threads);
    while (!stop && !interrupted()) {
      const std::size_t k = next++;
      if (k >= todo.size()) return;
      const std::size_t i = todo[k];
      try {
        const SweepRow row = run_one(sweep.cases[i], case_dir(i), arena, threads, options.interrupt);
        // A run stopped by the interrupt did not fail: it runs again next time.
        if (!row.completed && interrupted()) return;
        finish(i, row);
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

  summary.interrupted = interrupted() && summary.completed + summary.failed < n;
  const double elapsed = std::chrono::duration<double>(Clock::now() - start).count();
  log->info("sweep: {} completed ({} skipped), {} failed{} in {:.1f} s; table in {}", summary.completed,
            summary.skipped, summary.failed, summary.interrupted ? ", interrupted" : "", elapsed, csv_file.string());
  return summary;
}

}  // namespace flowmpm
