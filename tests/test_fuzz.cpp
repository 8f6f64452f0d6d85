// A deterministic fuzz test of the case reader and the run (issue 15): the
// shipped cases, mutated a few hundred times by a fixed-seed generator
// (values replaced by extreme or ill-typed ones, keys removed, lines
// deleted, duplicated or cut), each given to `flowmpm check` and to a short
// `flowmpm run`. Every process must end by itself with exit status 0, 1 or
// 2 (never a signal: no abort, no crash, no sanitizer report, which ends the
// process with a signal or status 1 only when asked to), within a deadline;
// a run still going after 2 s (FLOWMPM_FUZZ_INTERRUPT_AFTER, which the
// sanitizer job raises) must stop within 2 s of Ctrl-C with status 130. `check` and `run` must agree on whether the case is valid, a run
// that exits 1 must have written nothing, and one that exits 0 must have
// run at least a step. The counts are printed.
#include <doctest/doctest.h>
#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <toml++/toml.h>

#include "run_program.hpp"

namespace fs = std::filesystem;
using namespace flowmpm::testing;
using Clock = std::chrono::steady_clock;

namespace {

// The shipped cases that run in well under a second each.
const char* const shipped[] = {
    "uniaxial_stress/case1_usl.toml",      "uniaxial_stress/case2_usf.toml",
    "uniaxial_stress/case3_musl.toml",     "verification/elastic_wave.toml",
    "verification/bar_vibration_small.toml", "materials/von_mises_bar.toml",
    "materials/strain_softening_bar.toml", "materials/orthotropic_thermal_block.toml",
    "materials/transversely_isotropic_lamina.toml",
};

// Values a mutation puts in place of another: extremes, wrong types,
// empty containers, paths that escape.
const char* const replacements[] = {
    "0", "-1", "1", "2", "0.5", "-0.0", "1e308", "-1e308", "1e-308", "5e-324", "1e17", "1e-300", "1e100",
    "9007199254740993", "9223372036854775807", "-9223372036854775808", "1000000", "nan", "inf", "-inf",
    "\"\"", "\"../../etc/passwd\"", "\"a\\u0000b\"", "\"auto\"", "\"gimp\"", "\"bspline3\"", "\"musl\"",
    "\"von_mises\"", "\"y\"", "\"\\u00fc\"", "true", "[]", "[0]", "[1e308, 1e308, 1e308]",
    "[100000, 100000, 100000]", "[1, 2, 3, 4]", "[\"a\"]", "[[0.0, 1.0], [0.5, 2.0]]", "{}", "{ y = 0.0 }",
    "{ x = 1e308 }", "[0.0, 0.0, 0.0]", "[-1.0, -1.0, -1.0]", "[1e-9, 1e-9, 1e-9]",
};

struct Rng {
  std::mt19937_64 engine;  // its sequence is fixed by the C++ standard
  std::size_t below(std::size_t n) { return static_cast<std::size_t>(engine() % n); }
};

// Every leaf of a TOML tree (values and empty containers), with a way to
// replace or remove it.
struct Leaf {
  toml::node* parent;
  std::string key;    // in a table
  std::size_t index;  // in an array
};

void leaves_of(toml::node& node, std::vector<Leaf>& out) {
  if (toml::table* t = node.as_table()) {
    for (auto&& [key, value] : *t) {
      if ((value.is_table() && !value.as_table()->empty()) || (value.is_array() && !value.as_array()->empty())) {
        leaves_of(value, out);
      }
      out.push_back({&node, std::string(key.str()), 0});
    }
  } else if (toml::array* a = node.as_array()) {
    for (std::size_t i = 0; i < a->size(); ++i) {
      toml::node& value = *a->get(i);
      if (value.is_table() || value.is_array()) leaves_of(value, out);
      out.push_back({&node, {}, i});
    }
  }
}

toml::table parse_value(const std::string& text) { return toml::parse("v = " + text); }

// Factors a number is scaled by: a case that is still plausible, but bigger,
// longer, stiffer, or of the other sign.
const double factors[] = {10.0, 0.1, 1000.0, 1e-3, -1.0, 1e6, 1e-6, 2.0, 0.5};

// One mutation of the document (structural) or of the text (textual).
std::string mutate(const std::string& text, Rng& rng) {
  const std::size_t kind = rng.below(12);
  if (kind >= 10) {
    // Scale 1 to 3 numbers.
    toml::table root = toml::parse(text);
    std::vector<Leaf> leaves, numbers;
    leaves_of(root, leaves);
    for (const Leaf& leaf : leaves) {
      const toml::node* n = leaf.parent->is_table() ? leaf.parent->as_table()->get(leaf.key)
                                                    : leaf.parent->as_array()->get(leaf.index);
      if (n && n->is_number()) numbers.push_back(leaf);
    }
    const int count = 1 + static_cast<int>(rng.below(3));
    for (int k = 0; k < count && !numbers.empty(); ++k) {
      const Leaf& leaf = numbers[rng.below(numbers.size())];
      const double f = factors[rng.below(std::size(factors))];
      if (toml::table* t = leaf.parent->as_table()) {
        const double v = t->get(leaf.key)->value_or(0.0);
        t->insert_or_assign(leaf.key, v * f);
      } else if (toml::array* a = leaf.parent->as_array()) {
        const double v = a->get(leaf.index)->value_or(0.0);
        a->replace(a->begin() + static_cast<std::ptrdiff_t>(leaf.index), v * f);
      }
    }
    std::ostringstream out;
    out << toml::toml_formatter{root} << "\n";
    return out.str();
  }
  if (kind < 7) {
    toml::table root = toml::parse(text);
    const int count = 1 + static_cast<int>(rng.below(3));
    for (int k = 0; k < count; ++k) {
      std::vector<Leaf> leaves;
      leaves_of(root, leaves);
      if (leaves.empty()) break;
      const Leaf leaf = leaves[rng.below(leaves.size())];
      const bool remove = kind == 6;
      if (toml::table* t = leaf.parent->as_table()) {
        if (remove) {
          t->erase(leaf.key);
        } else {
          t->insert_or_assign(leaf.key, *parse_value(replacements[rng.below(std::size(replacements))]).get("v"));
        }
      } else if (toml::array* a = leaf.parent->as_array()) {
        if (remove) {
          a->erase(a->begin() + static_cast<std::ptrdiff_t>(leaf.index));
        } else {
          const toml::table v = parse_value(replacements[rng.below(std::size(replacements))]);
          a->replace(a->begin() + static_cast<std::ptrdiff_t>(leaf.index), *v.get("v"));
        }
      }
    }
    std::ostringstream out;
    out << toml::toml_formatter{root} << "\n";
    return out.str();
  }
  std::vector<std::string> lines = lines_of(text);
  const std::size_t n = rng.below(lines.size());
  if (kind == 7) {
    lines.erase(lines.begin() + static_cast<std::ptrdiff_t>(n));
  } else if (kind == 8) {
    lines.insert(lines.begin() + static_cast<std::ptrdiff_t>(n), lines[n]);
  } else {
    std::string joined;
    for (const std::string& line : lines) joined += line + "\n";
    return joined.substr(0, rng.below(joined.size()));
  }
  std::string joined;
  for (const std::string& line : lines) joined += line + "\n";
  return joined;
}

struct Outcome {
  int status = -1;   // exit status, or -1 if ended by a signal
  int signal = 0;    // the signal that ended it
  bool interrupted = false;  // we sent SIGINT
  bool hung = false;         // killed at the deadline
  std::string output;
};

// Runs argv in cwd with stdout and stderr to a file; sends SIGINT after
// `interrupt_after` s (if > 0) and SIGKILL `grace` s later (or after
// `interrupt_after` alone when it is 0, counting as a hang).
Outcome run_with_deadline(const std::vector<std::string>& argv, const fs::path& cwd, double interrupt_after,
                          double grace) {
  const fs::path log = cwd / "output.txt";
  std::vector<std::string> storage(argv);
  std::vector<char*> args;
  for (std::string& s : storage) args.push_back(s.data());
  args.push_back(nullptr);
  const int fd = ::open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  REQUIRE(fd >= 0);
  const pid_t pid = ::fork();
  REQUIRE(pid >= 0);
  if (pid == 0) {
    ::dup2(fd, STDOUT_FILENO);
    ::dup2(fd, STDERR_FILENO);
    if (::chdir(cwd.c_str()) != 0) ::_exit(126);
    ::execv(args[0], args.data());
    ::_exit(127);
  }
  ::close(fd);
  Outcome o;
  const auto t0 = Clock::now();
  int status = 0;
  for (;;) {
    const pid_t done = ::waitpid(pid, &status, WNOHANG);
    if (done == pid) break;
    const double t = std::chrono::duration<double>(Clock::now() - t0).count();
    if (!o.interrupted && interrupt_after > 0 && t > interrupt_after) {
      ::kill(pid, SIGINT);
      o.interrupted = true;
    } else if (t > interrupt_after + grace) {
      ::kill(pid, SIGKILL);
      ::waitpid(pid, &status, 0);
      o.hung = true;
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  if (WIFEXITED(status)) o.status = WEXITSTATUS(status);
  if (WIFSIGNALED(status)) o.signal = WTERMSIG(status);
  o.output = read_text(log);
  fs::remove(log);
  return o;
}

}  // namespace

TEST_CASE("fuzz: mutated shipped cases end with status 0, 1 or 2, never a signal or a hang") {
  // 300; the sanitizer job (scripts/test_sanitizers.sh) runs the first
  // FLOWMPM_FUZZ_MUTANTS of the same sequence, where every run is tens of
  // times slower.
  const char* subset = std::getenv("FLOWMPM_FUZZ_MUTANTS");
  const int mutants = subset ? std::clamp(std::atoi(subset), 1, 300) : 300;
  // Ctrl-C after 2 s; the sanitizer job waits longer, since there a process
  // can take more than 2 s to reach main() (its handler is installed first
  // thing there) and to read its case.
  const char* interrupt_env = std::getenv("FLOWMPM_FUZZ_INTERRUPT_AFTER");
  const double interrupt_after = interrupt_env ? std::clamp(std::atof(interrupt_env), 1.0, 60.0) : 2.0;
  Rng rng{std::mt19937_64(20260115)};
  TempDir dir("flowmpm_test_fuzz");
  std::vector<std::string> sources;
  for (const char* name : shipped) sources.push_back(read_text(fs::path(FLOWMPM_SOURCE_DIR) / "configs" / name));
  struct Mutant {
    std::size_t source;
    std::string text;
    Outcome check, run;
    std::vector<std::string> left;  // what the work directory holds after the run
    std::string summary;            // the run's summary.json
  };
  std::vector<Mutant> all;
  for (int m = 0; m < mutants; ++m) {
    const std::size_t source = rng.below(sources.size());
    all.push_back({source, mutate(sources[source], rng), {}, {}, {}, {}});
  }

  // Two at a time (the processes, not the assertions, run on the threads).
  std::atomic<std::size_t> next{0};
  const auto worker = [&] {
    for (std::size_t m; (m = next++) < all.size();) {
      Mutant& mutant = all[m];
      const fs::path work = dir.path / std::to_string(m);
      fs::create_directories(work);
      write_text(work / "case.toml", mutant.text);
      const fs::path out = work / "out";
      mutant.check = run_with_deadline({FLOWMPM_EXECUTABLE, "check", "case.toml", "--output", out.string()}, work,
                                       0.0, 60.0);
      mutant.run = run_with_deadline(
          {FLOWMPM_EXECUTABLE, "run", "case.toml", "--threads", "1", "--quiet", "--output", out.string()}, work,
          interrupt_after, 2.0);
      mutant.left = files_in(work);
      mutant.summary = read_text(out / "summary.json");
      fs::remove_all(work);
    }
  };
  std::thread other(worker);
  worker();
  other.join();

  std::map<std::string, int> counts;  // "check 0", "run 130", ...
  for (std::size_t m = 0; m < all.size(); ++m) {
    const Mutant& mutant = all[m];
    INFO("mutant " << m << " of " << shipped[mutant.source] << ":\n" << mutant.text);
    INFO("check printed:\n" << mutant.check.output);
    INFO("run printed:\n" << mutant.run.output);
    for (const Outcome* o : {&mutant.check, &mutant.run}) {
      CHECK_FALSE(o->hung);
      CHECK(o->signal == 0);
    }
    CHECK((mutant.check.status == 0 || mutant.check.status == 1 || mutant.check.status == 2));
    const int run = mutant.run.status;
    CHECK((run == 0 || run == 1 || run == 2 || (mutant.run.interrupted && run == 130)));
    // check and run agree on whether the case is valid (unless the run was
    // stopped by Ctrl-C, possibly before it had read the case).
    if (!(mutant.run.interrupted && run == 130)) CHECK((mutant.check.status == 1) == (run == 1));
    // Nothing written after exit 1.
    if (run == 1) CHECK(mutant.left == std::vector<std::string>{"case.toml"});
    // A run that says it succeeded ran: completed, at least one step (an
    // overflowing step count once ran none).
    if (run == 0) {
      CHECK(contains(mutant.summary, "\"status\": \"completed\""));
      CHECK_FALSE(contains(mutant.summary, "\"steps\": 0,"));
    }
    ++counts["check " + std::to_string(mutant.check.status)];
    ++counts["run " + std::to_string(run)];
  }
  std::string summary;
  for (const auto& [what, n] : counts) summary += (summary.empty() ? "" : ", ") + what + ": " + std::to_string(n);
  MESSAGE("fuzz: " << mutants << " mutants; " << summary);
}
