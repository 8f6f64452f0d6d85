#include "app/sweep_row.hpp"

#include <exception>
#include <fstream>
#include <sstream>

#include "app/run_case.hpp"
#include "io/results/atomic_file.hpp"
#include "io/results/output_lock.hpp"

namespace flowmpm {
namespace {

constexpr const char* row_file = "sweep_row.txt";

}  // namespace

std::filesystem::path case_directory(const Sweep& sweep, std::size_t i) {
  return sweep.output / "cases" / sweep.cases[i].id;
}

std::string case_label(const Sweep& sweep, std::size_t i) {
  std::string overrides;
  for (const std::string& o : sweep.cases[i].overrides) overrides += (overrides.empty() ? "" : ", ") + o;
  return "case " + sweep.cases[i].id + " (" + (overrides.empty() ? "the base case" : overrides) + ")";
}

std::string sweep_row_text(const Sweep& sweep, std::size_t i, const SweepRow& row) {
  const SweepCase& sc = sweep.cases[i];
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
  if (row.rank) t.insert("rank", static_cast<std::int64_t>(*row.rank));
  t.insert("errors", std::move(errors));
  std::ostringstream text;
  text << "# flowmpm sweep, case " << sc.id << "\n" << toml::toml_formatter{t} << "\n";
  return text.str();
}

std::optional<SweepRow> parse_sweep_row(std::string_view text, const Sweep& sweep, std::size_t i) {
  const SweepCase& sc = sweep.cases[i];
  toml::table t;
  try {
    t = toml::parse(text);
  } catch (const toml::parse_error&) {
    return std::nullopt;
  }
  if (t["base_digest"].value<std::string>() != sweep.base_digest) return std::nullopt;
  const toml::array* overrides = t["overrides"].as_array();
  if (!overrides || overrides->size() != sc.overrides.size()) return std::nullopt;
  for (std::size_t k = 0; k < sc.overrides.size(); ++k) {
    if (overrides->get(k)->value<std::string>() != sc.overrides[k]) return std::nullopt;
  }
  const auto status = t["status"].value<std::string>();
  const auto particles = t["particles"].value<std::int64_t>();
  const auto steps = t["steps"].value<std::int64_t>();
  const auto wall = t["wall_seconds"].value<double>();
  const auto rate = t["particle_steps_per_second"].value<double>();
  const auto message = t["message"].value<std::string>();
  const toml::table* errors = t["errors"].as_table();
  if (!status || (*status != "completed" && *status != "failed") || !particles || !steps || !wall || !rate ||
      !message || !errors) {
    return std::nullopt;
  }
  SweepRow row;
  row.completed = *status == "completed";
  row.particles = static_cast<std::size_t>(*particles);
  row.steps = *steps;
  row.wall_seconds = *wall;
  row.particle_steps_per_second = *rate;
  row.message = *message;
  if (const auto rank = t["rank"].value<std::int64_t>()) row.rank = static_cast<int>(*rank);
  for (auto&& [name, value] : *errors) {
    const auto v = value.value<double>();
    if (!v) return std::nullopt;
    row.errors.emplace(std::string(name.str()), *v);
  }
  return row;
}

std::optional<SweepRow> read_sweep_row(const Sweep& sweep, std::size_t i) {
  const std::filesystem::path file = case_directory(sweep, i) / row_file;
  if (!std::filesystem::is_regular_file(file)) return std::nullopt;
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return parse_sweep_row(text.str(), sweep, i);
}

std::optional<SweepRow> run_sweep_case(const Sweep& sweep, std::size_t i, tbb::task_arena& arena, int threads,
                                       const std::atomic<bool>* interrupt, std::optional<int> rank) {
  Case c = sweep.cases[i].c;
  c.output.directory = case_directory(sweep, i);
  RunOptions options;
  options.threads = threads;
  options.log_to_console = false;  // the case logs to its run.log
  options.interrupt = interrupt;
  // A case stopped part way (interrupted, or its process killed) has no row:
  // it continues from its checkpoint if it has one. A failed case runs again
  // from the start.
  options.restart = read_sweep_row(sweep, i) ? Restart::no : Restart::if_checkpoint;
  SweepRow row;
  row.rank = rank;
  try {
    RunSummary s;
    arena.execute([&] { s = run_case(c, options); });
    row.completed = true;
    row.particles = s.particles;
    row.steps = s.steps;
    row.wall_seconds = s.step_loop_seconds;
    row.particle_steps_per_second = s.particle_steps_per_second;
    row.errors = s.errors;
  } catch (const OutputInUse& e) {
    // Another process runs this case (the same sweep started twice): its
    // folder is not ours to write in.
    row.message = e.what();
    return row;
  } catch (const std::exception& e) {
    // A run stopped by the interrupt did not fail: it runs again next time.
    if (interrupt && interrupt->load()) return std::nullopt;
    row.message = failure_text(e);
  }
  // A case that failed before its run made its folder (while the model was
  // built) still gets its row there.
  std::filesystem::create_directories(c.output.directory);
  write_file_atomically(c.output.directory / row_file, sweep_row_text(sweep, i, row));
  return row;
}

}  // namespace flowmpm
