#include "app/sweep_table.hpp"

#include <charconv>
#include <cmath>
#include <set>

#include "io/results/atomic_file.hpp"
#include "io/results/csv_text.hpp"

namespace flowmpm {
namespace {

using Clock = std::chrono::steady_clock;

std::string csv_number(double value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value < 0.0 ? "-inf" : "inf";
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

std::string plural(std::size_t n, const std::string& word) { return word + (n == 1 ? "" : "s"); }

}  // namespace

std::string sweep_csv(const Sweep& sweep, const std::vector<std::optional<SweepRow>>& rows) {
  std::set<std::string> error_names;
  bool ranks = false;
  for (const auto& row : rows) {
    if (!row) continue;
    for (const auto& [name, value] : row->errors) error_names.insert(name);
    ranks = ranks || row->rank.has_value();
  }
  std::string out = "case";
  for (const std::string& key : sweep.keys) out += "," + csv_field(key);
  out += ",status,particles,steps,wall_seconds,particle_steps_per_second";
  if (ranks) out += ",rank";
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
    if (ranks) out += "," + (row.rank ? std::to_string(*row.rank) : std::string());
    for (const std::string& name : error_names) {
      const auto it = row.errors.find(name);
      out += "," + (it == row.errors.end() ? std::string() : csv_number(it->second));
    }
    out += "," + (row.message.empty() ? std::string() : csv_quoted(row.message)) + "\n";
  }
  return out;
}

SweepTable::SweepTable(const Sweep& sweep, SweepShard shard, std::shared_ptr<spdlog::logger> log)
    : sweep_(sweep), shard_(shard), log_(std::move(log)), rows_(sweep.cases.size()) {
  for (std::size_t i = 0; i < sweep.cases.size(); ++i) {
    if (!shard.takes(i)) continue;
    ++taken_;
    std::optional<SweepRow> row = read_sweep_row(sweep, i);
    if (row && row->completed) {
      rows_[i] = std::move(row);
      ++summary_.skipped;
    } else {
      todo_.push_back(i);
    }
  }
  summary_.completed = summary_.skipped;
}

void SweepTable::start(const std::string& how) {
  const std::size_t n = sweep_.cases.size();
  const std::string scope =
      shard_.whole() ? "" : "shard " + std::to_string(shard_.index) + "/" + std::to_string(shard_.count) +
                                ": " + std::to_string(taken_) + " of ";
  log_->info("sweep: {}{} {} of {} from {}, output in {}", scope, n, plural(n, "case"), sweep_.base.string(),
             sweep_.file.string(), sweep_.output.string());
  if (summary_.skipped > 0) {
    log_->info("sweep: {} {} already completed, skipped", summary_.skipped, plural(summary_.skipped, "case"));
  }
  if (!todo_.empty()) log_->info("sweep: running {} {}, {}", todo_.size(), plural(todo_.size(), "case"), how);
  std::filesystem::create_directories(sweep_.output / "cases");
  if (shard_.whole()) write_file_atomically(sweep_.output / "sweep.csv", sweep_csv(sweep_, rows_));
  start_ = last_progress_ = Clock::now();
}

void SweepTable::record(std::size_t i, const SweepRow& row) {
  const std::lock_guard lock(mutex_);
  rows_[i] = row;
  ++ran_;
  ++(row.completed ? summary_.completed : summary_.failed);
  if (!row.completed) {
    log_->warn("sweep: {} failed: {}", case_label(sweep_, i), row.message);
  }
  if (shard_.whole()) write_file_atomically(sweep_.output / "sweep.csv", sweep_csv(sweep_, rows_));
  const auto now = Clock::now();
  if (ran_ == todo_.size() || now - last_progress_ >= std::chrono::seconds(1)) {
    last_progress_ = now;
    const double elapsed = std::chrono::duration<double>(now - start_).count();
    const double eta = elapsed / static_cast<double>(ran_) * static_cast<double>(todo_.size() - ran_);
    log_->info("sweep: {}/{} done ({} failed, {} skipped), {:.1f} s elapsed, ETA {:.0f} s", summary_.skipped + ran_,
               taken_, summary_.failed, summary_.skipped, elapsed, eta);
  }
}

SweepSummary SweepTable::finish(bool interrupted) {
  const std::lock_guard lock(mutex_);
  summary_.interrupted = interrupted && summary_.completed + summary_.failed < taken_;
  const double elapsed = std::chrono::duration<double>(Clock::now() - start_).count();
  const std::string where =
      shard_.whole() ? "table in " + (sweep_.output / "sweep.csv").string()
                     : std::string("no table for a shard: --collect builds it once every shard has run");
  log_->info("sweep: {} completed ({} skipped), {} failed{} in {:.1f} s; {}", summary_.completed, summary_.skipped,
             summary_.failed, summary_.interrupted ? ", interrupted" : "", elapsed, where);
  return summary_;
}

}  // namespace flowmpm
