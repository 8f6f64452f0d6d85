// Nothing lost, nothing mislabelled, nothing accepted that cannot run
// (issue 15): one run per output directory, numbers that the engine can
// represent, cases that fit in memory, interrupts while a model is built,
// sweeps that record a case failing at set-up, a full disk and read-only
// directories. Most checks run the flowmpm binary as a separate process.
#include <doctest/doctest.h>
#include <hdf5.h>
#include <signal.h>
#include <sys/wait.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <regex>
#include <string>
#include <thread>
#include <vector>

#include "io/case/case_file.hpp"
#include "io/case/memory_estimate.hpp"
#include "run_program.hpp"
#include "test_helpers.hpp"

namespace fs = std::filesystem;
using namespace flowmpm;
using namespace flowmpm::testing;
using Clock = std::chrono::steady_clock;

namespace {

// AddressSanitizer (scripts/test_sanitizers.sh) reserves terabytes of
// address space and doubles the resident size: the tests of memory limits
// and resident sizes do not apply to its build.
#if defined(__SANITIZE_ADDRESS__)
constexpr bool address_sanitizer = true;
#else
constexpr bool address_sanitizer = false;
#endif

double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

// Polls `done` every 10 ms for up to `seconds`; whether it became true.
bool wait_until(const std::function<bool()>& done, double seconds) {
  const auto t0 = Clock::now();
  while (!done()) {
    if (seconds_since(t0) > seconds) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return true;
}

// A 2D block at rest in a 20 x 20 grid (32 x 32 particles, nothing moves), run
// for `steps` steps with an output step every `every`: a run that lasts as
// long as a test needs it to and writes all the while.
std::string resting_block(std::int64_t steps, std::int64_t every, int particles_per_cell = 2) {
  return R"(name = "resting_block"
[analysis]
dimension = 2
dt = 1e-4
steps = )" + std::to_string(steps) +
         R"(
[grid]
cell_size = 0.05
cells = [20, 20]
[materials.soft]
type = "linear_elastic"
density = 1000.0
youngs_modulus = 1e6
poisson_ratio = 0.3
[[bodies]]
material = "soft"
min = [0.1, 0.1]
max = [0.9, 0.9]
particles_per_cell = )" + std::to_string(particles_per_cell) +
         R"(
[output]
every = )" + std::to_string(every) + "\n";
}

// Whether process `pid` runs flowmpm and has installed its handlers for
// SIGINT and SIGTERM (the SigCgt mask of /proc/PID/status, bit n - 1 for
// signal n). Until exec the child is a copy of this test program, whose
// doctest catches both too.
bool catches_interrupts(pid_t pid) {
  const fs::path proc = "/proc/" + std::to_string(pid);
  std::error_code error;
  if (fs::read_symlink(proc / "exe", error) != fs::canonical(FLOWMPM_EXECUTABLE)) return false;
  std::ifstream status(proc / "status");
  for (std::string line; std::getline(status, line);) {
    if (!line.starts_with("SigCgt:")) continue;
    const unsigned long long mask = std::stoull(line.substr(7), nullptr, 16);
    return (mask >> (SIGINT - 1) & 1) && (mask >> (SIGTERM - 1) & 1);
  }
  return false;
}

// Whether the HDF5 file at `path` opens and its root group carries a
// numeric attribute `attribute`.
bool opens_with(const fs::path& path, const char* attribute) {
  const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (file < 0) return false;
  const bool has = H5Aexists_by_name(file, "/", attribute, H5P_DEFAULT) > 0;
  H5Fclose(file);
  return has;
}

// The steps that results.h5 links ("00000010", ...) and whether each one's
// file opens as a step; nullopt if results.h5 does not open.
std::optional<std::vector<std::pair<std::string, bool>>> h5_steps(const fs::path& path) {
  const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (file < 0) return std::nullopt;
  std::vector<std::pair<std::string, bool>> steps;
  const hid_t group = H5Gopen2(file, "/steps", H5P_DEFAULT);
  if (group >= 0) {
    H5G_info_t info;
    H5Gget_info(group, &info);
    for (hsize_t i = 0; i < info.nlinks; ++i) {
      char name[64] = {};
      H5Lget_name_by_idx(group, ".", H5_INDEX_NAME, H5_ITER_INC, i, name, sizeof name, H5P_DEFAULT);
      steps.emplace_back(name, opens_with(path.parent_path() / "steps" / (std::string(name) + ".h5"), "step") &&
                                   H5Aexists_by_name(group, name, "time", H5P_DEFAULT) > 0);
    }
    H5Gclose(group);
  }
  H5Fclose(file);
  return steps;
}

// The step groups that results.xdmf refers to ("00000010", ...).
std::vector<std::string> xdmf_steps(const fs::path& path) {
  const std::string text = read_text(path);
  static const std::regex step(R"(steps/(\d{8})\.h5:/position)");
  std::vector<std::string> steps;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), step); it != std::sregex_iterator(); ++it)
    steps.push_back((*it)[1]);
  return steps;
}

// Every output file of a directory is whole: results.h5 opens and each step
// it links opens, every step file in steps/ opens, results.xdmf names only
// steps results.h5 links, and summary.json (if any) is a closed JSON object.
void check_readable(const fs::path& dir) {
  INFO("output directory " << dir.string());
  const auto steps = h5_steps(dir / "results.h5");
  REQUIRE_MESSAGE(steps.has_value(), "results.h5 does not open");
  for (const auto& [name, complete] : *steps) CHECK_MESSAGE(complete, "step " << name << " does not read");
  static const std::regex step_file(R"(\d{8}\.h5)");
  for (const auto& entry : fs::directory_iterator(dir / "steps")) {
    const std::string name = entry.path().filename().string();
    if (std::regex_match(name, step_file)) CHECK_MESSAGE(opens_with(entry.path(), "step"), name << " does not open");
  }
  if (fs::exists(dir / "results.xdmf")) {
    for (const std::string& s : xdmf_steps(dir / "results.xdmf")) {
      const bool present =
          std::ranges::any_of(*steps, [&](const auto& step) { return step.first == s && step.second; });
      CHECK_MESSAGE(present, "results.xdmf names step " << s << ", which results.h5 does not link");
    }
  }
  if (fs::exists(dir / "summary.json")) {
    const std::string summary = read_text(dir / "summary.json");
    CHECK(summary.starts_with("{"));
    CHECK(summary.ends_with("}\n"));
  }
}

std::string summary_status(const fs::path& dir) {
  static const std::regex status(R"re("status": "([^"]*)")re");
  std::smatch m;
  const std::string text = read_text(dir / "summary.json");
  return std::regex_search(text, m, status) ? m[1].str() : std::string();
}

// The lines of `output` that the program logged as errors, or printed
// without a log prefix.
std::vector<std::string> error_lines(const std::string& output) {
  std::vector<std::string> lines;
  for (const std::string& line : non_empty_lines(output))
    if (contains(line, "error") || contains(line, "flowmpm:")) lines.push_back(line);
  return lines;
}

// Runs the program under /bin/sh with `prelude` (e.g. "ulimit -v 400000")
// before it.
Result run_flowmpm_after(const std::string& prelude, const std::vector<std::string>& args, const fs::path& cwd) {
  std::vector<std::string> argv{"/bin/sh", "-c", prelude + "; exec \"$0\" \"$@\"", FLOWMPM_EXECUTABLE};
  argv.insert(argv.end(), args.begin(), args.end());
  return wait_for(start_program(argv, cwd));
}

// Whether a command can mount a tmpfs of its own (a private mount namespace,
// as root or in a user namespace).
bool can_mount_tmpfs(const fs::path& dir) {
  fs::create_directories(dir / "probe");
  const Result r = wait_for(start_program(
      {"/usr/bin/unshare", "--user", "--map-root-user", "--mount", "/bin/sh", "-c",
       "mount -t tmpfs -o size=64k tmpfs \"$0\" && echo mounted", (dir / "probe").string()},
      dir));
  return r.status == 0 && contains(r.output, "mounted");
}

}  // namespace

// 1 and 4: one run owns an output directory; a stale summary never labels
// new results; stale temporaries are removed.
TEST_CASE("a second run into a directory in use is refused at once and changes nothing") {
  TempDir dir("flowmpm_test_robust");
  write_text(dir.path / "long.toml", resting_block(1000000, 20));
  const fs::path out = dir.path / "out";
  const Running first = start_program({FLOWMPM_EXECUTABLE, "run", "long.toml", "--threads", "1", "--output",
                                       out.string()},
                                      dir.path);
  // The first run holds the lock and has written some steps.
  REQUIRE(wait_until([&] { return fs::exists(out / "flowmpm.lock") && fs::exists(out / "results.xdmf"); }, 30));

  const auto t0 = Clock::now();
  const Result second = run_flowmpm({"run", "long.toml", "--threads", "1", "--output", out.string()}, dir.path);
  const double refused_after = seconds_since(t0);
  INFO("second run printed:\n" << second.output);
  CHECK(second.status == 1);
  CHECK(error_lines(second.output).size() == 1);
  CHECK(contains(second.output, "output directory " + out.string() + " is in use by another flowmpm run"));
  CHECK(contains(second.output, "process " + std::to_string(first.pid)));
  CHECK(refused_after < 5.0);  // at once: no model built (the bound is loose for a loaded machine)

  ::kill(first.pid, SIGINT);
  const Result finished = wait_for(first);
  INFO("first run printed:\n" << finished.output);
  CHECK(finished.status == 130);
  CHECK(summary_status(out).starts_with("interrupted at step"));
  check_readable(out);
  // The lock file goes with the run that held it.
  CHECK(!fs::exists(out / "flowmpm.lock"));
}

TEST_CASE("a run killed with SIGKILL leaves whole files and no lock, and the next run takes the directory") {
  TempDir dir("flowmpm_test_robust");
  // The long case writes an output step (about 90 kB) at every step, so a
  // kill almost always lands while a step is being written.
  write_text(dir.path / "long.toml", resting_block(1000000, 1));
  write_text(dir.path / "short.toml", resting_block(40, 20, 1));
  const fs::path out = dir.path / "out";

  // A completed run of the short case, whose summary says "completed".
  REQUIRE(run_flowmpm({"run", "short.toml", "--output", out.string()}, dir.path).status == 0);
  REQUIRE(summary_status(out) == "completed");
  REQUIRE(contains(read_text(out / "summary.json"), "\"particles\": 256"));

  // Runs of the long case, killed at different moments once they write
  // output steps. Every file left is whole: each step file is written under
  // a temporary name and renamed when complete, and the indexes are replaced
  // the same way. (With one results.h5 written in place, 1 kill in 40 left
  // it unreadable: a process killed while HDF5 flushed its metadata.)
  for (int kill = 0; kill < 6; ++kill) {
    CAPTURE(kill);
    fs::remove(out / "timeseries.csv");  // so that only the new run's rows count
    const Running killed = start_program({FLOWMPM_EXECUTABLE, "run", "long.toml", "--output", out.string()}, dir.path);
    const std::size_t rows = 5 + 7 * static_cast<std::size_t>(kill);
    REQUIRE(wait_until(
        [&] {
          if (!fs::exists(out / "timeseries.csv")) return false;
          const std::string text = read_text(out / "timeseries.csv");
          return static_cast<std::size_t>(std::ranges::count(text, '\n')) > rows;
        },
        30));
    std::this_thread::sleep_for(std::chrono::milliseconds(3 * kill));
    ::kill(killed.pid, SIGKILL);
    CHECK(wait_for(killed).status == 128 + SIGKILL);
    // The directory says that a run started and did not end, with the new
    // run's figures: never the earlier run's "completed".
    CHECK(summary_status(out) == "running");
    CHECK(contains(read_text(out / "summary.json"), "\"particles\": 1024"));
    CHECK(read_text(out / "results.xdmf").ends_with("</Xdmf>\n"));
    check_readable(out);
    const auto steps = h5_steps(out / "results.h5");
    CHECK(steps->size() >= 1);  // the index was written after the first step
  }

  // Temporary files as a run killed in the middle of an atomic write leaves them.
  write_text(out / "summary.json.tmp-99999-0", "{");
  write_text(out / "results.xdmf.tmp-99999-3", "<Xdmf");
  write_text(out / "steps" / "00000007.h5.tmp-99999-4", "HDF");
  const Result next = run_flowmpm({"run", "short.toml", "--output", out.string()}, dir.path);
  INFO(next.output);
  CHECK(next.status == 0);
  CHECK(summary_status(out) == "completed");
  CHECK(!fs::exists(out / "summary.json.tmp-99999-0"));
  CHECK(!fs::exists(out / "results.xdmf.tmp-99999-3"));
  CHECK(!fs::exists(out / "steps" / "00000007.h5.tmp-99999-4"));
  check_readable(out);
  // Only the new run's steps: 0, 20 and 40.
  CHECK(h5_steps(out / "results.h5")->size() == 3);
  CHECK(std::distance(fs::directory_iterator(out / "steps"), fs::directory_iterator()) == 3);
}

TEST_CASE("a run does not disturb the earlier results that a reader has open") {
  TempDir dir("flowmpm_test_robust");
  write_text(dir.path / "short.toml", resting_block(40, 20, 1));
  // The same block moving at 0.5 m/s: 2 mm further at step 40.
  std::string moving = resting_block(40, 20, 1);
  moving.replace(moving.find("particles_per_cell = 1\n"), 23, "particles_per_cell = 1\nvelocity = [0.5, 0.0]\n");
  write_text(dir.path / "moving.toml", moving);
  const fs::path out = dir.path / "out";
  REQUIRE(run_flowmpm({"run", "short.toml", "--output", out.string()}, dir.path).status == 0);

  // A reader (as h5py would) holds the first run's last step open while a
  // second run writes into the same directory.
  const auto read_position = [](hid_t dataset) {
    std::vector<double> position(256 * 3);
    CHECK(H5Dread(dataset, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, position.data()) >= 0);
    return position;
  };
  const hid_t reader = H5Fopen((out / "results.h5").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  REQUIRE(reader >= 0);
  const hid_t dataset = H5Dopen2(reader, "/steps/00000040/position", H5P_DEFAULT);
  REQUIRE(dataset >= 0);
  const std::vector<double> first = read_position(dataset);
  CHECK(first[0] > 0.1);  // the first particle, inside the block

  const Result second = run_flowmpm({"run", "moving.toml", "--output", out.string()}, dir.path);
  INFO(second.output);
  CHECK(second.status == 0);
  // The reader still reads the first run's step; the new files are whole
  // and hold the second run's.
  CHECK(read_position(dataset) == first);
  H5Dclose(dataset);
  H5Fclose(reader);
  check_readable(out);
  const hid_t now = H5Fopen((out / "results.h5").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  const hid_t moved = H5Dopen2(now, "/steps/00000040/position", H5P_DEFAULT);
  REQUIRE(moved >= 0);
  CHECK(read_position(moved)[0] == doctest::Approx(first[0] + 0.002).epsilon(1e-6));
  H5Dclose(moved);
  H5Fclose(now);
}

TEST_CASE("a case that fails its checks leaves the directory's earlier results untouched") {
  TempDir dir("flowmpm_test_robust");
  // The elastic-wave bar with its probe beyond the last particle: the
  // reference's own check, when the model is built, rejects it.
  const std::string wave = read_text(fs::path(FLOWMPM_SOURCE_DIR) / "configs/verification/elastic_wave.toml");
  write_text(dir.path / "wave.toml", wave);
  std::string bad = wave;
  bad.replace(bad.find("probe = 0.5"), 11, "probe = 0.999");
  write_text(dir.path / "bad.toml", bad);
  const fs::path out = dir.path / "out";
  REQUIRE(run_flowmpm({"run", "wave.toml", "--output", out.string()}, dir.path).status == 0);
  const std::string log = read_text(out / "run.log"), summary = read_text(out / "summary.json");

  for (const std::string command : {"check", "run"}) {
    const Result r = run_flowmpm({command, "bad.toml", "--output", out.string()}, dir.path);
    INFO(command << " printed:\n" << r.output);
    CHECK(r.status == 1);
    CHECK(contains(r.output, "needs a particle on each side"));
  }
  CHECK(read_text(out / "run.log") == log);
  CHECK(read_text(out / "summary.json") == summary);
  check_readable(out);
}

// 2 and 3: every number read is one the engine can represent.
TEST_CASE("integers beyond 2^53, absurd magnitudes and overflowing step counts are rejected") {
  const std::string base = read_text(fs::path(FLOWMPM_SOURCE_DIR) / "configs/uniaxial_stress/case1_usl.toml");
  const auto rejected = [&](const std::vector<std::string>& overrides, const std::string& key,
                            const std::string& expected) {
    INFO("overrides " << overrides.front());
    try {
      case_from_text("robust_numbers", base, overrides);
      FAIL("accepted");
    } catch (const CaseError& e) {
      const std::string message = e.what();
      INFO(message);
      CHECK(contains(message, "--set " + overrides.front()));  // where the value came from
      CHECK(contains(message, key));
      CHECK(contains(message, expected));
    }
  };
  rejected({"node_sets.0.velocity={ y = 9007199254740993 }"}, "node_sets[0].velocity.y", "2^53");
  rejected({"analysis.dt=-9223372036854775808"}, "analysis.dt", "2^53");
  rejected({"bodies.0.max=[9223372036854775807, 1.0, 1.0]"}, "bodies[0].max", "2^53");
  rejected({"materials.elastic.youngs_modulus=9223372036854775807"}, "materials.elastic.youngs_modulus", "2^53");
  rejected({"materials.elastic.youngs_modulus=1e-308"}, "materials.elastic.youngs_modulus", "1e-100");
  rejected({"analysis.dt=1e-300"}, "analysis.dt", "1e-100");
  // end_time / dt = 1e19 would overflow a 64-bit step count.
  rejected({"analysis.end_time=1e17"}, "analysis.end_time", "at most 10^10 steps");
  rejected({"analysis.dimension=4294967298"}, "analysis.dimension", "1, 2 or 3");
  // A count of steps beyond the stated maximum.
  std::string by_steps = base;
  by_steps.replace(by_steps.find("end_time = 0.1"), 14, "steps = 20000000000");
  CHECK_THROWS_WITH_AS(case_from_text("robust_steps", by_steps), doctest::Contains("at most 10^10"), CaseError);
  // The largest exact integers are still numbers.
  CHECK_NOTHROW(case_from_text("robust_numbers", base, {"materials.elastic.density=9007199254740992"}));
}

TEST_CASE("an absurd case is rejected by check and run alike, in one line naming the key") {
  TempDir dir("flowmpm_test_robust");
  const std::string base = read_text(fs::path(FLOWMPM_SOURCE_DIR) / "configs/uniaxial_stress/case1_usl.toml");
  write_text(dir.path / "case.toml", base);
  const auto rejected = [&](const std::string& set, const std::string& expected) {
    for (const std::string command : {"check", "run"}) {
      const Result r =
          run_flowmpm({command, "case.toml", "--set", set, "--output", (dir.path / "out").string()}, dir.path);
      INFO(command << " --set " << set << " printed:\n" << r.output);
      CHECK(r.status == 1);
      CHECK(non_empty_lines(r.output).size() == 1);
      CHECK(contains(r.output, expected));
      CHECK(!fs::exists(dir.path / "out"));
    }
  };
  // 11: the smaller points.
  rejected("bodies.0.max=[1.0, 1e-9, 1.0]", "bodies[0].max: expected a box at least one particle spacing");
  rejected("reference={ type = \"uniaxial_stress\", axis = \"y\", length = 1e308, velocity = -0.01 }",
           "reference.length");
  rejected("node_sets.0.velocity={}", "node_sets[0].velocity: expected a velocity for at least one axis");
  rejected("output.every=0", "output.every: expected a number of steps >= 1");
  rejected("name=\"../../etc/passwd\"", "name: expected a name that can be a directory's");
  rejected("output.directory=\"results/a\\u0000b\"", "output.directory: expected a path without control characters");
}

// 5: a sweep case that fails while its model is built gets its row.
TEST_CASE("a sweep case that fails while its model is built gets its row and the rest run") {
  TempDir dir("flowmpm_test_robust");
  // A 1D bar filling its grid: linear shape functions reach it, uGIMP needs
  // a cell beyond it, which only building the model finds.
  write_text(dir.path / "bar.toml", R"(name = "edge_bar"
[analysis]
dimension = 1
dt = 1e-3
steps = 5
[grid]
cell_size = 0.1
cells = [10]
[materials.bar]
type = "linear_elastic"
density = 1.0
youngs_modulus = 100.0
poisson_ratio = 0.0
[[bodies]]
material = "bar"
min = [0.0]
max = [1.0]
particles_per_cell = 2
)");
  write_text(dir.path / "sweep.toml", R"(base = "bar.toml"
output = "sweep_out"
[vary]
"analysis.shape_function" = ["linear", "gimp", "linear"]
)");
  const Result r = run_flowmpm({"sweep", "sweep.toml", "--threads", "1"}, dir.path);
  INFO(r.output);
  CHECK(r.status == 2);  // a case failed, after all ran
  const std::vector<std::string> rows = lines_of(read_text(dir.path / "sweep_out/sweep.csv"));
  REQUIRE(rows.size() == 4);
  CHECK(rows[1].starts_with("000,linear,completed"));
  CHECK(rows[2].starts_with("001,gimp,failed"));
  CHECK(contains(rows[2], "outermost cells"));
  CHECK(rows[3].starts_with("002,linear,completed"));
  CHECK(contains(read_text(dir.path / "sweep_out/cases/001/sweep_row.txt"), "failed"));
}

// 6 and 7: memory the case needs, and what happens when it is not there.
TEST_CASE("a case estimated to need more memory than allowed is an error naming the figure and the keys") {
  TempDir dir("flowmpm_test_robust");
  std::string base = read_text(fs::path(FLOWMPM_SOURCE_DIR) / "configs/uniaxial_stress/case1_usl.toml");
  write_text(dir.path / "case.toml", base);
  base.replace(base.find("particles_per_cell = 2"), 22, "spacing = 0.5");
  write_text(dir.path / "spaced.toml", base);
  const auto rejected = [&](const std::string& file, const std::vector<std::string>& extra, const std::string& key) {
    for (const std::string command : {"check", "run"}) {
      std::vector<std::string> args{command, file, "--output", (dir.path / "out").string()};
      args.insert(args.end(), extra.begin(), extra.end());
      const auto t0 = Clock::now();
      const Result r = run_flowmpm(args, dir.path);
      INFO(command << " " << extra[1] << " printed:\n" << r.output);
      CHECK(r.status == 1);
      CHECK(non_empty_lines(r.output).size() == 1);
      CHECK(contains(r.output, key));
      CHECK(contains(r.output, "a case that fits in memory: it needs about"));
      CHECK(seconds_since(t0) < 10.0);  // nothing is built (the bound is loose for a loaded machine)
      CHECK(!fs::exists(dir.path / "out"));
    }
  };
  // 401^3 grid nodes, about 7.7 GB: above a 2 GB limit.
  rejected("case.toml", {"--set", "grid.cells=[400, 400, 400]", "--max-memory", "2G"}, "grid.cells");
  // 10^15 cells: above any machine (this made `check` abort with std::bad_alloc).
  rejected("case.toml", {"--set", "grid.cells=[100000, 100000, 100000]"}, "grid.cells");
  // A spacing of 1 um fills the 1 m block with 10^18 particles.
  rejected("spaced.toml", {"--set", "bodies.0.spacing=1e-6"}, "bodies[0].spacing");
}

TEST_CASE("the memory estimate matches the peak a run takes") {
  if (address_sanitizer) return;
  // 3D block of 64^3 = 262,144 particles in a 40^3 grid, default output fields.
  TempDir dir("flowmpm_test_robust");
  const std::string text = R"(name = "memory_block"
[analysis]
dimension = 3
dt = 1e-4
steps = 2
[grid]
cell_size = 0.025
cells = [40, 40, 40]
[materials.soft]
type = "linear_elastic"
density = 1000.0
youngs_modulus = 1e6
poisson_ratio = 0.3
[[bodies]]
material = "soft"
min = [0.1, 0.1, 0.1]
max = [0.9, 0.9, 0.9]
spacing = 0.0125
)";
  write_text(dir.path / "block.toml", text);
  const MemoryEstimate e = estimate_memory(case_from_text("memory_block", text));
  CHECK(e.particles == doctest::Approx(262144));
  CHECK(e.nodes == doctest::Approx(41.0 * 41 * 41));

  const Result run = run_flowmpm({"run", "block.toml", "--threads", "2", "--output", (dir.path / "out").string()},
                                 dir.path);
  INFO(run.output);
  CHECK(run.status == 0);
  const double peak = run.peak_resident_bytes;
  MESSAGE("estimate " << memory_text(e.total_bytes) << ", peak resident " << memory_text(peak));
  // The estimate counts the arrays held at peak; the resident size also has
  // allocator slack and pages the kernel has not reclaimed. Within 30 %
  // either way is close enough to tell a case that fits from one that
  // does not (the check compares against the available memory).
  CHECK(peak > 0.7 * e.total_bytes);
  CHECK(peak < 1.3 * e.total_bytes);
}

TEST_CASE("running out of memory is one line and a failure status, never an abort") {
  if (address_sanitizer) return;
  TempDir dir("flowmpm_test_robust");
  // 2.56 million particles (about 0.6 GB to build, 1.5 GB to run) with the
  // address space limited to 400 MB and the estimate's limit lifted:
  // std::bad_alloc while the model is built.
  std::string big = resting_block(10, 5);
  big.replace(big.find("particles_per_cell = 2"), 22, "spacing = 0.0005");
  write_text(dir.path / "big.toml", big);
  for (const std::string command : {"check", "run"}) {
    const Result r = run_flowmpm_after(
        "ulimit -v 400000", {command, "big.toml", "--max-memory", "100G", "--output", (dir.path / "out").string()},
        dir.path);
    INFO(command << " printed:\n" << r.output);
    CHECK(r.status == 2);
    CHECK(error_lines(r.output).size() == 1);
    CHECK(contains(r.output, "out of memory"));
  }
}

TEST_CASE("Ctrl-C or SIGTERM while the model is built ends the program within a second") {
  TempDir dir("flowmpm_test_robust");
  // 400 node sets, each selected from the 10^6 nodes of a 1000 x 1000
  // grid: seconds of building for little memory.
  std::string text = R"(name = "slow_build"
[analysis]
dimension = 2
dt = 1e-5
steps = 10
[grid]
cell_size = 0.001
cells = [1000, 1000]
[materials.soft]
type = "linear_elastic"
density = 1000.0
youngs_modulus = 1e6
poisson_ratio = 0.3
[[bodies]]
material = "soft"
min = [0.1, 0.1]
max = [0.2, 0.2]
particles_per_cell = 1
)";
  for (int k = 0; k < 400; ++k) {
    text += "[[node_sets]]\nmin = [0.5, 0.5]\nmax = [0.51, 0.51]\nvelocity = { x = 0.0 }\n";
  }
  write_text(dir.path / "slow.toml", text);
  for (const int signal : {SIGINT, SIGTERM}) {
    const fs::path out = dir.path / "out";
    const Running p = start_program({FLOWMPM_EXECUTABLE, "run", "slow.toml", "--output", out.string()}, dir.path);
    // Once its handlers are in place (a slow start, as under the sanitizers,
    // would otherwise meet the signal's default action), the case is read
    // within milliseconds and the build takes seconds.
    REQUIRE(wait_until([&] { return catches_interrupts(p.pid); }, 30));
    std::this_thread::sleep_for(std::chrono::milliseconds(300));  // read, now building
    const auto t0 = Clock::now();
    ::kill(p.pid, signal);
    const Result r = wait_for(p);
    const double took = seconds_since(t0);
    INFO("signal " << signal << "; printed:\n" << r.output);
    CHECK(r.status == 130);
    CHECK(took < 1.0);
    CHECK(contains(r.output, "interrupted before anything was written"));
    CHECK(!fs::exists(out));
  }
}

// 8: a full disk.
TEST_CASE("a full disk ends the run with one line naming the file, and what was written stays readable") {
  TempDir dir("flowmpm_test_robust");
  // 1600 particles, an output step (about 300 kB) every 5 steps.
  write_text(dir.path / "case.toml", resting_block(200, 5));
  const fs::path keep = dir.path / "kept";
  Result r;
  std::string expected;
  if (can_mount_tmpfs(dir.path)) {
    // A 2 MB file system of its own: full after a few output steps.
    const fs::path mount = dir.path / "disk";
    fs::create_directories(mount);
    const std::string script =
        "mount -t tmpfs -o size=2m tmpfs \"$0\" || exit 99; \"$1\" run case.toml --output \"$0/out\"; status=$?; "
        "cp -a \"$0/out\" \"$2\"; exit $status";
    r = wait_for(start_program({"/usr/bin/unshare", "--user", "--map-root-user", "--mount", "/bin/sh", "-c", script,
                                mount.string(), FLOWMPM_EXECUTABLE, keep.string()},
                               dir.path));
    expected = "No space left on device";
  } else {
    MESSAGE("skipped: no private tmpfs can be mounted here (unshare --user --mount)");
    return;
  }
  INFO(r.output);
  REQUIRE(r.status != 99);
  CHECK(r.status == 2);
  const std::vector<std::string> errors = error_lines(r.output);
  CHECK(errors.size() == 1);
  CHECK(contains(r.output, expected));
  CHECK(std::regex_search(r.output, std::regex("steps/\\d{8}\\.h5|results\\.h5|timeseries\\.csv|results\\.xdmf")));
  check_readable(keep);
  const auto steps = h5_steps(keep / "results.h5");
  REQUIRE(steps);
  CHECK(steps->size() >= 1);  // the steps before the disk filled
  CHECK(steps->size() < 41);  // and not all of them
}

// 10: the output's cost and memory do not grow with the run. The XDMF index
// was rewritten in full at every output step (the cost of a step grew with
// the number written before it) and built as one string, and HDF5's
// metadata cache grew to 32 MiB: about 20-40 kB of resident memory per
// output step.
TEST_CASE("output cost per step and resident memory stay flat over a 100,000-step run") {
  if (address_sanitizer) return;
  TempDir dir("flowmpm_test_robust");
  // A 1D bar of 32 particles in uniform motion, an output step every 100
  // steps: 10,000 steps (101 output steps) against 100,000 (1,001, the run
  // of the finding).
  const auto bar = [](int steps) {
    return R"(name = "long_bar"
[analysis]
dimension = 1
dt = 1e-5
steps = )" + std::to_string(steps) +
           R"(
[grid]
cell_size = 0.05
cells = [20]
[materials.soft]
type = "linear_elastic"
density = 1000.0
youngs_modulus = 1e6
poisson_ratio = 0.0
[[bodies]]
material = "soft"
min = [0.1]
max = [0.9]
particles_per_cell = 2
velocity = [0.01]
[output]
every = 100
fields = ["position"]
)";
  };
  struct Measured {
    double peak_bytes = 0.0, seconds_per_output = 0.0;
  };
  const auto measure = [&](int steps) {
    const std::string name = "bar" + std::to_string(steps);
    write_text(dir.path / (name + ".toml"), bar(steps));
    const fs::path out = dir.path / name;
    const std::size_t output_steps = static_cast<std::size_t>(steps / 100 + 1);
    const Result run = run_flowmpm({"run", name + ".toml", "--threads", "1", "--output", out.string()}, dir.path);
    INFO(run.output);
    REQUIRE(run.status == 0);
    check_readable(out);
    CHECK(xdmf_steps(out / "results.xdmf").size() == output_steps);
    static const std::regex seconds(R"re("output_seconds": ([0-9.eE+-]+))re");
    std::smatch m;
    const std::string summary = read_text(out / "summary.json");
    REQUIRE(std::regex_search(summary, m, seconds));
    return Measured{run.peak_resident_bytes, std::stod(m[1].str()) / static_cast<double>(output_steps)};
  };
  const Measured shorter = measure(10000), longer = measure(100000);
  MESSAGE("101 output steps: peak resident " << shorter.peak_bytes / 1e6 << " MB, " << shorter.seconds_per_output * 1e3
                                            << " ms per output step; 1,001: " << longer.peak_bytes / 1e6 << " MB, "
                                              << longer.seconds_per_output * 1e3 << " ms");
  // Measured on 2 cores: 20.8 and 20.8 MB, 0.94 and 0.90 ms (a step file
  // created, flushed to disk and renamed). Rewriting the indexes at every
  // step would make the longer run's mean cost about ten times the
  // shorter's; the bounds leave room for a loaded machine.
  CHECK(longer.peak_bytes - shorter.peak_bytes < 5e6);
  CHECK(longer.seconds_per_output < 4.0 * shorter.seconds_per_output);
}

// 11: a read-only output directory gives one exit status, whether or not it
// exists.
TEST_CASE("a read-only output directory is exit status 1, whether or not the directory exists") {
  TempDir dir("flowmpm_test_robust");
  write_text(dir.path / "case.toml", resting_block(10, 5, 1));
  const fs::path ro = dir.path / "ro";
  fs::create_directories(ro / "exists");
  std::vector<std::string> prefix;
  if (::geteuid() != 0) {
    fs::permissions(ro, fs::perms::owner_read | fs::perms::owner_exec);
    fs::permissions(ro / "exists", fs::perms::owner_read | fs::perms::owner_exec);
  } else if (can_mount_tmpfs(dir.path)) {
    // Root writes wherever the file system allows: the directory is made a
    // read-only bind mount of itself, in a mount namespace of its own.
    prefix = {"/usr/bin/unshare", "--user", "--map-root-user", "--mount", "/bin/sh", "-c",
              "mount --bind \"$0\" \"$0\" && mount -o remount,bind,ro \"$0\" || exit 99; exec \"$@\"",
              ro.string()};
  } else {
    MESSAGE("running as root without a mount namespace: no read-only directory to test with");
    return;
  }
  for (const std::string target : {"exists", "missing"}) {
    for (const std::string command : {"check", "run"}) {
      std::vector<std::string> argv = prefix;
      argv.insert(argv.end(), {FLOWMPM_EXECUTABLE, command, "case.toml", "--output", (ro / target).string()});
      const Result r = wait_for(start_program(argv, dir.path));
      INFO(command << " into " << target << ": " << r.output);
      REQUIRE(r.status != 99);
      CHECK(r.status == 1);
      CHECK(non_empty_lines(r.output).size() == 1);
      CHECK(contains(r.output, "output directory " + (ro / target).string()));
    }
  }
  fs::permissions(ro, fs::perms::owner_all);
  fs::permissions(ro / "exists", fs::perms::owner_all);
}
