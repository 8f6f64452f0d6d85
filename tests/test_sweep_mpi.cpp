// flowmpm sweep --mpi under the real mpirun (Open MPI): 2 and 3 ranks give
// the table of one process, but for the timings and the rank column; a
// rank killed with SIGKILL ends the sweep, the rows finished before are
// kept, and the same command again skips them and completes the table. Built only with MPI (FLOWMPM_MPI).
//
// CI runs as root on 2 cores: mpirun is allowed to run as root and to start
// more ranks than cores through Open MPI's environment variables, the same
// as its flags --allow-run-as-root and --oversubscribe (other MPIs ignore
// them). Shared-memory transfers copy through a buffer
// (single_copy_mechanism none), which works in containers that forbid the
// cross-process reads Open MPI otherwise uses.
#include <doctest/doctest.h>
#include <signal.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "run_program.hpp"
#include "sweep_csv.hpp"

namespace fs = std::filesystem;
using namespace flowmpm::testing;

namespace {

const std::vector<std::string> mpi_environment{
    "OMPI_ALLOW_RUN_AS_ROOT=1", "OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1", "OMPI_MCA_rmaps_base_oversubscribe=1",
    "OMPI_MCA_btl_vader_single_copy_mechanism=none"};

// The vibrating bar with its reference (the table has error columns, which
// must come through the ranks' messages exactly), 8 cases. The completed
// ones run 5 periods (about 0.2 s each); a large amplitude makes a particle
// cross more than a cell in the first step, so the odd cases fail at once.
struct BarSweep : TempDir {
  BarSweep() : TempDir("flowmpm_test_sweep_mpi") {
    const fs::path base = fs::path(FLOWMPM_SOURCE_DIR) / "configs/verification/bar_vibration_small.toml";
    write_text(path / "sweep.toml", "base = \"" + base.string() + "\"\n" + R"(
[vary]
"analysis.end_time" = [2.0]
"analysis.shape_function" = ["linear", "bspline2"]
"analysis.scheme" = ["usl", "musl"]
[[zip]]
"reference.amplitude" = [1e-4, 1e3]
)");
  }

  // One process, the reference table.
  std::vector<std::map<std::string, std::string>> one_process() const {
    const Result r = run_flowmpm({"sweep", "sweep.toml", "--output", "one", "--jobs", "2", "--threads", "2"}, path);
    INFO("one process printed:\n" << r.output);
    REQUIRE(r.status == 2);
    return results_of(path / "one/sweep.csv");
  }

  Running start_mpi(int ranks, const std::string& out) const {
    return start_program({FLOWMPM_MPIEXEC, FLOWMPM_MPIEXEC_NUMPROC_FLAG, std::to_string(ranks), FLOWMPM_EXECUTABLE,
                          "sweep", "sweep.toml", "--mpi", "--threads", "1", "--output", out},
                         path, mpi_environment);
  }
};

// The ranks in the rank column of a table.
std::set<std::string> ranks_of(const fs::path& csv) {
  std::set<std::string> ranks;
  for (const auto& row : table_of(csv)) ranks.insert(row.at("rank"));
  return ranks;
}

// The process id of `rank` among the processes mpirun (`launcher`) started,
// 0 while there is none: Open MPI starts the ranks on this host as children
// of mpirun, each with OMPI_COMM_WORLD_RANK in its environment.
pid_t rank_process(pid_t launcher, int rank) {
  const std::string wanted = "OMPI_COMM_WORLD_RANK=" + std::to_string(rank);
  for (const auto& entry : fs::directory_iterator("/proc")) {
    const std::string name = entry.path().filename().string();
    if (name.find_first_not_of("0123456789") != std::string::npos) continue;
    // /proc/PID/stat: "pid (command) state ppid ..."; the command may hold spaces.
    const std::string stat = read_text(entry.path() / "stat");
    const auto close = stat.rfind(')');
    if (close == std::string::npos) continue;
    std::istringstream fields(stat.substr(close + 1));
    char state = 0;
    pid_t parent = 0;
    fields >> state >> parent;
    if (parent != launcher) continue;
    std::ifstream environ_file(entry.path() / "environ", std::ios::binary);
    for (std::string variable; std::getline(environ_file, variable, '\0');) {
      if (variable == wanted) return static_cast<pid_t>(std::stol(name));
    }
  }
  return 0;
}

}  // namespace

TEST_CASE("mpirun -n 2 and -n 3 give the one-process table, but for the timings and the rank column") {
  BarSweep dir;
  const auto one = dir.one_process();
  REQUIRE(one.size() == 8);
  CHECK(table_of(dir.path / "one/sweep.csv")[0].count("rank") == 0);
  for (const int ranks : {2, 3}) {
    const std::string out = "ranks" + std::to_string(ranks);
    const Result r = wait_for(dir.start_mpi(ranks, out));
    INFO(ranks << " ranks printed:\n" << r.output);
    CHECK(r.status == 2);  // cases failed, reported through mpirun
    CHECK(contains(r.output, "running 8 cases, one at a time on each of " + std::to_string(ranks) +
                                 " ranks on 1 host, 1 thread each"));
    CHECK(contains(r.output, "sweep: 8/8 done (4 failed, 0 skipped)"));
    CHECK(contains(r.output, "case 001 (analysis.end_time=2.0, analysis.shape_function=\"linear\", "
                             "analysis.scheme=\"usl\", reference.amplitude=1000.0) failed"));
    CHECK(results_of(dir.path / out / "sweep.csv") == one);
    // Every rank takes cases: the workers ask for the next one when free, so
    // each of the 2 ranks gets some of the 4 slow cases; with 3, at least
    // two ranks do (one may find the slow cases taken).
    const std::set<std::string> ranks_used = ranks_of(dir.path / out / "sweep.csv");
    for (const std::string& rank : ranks_used) CHECK(std::stoi(rank) < ranks);
    if (ranks == 2) CHECK(ranks_used == std::set<std::string>{"0", "1"});
    if (ranks == 3) CHECK(ranks_used.size() >= 2);
  }

}

TEST_CASE("a rank killed during an MPI sweep ends it, keeps the finished rows, and the same command completes it") {
  BarSweep dir;
  const auto one = dir.one_process();
  const Running job = dir.start_mpi(2, "killed");
  // Wait for the first case to start (its folder appears), then kill rank 1:
  // about a second of cases is still ahead.
  pid_t victim = 0;
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(30);
  while (std::chrono::steady_clock::now() < give_up) {
    victim = rank_process(job.pid, 1);
    if (victim != 0 && fs::exists(dir.path / "killed/cases") && !fs::is_empty(dir.path / "killed/cases")) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  REQUIRE(victim != 0);
  ::kill(victim, SIGKILL);
  const Result killed = wait_for(job);
  MESSAGE("the killed job printed:\n" << killed.output);
  // Open MPI ends the job when a rank dies: rank 0 gets SIGTERM, says what
  // was left, and the job exits with a failure status.
  CHECK(killed.status != 0);
  CHECK(contains(killed.output, "sweep: stopped by a signal"));
  CHECK(contains(killed.output, "left to run again: "));
  CHECK(contains(killed.output, "run the same command again to resume"));
  const auto kept = results_of(dir.path / "killed/sweep.csv");
  CHECK(kept.size() < one.size());
  for (const auto& row : kept) {
    INFO("case " << row.at("case"));
    CHECK(row == one.at(std::stoul(row.at("case"))));
  }

  std::size_t completed = 0;
  for (const auto& row : kept) completed += row.at("status") == "completed" ? 1 : 0;
  const Result resumed = wait_for(dir.start_mpi(2, "killed"));
  INFO("the resumed job printed:\n" << resumed.output);
  CHECK(resumed.status == 2);
  if (completed > 0) CHECK(contains(resumed.output, std::to_string(completed) + " case"));
  CHECK(contains(resumed.output, "running " + std::to_string(one.size() - completed) + " case"));
  CHECK(results_of(dir.path / "killed/sweep.csv") == one);
}
