// flowmpm: run or check an explicit MPM case described by a TOML file, or
// run a sweep of cases.
#include <algorithm>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <spdlog/spdlog.h>
#include <tbb/global_control.h>
#include <tbb/info.h>

#include "app/run_case.hpp"
#include "app/run_sweep.hpp"
#include "core/errors.hpp"
#include "io/sweep_file.hpp"

namespace {

std::atomic<bool> interrupted{false};
void on_signal(int) { interrupted = true; }

struct Arguments {
  std::string command, case_file, output;
  int threads = 0;  // 0: all cores
  int jobs = 1;
  bool quiet = false;
  std::vector<std::string> overrides;
};

[[noreturn]] void bad_usage(const std::string& message) {
  std::cerr << "flowmpm: " << message << "\n(see flowmpm --help)\n";
  std::exit(1);
}

// Parses the command line (CLI11): one command, each with its own options
// and --help. Exits 0 after --help or --version, 1 on misuse.
Arguments parse(int argc, char** argv) {
  Arguments a;
  CLI::App app("flowmpm - explicit Material Point Method for solid mechanics", "flowmpm");
  app.set_version_flag("--version", std::string("flowmpm ") + FLOWMPM_VERSION);
  app.footer(
      "Exit status: 0 on success, 1 for a bad case file, sweep file or command line, 2 if the simulation "
      "(or a case of the sweep) failed, 130 if interrupted. `flowmpm COMMAND --help` lists a command's "
      "options; README.md has the case file keys.");
  const auto threads = [&](CLI::App* command) {
    command->add_option("--threads", a.threads, "worker threads (default: all cores); results do not depend on it")
        ->check(CLI::Range(1, 1024));
  };
  const auto quiet = [&](CLI::App* command) { command->add_flag("--quiet", a.quiet, "log warnings and errors only"); };
  const auto overrides = [&](CLI::App* command) {
    command
        ->add_option("--set", a.overrides,
                     "override a key of the case, VALUE in TOML syntax (a bare word is a string): "
                     "--set analysis.dt=0.001 --set bodies.0.velocity=[1.0,0,0]")
        ->type_name("KEY=VALUE")
        ->allow_extra_args(false);
  };

  CLI::App* run = app.add_subcommand(
      "run", "run a case; writes results.h5, results.xdmf (open in ParaView), timeseries.csv and summary.json");
  run->add_option("case", a.case_file, "the case file (TOML)")->type_name("CASE.toml");
  threads(run);
  run->add_option("--output", a.output, "output directory (overrides output.directory)");
  overrides(run);
  quiet(run);

  CLI::App* check = app.add_subcommand("check", "read and validate a case and describe the model it builds");
  check->add_option("case", a.case_file, "the case file (TOML)")->type_name("CASE.toml");
  overrides(check);

  CLI::App* sweep = app.add_subcommand(
      "sweep",
      "run every case of a sweep file (a base case and the keys to vary); writes sweep.csv and each case's "
      "results in cases/NNN/; running it again skips the cases already completed");
  sweep->add_option("sweep", a.case_file, "the sweep file (TOML)")->type_name("SWEEP.toml");
  sweep->add_option("--jobs", a.jobs, "cases run side by side (default 1); the threads are split between them")
      ->check(CLI::Range(1, 1024));
  threads(sweep);
  sweep->add_option("--output", a.output, "output directory (overrides the sweep file's output)");
  quiet(sweep);

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    std::exit(app.exit(e));
  } catch (const CLI::CallForAllHelp& e) {
    std::exit(app.exit(e));
  } catch (const CLI::CallForVersion& e) {
    std::exit(app.exit(e));
  } catch (const CLI::ParseError& e) {
    bad_usage(e.what());
  }
  const std::vector<CLI::App*> chosen = app.get_subcommands();
  if (chosen.empty()) bad_usage("no command given: run, check or sweep");
  a.command = chosen.front()->get_name();
  if (a.case_file.empty()) bad_usage(a.command + ": no " + (a.command == "sweep" ? "sweep" : "case") + " file given");
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
  options.jobs = args.jobs;
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
      spdlog::info("error against the {} reference: {} = {:.4g}", c.reference->type(), name, value);
    }
    for (const auto& [name, value] : s.measures) {
      spdlog::info("measured by the {} reference: {} = {:.6g}", c.reference->type(), name, value);
    }
    if (s.damping_dissipated) spdlog::info("energy dissipated by damping: {:.6g} J", *s.damping_dissipated);
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
