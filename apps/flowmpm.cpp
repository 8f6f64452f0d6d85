// flowmpm: run or check an explicit MPM case described by a TOML file, or
// run a sweep of cases.
#include <algorithm>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

#include <spdlog/spdlog.h>
#include <tbb/global_control.h>

#include "engine/run_case.hpp"
#include "engine/run_sweep.hpp"
#include "engine/simulation.hpp"
#include "io/case_reader.hpp"
#include "io/sweep_file.hpp"

namespace {

constexpr const char* usage = R"(flowmpm - explicit Material Point Method for solid mechanics

Usage:
  flowmpm run CASE.toml [--threads N] [--output DIR] [--set KEY=VALUE ...] [--quiet]
  flowmpm check CASE.toml [--set KEY=VALUE ...]
  flowmpm sweep SWEEP.toml [--jobs N] [--threads N] [--output DIR] [--quiet]
  flowmpm --help | --version

Commands:
  run     run the case; writes results.h5, results.xdmf (open in ParaView),
          timeseries.csv and summary.json to the output directory
  check   read and validate the case and describe the model it builds
  sweep   run every case of a sweep file (a base case and the keys to vary);
          writes sweep.csv (one row per case: the varied values, particles,
          steps, wall time, particle-steps/s, error norms) and each case's
          results in cases/NNN/ of the output directory; running it again
          skips the cases already completed

Options:
  --threads N       worker threads (default: all cores); results do not
                    depend on N; a sweep splits them between its jobs
  --output DIR      output directory (overrides output.directory, or the
                    sweep file's output)
  --jobs N          sweep: cases run side by side (default 1)
  --set KEY=VALUE   override a key of the case, VALUE in TOML syntax, e.g.
                    --set analysis.dt=0.001 --set analysis.scheme=musl
                    --set bodies.0.velocity=[1.0,0,0]
  --quiet           log warnings and errors only

Exit status: 0 on success, 1 for a bad case file, sweep file or command
line, 2 if the simulation (or a case of the sweep) failed, 130 if
interrupted.
)";

std::atomic<bool> interrupted{false};
void on_signal(int) { interrupted = true; }

struct Arguments {
  std::string command, case_file, output;
  int threads = 0;
  int jobs = 0;  // 0: not given
  bool quiet = false;
  std::vector<std::string> overrides;
};

[[noreturn]] void bad_usage(const std::string& message) {
  std::cerr << "flowmpm: " << message << "\n(see flowmpm --help)\n";
  std::exit(1);
}

Arguments parse(int argc, char** argv) {
  Arguments a;
  std::vector<std::string> args(argv + 1, argv + argc);
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& s = args[i];
    auto value = [&](const char* option) -> std::string {
      if (i + 1 >= args.size()) bad_usage(std::string(option) + " needs a value");
      return args[++i];
    };
    if (s == "--help" || s == "-h") {
      std::cout << usage;
      std::exit(0);
    } else if (s == "--version") {
      std::cout << "flowmpm " << FLOWMPM_VERSION << "\n";
      std::exit(0);
    } else if (s == "--threads" || s == "--jobs") {
      const std::string v = value(s.c_str());
      char* end = nullptr;
      const long n = std::strtol(v.c_str(), &end, 10);
      if (*end != '\0' || n < 1 || n > 1024) bad_usage(s + ": expected a positive integer, got '" + v + "'");
      (s == "--threads" ? a.threads : a.jobs) = static_cast<int>(n);
    } else if (s == "--output") {
      a.output = value("--output");
    } else if (s == "--set") {
      a.overrides.push_back(value("--set"));
    } else if (s == "--quiet") {
      a.quiet = true;
    } else if (s.starts_with("-")) {
      bad_usage("unknown option '" + s + "'");
    } else if (a.command.empty()) {
      a.command = s;
    } else if (a.case_file.empty()) {
      a.case_file = s;
    } else {
      bad_usage("unexpected argument '" + s + "'");
    }
  }
  if (a.command.empty()) bad_usage("no command given");
  if (a.command != "run" && a.command != "check" && a.command != "sweep") {
    bad_usage("unknown command '" + a.command + "'");
  }
  if (a.case_file.empty()) bad_usage(a.command + ": no " + (a.command == "sweep" ? "sweep" : "case") + " file given");
  if (a.command == "sweep" && !a.overrides.empty()) {
    bad_usage("sweep: --set is not supported; vary the key in the sweep file");
  }
  if (a.command != "sweep" && a.jobs > 0) bad_usage(a.command + ": --jobs is for sweep only");
  return a;
}

// flowmpm sweep: reads and checks the whole sweep, then runs it.
int sweep(const Arguments& args, int threads) {
  flowmpm::Sweep s;
  try {
    s = flowmpm::read_sweep(args.case_file);
  } catch (const flowmpm::CaseError& e) {
    spdlog::error("{}", e.what());
    return 1;
  }
  if (!args.output.empty()) s.output = args.output;
  flowmpm::SweepOptions options;
  options.jobs = std::max(1, args.jobs);
  options.threads = threads;
  options.interrupt = &interrupted;
  try {
    const flowmpm::SweepSummary summary = flowmpm::run_sweep(s, options);
    if (summary.interrupted) return 130;
    return summary.failed > 0 ? 2 : 0;
  } catch (const std::exception& e) {
    spdlog::error("{}", e.what());
    return 2;
  }
}

}  // namespace

int main(int argc, char** argv) {
  const Arguments args = parse(argc, argv);
  spdlog::set_pattern("[%H:%M:%S.%e] %^%l%$ %v");
  if (args.quiet) spdlog::set_level(spdlog::level::warn);

  const int threads = args.threads > 0 ? args.threads
                                        : static_cast<int>(tbb::info::default_concurrency());
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(threads));

  // Ctrl-C or a termination request: finish the current step, keep results.
  std::signal(SIGINT, on_signal);
  std::signal(SIGTERM, on_signal);
  if (args.command == "sweep") return sweep(args, threads);

  flowmpm::Case c;
  const auto read_start = std::chrono::steady_clock::now();
  try {
    if (!std::filesystem::exists(args.case_file)) {
      throw flowmpm::CaseError(args.case_file + ": no such file");
    }
    c = flowmpm::read_case(args.case_file, args.overrides);
    if (!args.output.empty()) c.output.directory = args.output;
    spdlog::info("case '{}' read from {}", c.name, args.case_file);
    if (args.command == "check") {
      flowmpm::describe_case(c);
      std::cout << args.case_file << ": ok\n";
      return 0;
    }
  } catch (const flowmpm::CaseError& e) {
    spdlog::error("{}", e.what());
    return 1;
  }

  flowmpm::RunOptions options;
  options.threads = threads;
  options.interrupt = &interrupted;
  options.setup_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - read_start).count();
  try {
    spdlog::info("running on {} thread{}, output in {}", threads, threads == 1 ? "" : "s",
                 c.output.directory.string());
    const flowmpm::RunSummary s = flowmpm::run_case(c, options);
    spdlog::info("done: {} steps, {} particles, {:.3f} s in the step loop, {:.4g} particle-steps/s "
                 "(set-up {:.3f} s, output {:.3f} s)",
                 s.steps, s.particles, s.step_loop_seconds, s.particle_steps_per_second, s.setup_seconds,
                 s.output_seconds);
    for (const auto& b : s.bodies) {
      spdlog::info("body '{}' at t = {} s: mean stress xx {:.6g} yy {:.6g} zz {:.6g} Pa, "
                   "mean strain xx {:.6g} yy {:.6g} zz {:.6g}",
                   b.name, c.end_time, b.mean_stress[0], b.mean_stress[1], b.mean_stress[2], b.mean_strain[0],
                   b.mean_strain[1], b.mean_strain[2]);
    }
    if (s.energy_initial > 0.0) {
      spdlog::info("energy (kinetic + strain): {:.6g} J at the start, {:.6g} J at the end, drift {:+.3g} %",
                   s.energy_initial, s.energy_final, 100.0 * s.energy_drift());
    }
    for (const auto& [name, value] : s.errors) {
      spdlog::info("error against the {} reference: {} = {:.4g}", c.reference.type, name, value);
    }
  } catch (const flowmpm::CaseError& e) {
    spdlog::error("{}", e.what());
    return 1;
  } catch (const flowmpm::SimulationError& e) {
    spdlog::error("{}", e.what());
    return interrupted ? 130 : 2;
  } catch (const std::exception& e) {
    spdlog::error("{}", e.what());
    return 2;
  }
  return 0;
}
