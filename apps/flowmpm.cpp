// flowmpm: run or check an explicit MPM case described by a TOML file, or
// run a sweep of cases.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>
#include <tbb/global_control.h>
#include <tbb/info.h>

#include "app/interrupt.hpp"
#include "app/run_case.hpp"
#include "app/run_sweep.hpp"
#ifdef FLOWMPM_MPI
#include "app/run_sweep_mpi.hpp"
#endif
#include "core/errors.hpp"
#include "io/case/memory_estimate.hpp"
#include "io/results/output_lock.hpp"
#include "io/case/sweep_file.hpp"

namespace {

struct Arguments {
  std::string command, case_file, output, restart, max_memory;
  int threads = 0;  // 0: all cores
  int jobs = 1;
  bool quiet = false;
  bool mpi = false, collect = false;
  flowmpm::SweepShard shard;
  std::vector<std::string> overrides;
};

[[noreturn]] void bad_usage(const std::string& message) {
  std::cerr << "flowmpm: " << message << "\n(see flowmpm --help)\n";
  std::exit(1);
}

// --shard I/N: the cases whose number is I modulo N.
std::string read_shard(const std::string& text, flowmpm::SweepShard& shard) {
  const auto slash = text.find('/');
  const auto whole = [](const std::string& part, std::size_t& value) {
    if (part.empty() || part.size() > 9 || part.find_first_not_of("0123456789") != std::string::npos) return false;
    value = std::stoul(part);
    return true;
  };
  if (slash == std::string::npos || !whole(text.substr(0, slash), shard.index) ||
      !whole(text.substr(slash + 1), shard.count) || shard.count == 0 || shard.index >= shard.count) {
    return "expected I/N, whole numbers with 0 <= I < N (the cases whose number is I modulo N), got " + text;
  }
  return {};
}

// The processes an MPI launcher started this one with (1 if none): mpirun
// of Open MPI, or of MPICH and Intel MPI (Hydra).
int launched_processes() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"}) {
    if (const char* value = std::getenv(name)) return std::max(1, std::atoi(value));
  }
  return 1;
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
      "options; docs/reference/ has every case file key.");
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
  const auto max_memory = [&](CLI::App* command) {
    command
        ->add_option("--max-memory", a.max_memory,
                     "the memory a case may take (default: what the machine has available); a case estimated "
                     "to need more is rejected")
        ->type_name("SIZE")
        ->check([](const std::string& text) {
          return flowmpm::parse_memory_size(text) ? std::string()
                                                  : "expected a size such as 512M, 2G or 1.5G (K, M, G, T: "
                                                    "powers of 1024), got " + text;
        });
  };

  CLI::App* run = app.add_subcommand(
      "run", "run a case; writes results.h5, results.xdmf (open in ParaView), timeseries.csv and summary.json");
  run->add_option("case", a.case_file, "the case file (TOML)")->type_name("CASE.toml");
  threads(run);
  CLI::Option* output = run->add_option("--output", a.output, "output directory (overrides output.directory)");
  run->add_option("--restart", a.restart,
                  "continue the run whose output directory is DIR from its checkpoint (with the same case file and "
                  "--set options); its results files are continued")
      ->type_name("DIR")
      ->excludes(output);
  overrides(run);
  max_memory(run);
  quiet(run);

  CLI::App* check = app.add_subcommand("check", "read and validate a case and describe the model it builds");
  check->add_option("case", a.case_file, "the case file (TOML)")->type_name("CASE.toml");
  check->add_option("--output", a.output, "output directory (as run takes it; checked to be writable)");
  overrides(check);
  max_memory(check);

  CLI::App* sweep = app.add_subcommand(
      "sweep",
      "run every case of a sweep file (a base case and the keys to vary); writes sweep.csv and each case's "
      "results in cases/NNN/; running it again skips the cases already completed");
  sweep->add_option("sweep", a.case_file, "the sweep file (TOML)")->type_name("SWEEP.toml");
  CLI::Option* jobs =
      sweep->add_option("--jobs", a.jobs, "cases run side by side (default 1); the threads are split between them")
          ->check(CLI::Range(1, 1024));
  threads(sweep);
  sweep->add_option("--output", a.output, "output directory (overrides the sweep file's output)");
  max_memory(sweep);
  quiet(sweep);
  CLI::Option* mpi = sweep->add_flag(
      "--mpi", a.mpi,
      "run the cases over the ranks of an MPI job (mpirun -n R flowmpm sweep SWEEP.toml --mpi): each rank runs one "
      "case at a time on its --threads; rank 0 writes sweep.csv");
  CLI::Option* shard =
      sweep
          ->add_option_function<std::string>(
              "--shard",
              [&](const std::string& text) {
                if (const std::string problem = read_shard(text, a.shard); !problem.empty()) {
                  throw CLI::ValidationError("--shard", problem);
                }
              },
              "run only the cases whose number is I modulo N (one job of a scheduler's job array); writes their "
              "folders and no sweep.csv")
          ->type_name("I/N");
  CLI::Option* collect = sweep->add_flag(
      "--collect", a.collect, "run nothing: build sweep.csv from the cases' folders (after the shards have run)");
  mpi->excludes(shard)->excludes(jobs);
  collect->excludes(mpi)->excludes(shard)->excludes(jobs);

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
#ifndef FLOWMPM_MPI
  if (a.mpi) bad_usage("--mpi: this flowmpm was built without MPI (install libopenmpi-dev and build again)");
#endif
  const int processes = launched_processes();
  if (processes > 1 && !a.mpi && a.command != "check") {
    bad_usage("started by an MPI launcher as " + std::to_string(processes) + " processes, each of which would run " +
              (a.command == "sweep" ? "the whole sweep; add --mpi to share the cases out"
                                    : "the whole case; run a case as one process"));
  }
  return a;
}

// flowmpm sweep: reads and checks the whole sweep, then runs it (on
// threads, on MPI ranks or as a shard) or collects its table.
int sweep(const Arguments& args, int threads, int& argc, char**& argv) {
  bool root = true;  // the process that reports
#ifdef FLOWMPM_MPI
  std::optional<flowmpm::MpiSession> mpi;
  if (args.mpi) {
    mpi.emplace(argc, argv);
    root = mpi->rank() == 0;
  }
#else
  (void)argc;
  (void)argv;
#endif
  flowmpm::Sweep s;
  try {
    s = flowmpm::read_sweep(args.case_file);
  } catch (const flowmpm::CaseError& e) {
    if (root) spdlog::error("{}", e.what());
    return 1;
  }
  if (!args.output.empty()) s.output = args.output;
  flowmpm::SweepOptions options;
  options.jobs = args.jobs;
  options.threads = threads;
  options.shard = args.shard;
  options.interrupt = &flowmpm::interrupt_requested();
  // A sweep stops its running cases after their current step.
  const flowmpm::FinishBeforeExit finish_before_exit;
  try {
    flowmpm::SweepSummary summary;
    if (args.collect) {
      summary = flowmpm::collect_sweep(s);
#ifdef FLOWMPM_MPI
    } else if (mpi) {
      summary = flowmpm::run_sweep_mpi(s, options, *mpi);
#endif
    } else {
      summary = flowmpm::run_sweep(s, options);
    }
    if (summary.interrupted) return 130;
    return summary.failed > 0 || summary.missing > 0 ? 2 : 0;
  } catch (const std::exception& e) {
    spdlog::error("{}", flowmpm::failure_text(e));
    return 2;
  }
}

int run_command(int argc, char** argv) {
  const Arguments args = parse(argc, argv);
  // The log (progress, warnings, errors) goes to stderr; stdout carries only
  // what a command prints as its result ("check": CASE: ok).
  spdlog::set_default_logger(spdlog::stderr_color_mt("flowmpm"));
  spdlog::set_pattern("[%H:%M:%S.%e] %^%l%$ %v");
  if (args.quiet) spdlog::set_level(spdlog::level::warn);

  const int threads = args.threads > 0 ? args.threads
                                        : static_cast<int>(tbb::info::default_concurrency());
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(threads));

  if (!args.max_memory.empty()) flowmpm::set_memory_limit(flowmpm::parse_memory_size(args.max_memory));
  if (args.command == "sweep") return sweep(args, threads, argc, argv);

  flowmpm::Case c;
  const auto read_start = std::chrono::steady_clock::now();
  try {
    if (!std::filesystem::exists(args.case_file)) {
      throw flowmpm::CaseError(args.case_file + ": no such file");
    }
    c = flowmpm::read_case(args.case_file, args.overrides);
    if (!args.output.empty()) c.output.directory = args.output;
    if (!args.restart.empty()) c.output.directory = args.restart;
    flowmpm::check_output_directory(c.output.directory);
    if (args.command == "check") {
      flowmpm::describe_case(c);
      std::cout << args.case_file << ": ok\n";
      return 0;
    }
  } catch (const flowmpm::CaseError& e) {
    spdlog::error("{}", e.what());
    return 1;
  } catch (const std::exception& e) {
    spdlog::error("{}: {}", args.case_file, flowmpm::failure_text(e));
    return 2;
  }

  flowmpm::RunOptions options;
  options.threads = threads;
  options.interrupt = &flowmpm::interrupt_requested();
  if (!args.restart.empty()) options.restart = flowmpm::Restart::from_checkpoint;
  options.setup_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - read_start).count();
  try {
    flowmpm::run_case(c, options);
  } catch (const flowmpm::CaseError& e) {
    spdlog::error("{}", e.what());
    return 1;
  } catch (const flowmpm::SimulationError&) {
    return flowmpm::interrupt_requested() ? 130 : 2;  // run_case logged it
  } catch (const std::exception& e) {
    spdlog::error("{}: {}", args.case_file, flowmpm::failure_text(e));
    return 2;
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  // Before anything is read: an early Ctrl-C or SIGTERM ends the program
  // with status 130 and a message (app/interrupt.hpp).
  flowmpm::install_interrupt_handlers();
  // Nothing escapes as an uncaught exception (which would abort).
  try {
    return run_command(argc, argv);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "flowmpm: %s\n", flowmpm::failure_text(e).c_str());
  } catch (...) {
    std::fprintf(stderr, "flowmpm: an unknown error\n");
  }
  return 2;
}
