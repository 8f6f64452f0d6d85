// flowmpm sweep: how a sweep file expands (product order, zipped lists),
// and the program run on sweeps of the uniaxial stress case (8 particles,
// milliseconds a case) and the small vibrating bar: sweep.csv, a failing
// case, skipping completed cases on a second run, --jobs, shards and
// --collect, and bad sweep files or command lines rejected up front. The
// MPI sweep has its own test (test_sweep_mpi).
#include <doctest/doctest.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "io/case/case_reader.hpp"
#include "io/case/sweep_file.hpp"
#include "run_program.hpp"
#include "sweep_csv.hpp"

namespace fs = std::filesystem;
using namespace flowmpm::testing;

namespace {

const std::string base_text =
    read_text(fs::path(FLOWMPM_SOURCE_DIR) / "configs/uniaxial_stress/case1_usf.toml");

// A scratch directory holding base.toml (uniaxial stress Case I, USF).
struct SweepDir : TempDir {
  SweepDir() : TempDir("flowmpm_test_sweep") { write_text(path / "base.toml", base_text); }

  // Writes sweep.toml (base = "base.toml", output = "out", then `body`).
  fs::path sweep(const std::string& body) const {
    write_text(path / "sweep.toml", "base = \"base.toml\"\noutput = \"out\"\n" + body);
    return path / "sweep.toml";
  }

  Result run(const std::vector<std::string>& extra = {}) const {
    std::vector<std::string> args{"sweep", (path / "sweep.toml").string()};
    args.insert(args.end(), extra.begin(), extra.end());
    return run_flowmpm(args, path);
  }
};

// Scheme over usf/usl, the second item of the zip makes a particle leave the
// grid in the first step: cases 001 and 003 fail.
const std::string failing_sweep = R"(
[vary]
"analysis.scheme" = ["usf", "usl"]
[[zip]]
"bodies.0.velocity" = [[0.0, 0.0, 0.0], [100.0, 0.0, 0.0]]
)";

}  // namespace

TEST_CASE("a sweep expands [vary] keys in file order, then each [[zip]], the last fastest") {
  SweepDir dir;
  // velocity_update comes before scheme in the file, after it alphabetically.
  const fs::path file = dir.sweep(R"(
[vary]
"analysis.velocity_update" = ["flip", "pic"]
"analysis.scheme" = ["usf", "musl"]
[[zip]]
"analysis.dt" = [0.01, 0.001]
"analysis.end_time" = [0.1, 0.2]
[[zip]]
"output.every" = [1, 2, 5]
)");
  const flowmpm::Sweep s = flowmpm::read_sweep(file);
  CHECK(s.base == dir.path / "base.toml");
  CHECK(s.output == "out");
  CHECK(s.keys == std::vector<std::string>{"analysis.velocity_update", "analysis.scheme", "analysis.dt",
                                           "analysis.end_time", "output.every"});
  REQUIRE(s.cases.size() == 2 * 2 * 2 * 3);
  CHECK(s.cases[0].id == "000");
  CHECK(s.cases[23].id == "023");
  CHECK(s.cases[0].overrides == std::vector<std::string>{"analysis.velocity_update=\"flip\"",
                                                         "analysis.scheme=\"usf\"", "analysis.dt=0.01",
                                                         "analysis.end_time=0.1", "output.every=1"});
  CHECK(s.cases[0].values == std::vector<std::string>{"flip", "usf", "0.01", "0.1", "1"});
  CHECK(s.cases[1].values == std::vector<std::string>{"flip", "usf", "0.01", "0.1", "2"});
  CHECK(s.cases[3].values == std::vector<std::string>{"flip", "usf", "0.001", "0.2", "1"});
  CHECK(s.cases[6].values == std::vector<std::string>{"flip", "musl", "0.01", "0.1", "1"});
  CHECK(s.cases[12].values == std::vector<std::string>{"pic", "usf", "0.01", "0.1", "1"});
  CHECK(s.cases[23].values == std::vector<std::string>{"pic", "musl", "0.001", "0.2", "5"});
  // Every case was read with its overrides applied.
  CHECK(s.cases[23].c.scheme->name == "musl");
  CHECK(s.cases[23].c.system.velocity_update == flowmpm::VelocityUpdate::pic);
  CHECK(s.cases[23].c.time_control.steps == 200);
  CHECK(s.cases[23].c.output.every == 5);
}

TEST_CASE("the shipped speed-against-error sweeps run FLIP, APIC and XPIC(5) for every method and resolution") {
  for (auto [name, cases] : {std::pair{"bar_speed_vs_error.toml", 3 * 4 * 3 * 5}, std::pair{"column_speed_vs_error.toml", 3 * 4 * 4}}) {
    CAPTURE(name);
    const flowmpm::Sweep s = flowmpm::read_sweep(fs::path(FLOWMPM_SOURCE_DIR) / "configs/sweeps" / name);
    REQUIRE(s.cases.size() == static_cast<std::size_t>(cases));
    CHECK(s.keys.front() == "analysis.velocity_update");
    using flowmpm::VelocityUpdate;
    CHECK(s.cases.front().c.system.velocity_update == VelocityUpdate::flip);
    CHECK(s.cases[cases / 3].c.system.velocity_update == VelocityUpdate::apic);
    CHECK(s.cases.back().c.system.velocity_update == VelocityUpdate::xpic);
    CHECK(s.cases.back().c.system.xpic_order == 5);
  }
}

TEST_CASE("a sweep without [vary] or [[zip]] is the base case alone, with the default output") {
  SweepDir dir;
  write_text(dir.path / "alone.toml", "base = \"base.toml\"\n");
  const flowmpm::Sweep s = flowmpm::read_sweep(dir.path / "alone.toml");
  REQUIRE(s.cases.size() == 1);
  CHECK(s.cases[0].overrides.empty());
  CHECK(s.keys.empty());
  CHECK(s.output == fs::path("results/sweeps/alone"));
}

TEST_CASE("a varied value is passed on as the TOML text that reads back to it") {
  const toml::table t = toml::parse(R"(
values = [4e-4, 1e-5, 3.0, 1e300, -0.0, 12, true, "a\"b", [16, 32], { y = 0.0 }, [[0.0, 1.0], [2.5, -1.0]], inf]
)");
  std::vector<std::string> texts;
  for (const toml::node& v : *t["values"].as_array()) texts.push_back(flowmpm::toml_text(v));
  CHECK(texts == std::vector<std::string>{"0.0004", "1e-05", "3.0", "1e+300", "-0.0", "12", "true", "\"a\\\"b\"",
                                          "[16, 32]", "{ y = 0.0 }", "[[0.0, 1.0], [2.5, -1.0]]", "inf"});
}

TEST_CASE("flowmpm sweep runs every case and writes sweep.csv") {
  SweepDir dir;
  dir.sweep(R"(
[vary]
"analysis.scheme" = ["usf", "usl", "musl"]
[[zip]]
"analysis.dt" = [0.01, 0.001]
"analysis.end_time" = [0.1, 0.1]
)");
  const Result r = dir.run({"--threads", "2"});
  INFO("printed:\n" << r.output);
  REQUIRE(r.status == 0);
  CHECK(contains(r.output, "sweep: 6/6 done (0 failed, 0 skipped)"));
  CHECK(contains(r.output, "1 at a time on 2 threads each"));

  const auto lines = lines_of(read_text(dir.path / "out/sweep.csv"));
  REQUIRE(!lines.empty());
  CHECK(lines[0] ==
        "case,analysis.scheme,analysis.dt,analysis.end_time,status,particles,steps,wall_seconds,"
        "particle_steps_per_second,message");
  const auto table = table_of(dir.path / "out/sweep.csv");
  REQUIRE(table.size() == 6);
  const char* schemes[] = {"usf", "usf", "usl", "usl", "musl", "musl"};
  const char* upper[] = {"USF", "USF", "USL", "USL", "MUSL", "MUSL"};
  for (std::size_t i = 0; i < table.size(); ++i) {
    const auto& row = table[i];
    INFO("row " << i);
    CHECK(row.at("case") == "00" + std::to_string(i));
    CHECK(row.at("analysis.scheme") == schemes[i]);
    CHECK(row.at("analysis.dt") == (i % 2 == 0 ? "0.01" : "0.001"));
    CHECK(row.at("status") == "completed");
    CHECK(row.at("particles") == "8");
    CHECK(row.at("steps") == (i % 2 == 0 ? "10" : "100"));
    CHECK(std::stod(row.at("wall_seconds")) > 0.0);
    CHECK(std::stod(row.at("particle_steps_per_second")) > 0.0);
    CHECK(row.at("message").empty());
    const fs::path case_dir = dir.path / "out/cases" / row.at("case");
    CHECK(fs::is_regular_file(case_dir / "sweep_row.txt"));
    CHECK(fs::is_regular_file(case_dir / "summary.json"));
    CHECK(contains(read_text(case_dir / "summary.json"), std::string("\"scheme\": \"") + upper[i] + "\""));
  }
  for (const std::string& name : files_in(dir.path / "out")) CHECK_MESSAGE(!contains(name, ".tmp"), name);
}

TEST_CASE("sweep.csv has one column per error norm of the cases, sorted, between the rate and the message") {
  SweepDir dir;
  // A case with a reference solution: its summary has error norms.
  const fs::path base = fs::path(FLOWMPM_SOURCE_DIR) / "configs/verification/bar_vibration_small.toml";
  write_text(dir.path / "sweep.toml", "base = \"" + base.string() + "\"\noutput = \"out\"\n" +
                                          "[vary]\n\"analysis.shape_function\" = [\"linear\", \"bspline2\"]\n");
  const Result r = dir.run();
  INFO("printed:\n" << r.output);
  REQUIRE(r.status == 0);
  const auto rows = parse_csv(read_text(dir.path / "out/sweep.csv"));
  REQUIRE(rows.size() == 3);
  const auto& header = rows[0];
  const auto first = std::find(header.begin(), header.end(), "particle_steps_per_second") + 1;
  const auto last = header.end() - 1;
  CHECK(*last == "message");
  const std::vector<std::string> errors(first, last);
  CHECK(!errors.empty());
  CHECK(std::is_sorted(errors.begin(), errors.end()));
  for (std::size_t row = 1; row < rows.size(); ++row) {
    const std::string summary = read_text(dir.path / "out/cases" / rows[row][0] / "summary.json");
    for (std::size_t c = static_cast<std::size_t>(first - header.begin()); c + 1 < header.size(); ++c) {
      INFO("row " << row << ", column " << header[c]);
      CHECK(std::stod(rows[row][c]) > 0.0);
      CHECK(contains(summary, "\"" + header[c] + "\": "));
    }
  }
}

TEST_CASE("a failing case is recorded with its message, the others go on, and a second run retries only it") {
  SweepDir dir;
  dir.sweep(failing_sweep);
  const Result first = dir.run();
  INFO("first run printed:\n" << first.output);
  CHECK(first.status == 2);
  CHECK(contains(first.output, "case 001 (analysis.scheme=\"usf\", bodies.0.velocity=[100.0, 0.0, 0.0]) failed"));
  CHECK(contains(first.output, "4/4 done (2 failed, 0 skipped)"));

  const std::string csv = read_text(dir.path / "out/sweep.csv");
  const auto table = table_of(dir.path / "out/sweep.csv");
  REQUIRE(table.size() == 4);
  for (std::size_t i = 0; i < 4; ++i) {
    INFO("row " << i);
    const bool fails = i % 2 == 1;
    CHECK(table[i].at("bodies.0.velocity") == (fails ? "[100.0, 0.0, 0.0]" : "[0.0, 0.0, 0.0]"));
    CHECK(table[i].at("status") == (fails ? "failed" : "completed"));
    CHECK(table[i].at("steps") == (fails ? "" : "10"));
    if (fails) {
      CHECK(contains(table[i].at("message"), "step 1"));
      CHECK(contains(table[i].at("message"), "outside the grid"));
    } else {
      CHECK(table[i].at("message").empty());
    }
  }

  const Result second = dir.run();
  INFO("second run printed:\n" << second.output);
  CHECK(second.status == 2);
  CHECK(contains(second.output, "2 cases already completed, skipped"));
  CHECK(contains(second.output, "running 2 cases"));
  CHECK(contains(second.output, "case 001 (analysis.scheme=\"usf\", bodies.0.velocity=[100.0, 0.0, 0.0]) failed"));
  CHECK(contains(second.output, "case 003 (analysis.scheme=\"usl\", bodies.0.velocity=[100.0, 0.0, 0.0]) failed"));
  CHECK(contains(second.output, "4/4 done (2 failed, 2 skipped)"));
  CHECK(read_text(dir.path / "out/sweep.csv") == csv);
}

TEST_CASE("a case whose overrides changed since the earlier run is run again") {
  SweepDir dir;
  dir.sweep("[vary]\n\"analysis.scheme\" = [\"usf\", \"usl\"]\n");
  REQUIRE(dir.run().status == 0);
  dir.sweep("[vary]\n\"analysis.scheme\" = [\"usf\", \"musl\"]\n");
  const Result r = dir.run();
  INFO("printed:\n" << r.output);
  CHECK(r.status == 0);
  CHECK(contains(r.output, "1 case already completed, skipped"));
  CHECK(contains(r.output, "running 1 case,"));
  const auto table = table_of(dir.path / "out/sweep.csv");
  REQUIRE(table.size() == 2);
  CHECK(table[1].at("analysis.scheme") == "musl");
  CHECK(contains(read_text(dir.path / "out/cases/001/summary.json"), "\"scheme\": \"MUSL\""));
}

TEST_CASE("an edited base case runs every case again") {
  SweepDir dir;
  dir.sweep("[vary]\n\"analysis.scheme\" = [\"usf\", \"usl\"]\n");
  REQUIRE(dir.run().status == 0);
  write_text(dir.path / "base.toml", base_text + "\n# edited\n");
  const Result r = dir.run();
  INFO("printed:\n" << r.output);
  CHECK(r.status == 0);
  CHECK(!contains(r.output, "skipped,"));
  CHECK(contains(r.output, "running 2 cases,"));
}

TEST_CASE("--jobs 2 gives the rows of --jobs 1, but for wall time and rate") {
  SweepDir dir;
  dir.sweep(failing_sweep);
  auto rows = [&](const std::string& jobs, const std::string& out) {
    const Result r = dir.run({"--jobs", jobs, "--threads", "2", "--output", out});
    INFO("--jobs " << jobs << " printed:\n" << r.output);
    CHECK(r.status == 2);
    CHECK(contains(r.output, jobs + " at a time on " + (jobs == "1" ? "2 threads" : "1 thread") + " each"));
    return results_of(dir.path / out / "sweep.csv");
  };
  const auto one = rows("1", "one");
  const auto two = rows("2", "two");
  CHECK(one.size() == 4);
  CHECK(one == two);
}

TEST_CASE("shards run the cases whose number is I modulo N, and --collect builds the one-process table") {
  SweepDir dir;
  // The vibrating bar with its reference, so that the table has error
  // columns; a large amplitude makes a particle cross more than a cell in
  // the first step, so the odd cases 001, 003 and 005 fail.
  const fs::path base = fs::path(FLOWMPM_SOURCE_DIR) / "configs/verification/bar_vibration_small.toml";
  write_text(dir.path / "sweep.toml", "base = \"" + base.string() + "\"\n" + R"(
[vary]
"analysis.shape_function" = ["linear", "bspline2", "bspline3"]
[[zip]]
"reference.amplitude" = [1e-4, 1e3]
)");
  const Result whole = dir.run({"--output", "one"});
  INFO("one process printed:\n" << whole.output);
  REQUIRE(whole.status == 2);
  const auto one = results_of(dir.path / "one/sweep.csv");
  REQUIRE(one.size() == 6);

  // One shard alone runs its cases (1 and 4) and writes no table; --collect
  // then tabulates what there is and names the cases still missing.
  const Result shard = dir.run({"--shard", "1/3", "--output", "shards"});
  INFO("shard 1/3 printed:\n" << shard.output);
  CHECK(shard.status == 2);
  CHECK(contains(shard.output, "shard 1/3: 2 of 6 cases"));
  CHECK(contains(shard.output, "no table for a shard"));
  CHECK(files_in(dir.path / "shards/cases") == std::vector<std::string>{"001", "004"});
  CHECK(files_in(dir.path / "shards") == std::vector<std::string>{"cases"});
  const Result early = dir.run({"--collect", "--output", "shards"});
  INFO("early --collect printed:\n" << early.output);
  CHECK(early.status == 2);
  CHECK(contains(early.output, "4 cases not run yet, or run with another base case or other overrides: 000, 002, "
                               "003, 005"));
  CHECK(contains(early.output, "collected 2 of 6 cases: 1 completed, 1 failed (001), 4 missing"));
  const auto partial = results_of(dir.path / "shards/sweep.csv");
  CHECK(partial == std::vector<std::map<std::string, std::string>>{one[1], one[4]});

  // The other two at once, as a scheduler runs the jobs of an array.
  std::vector<Running> others;
  for (const std::string shard_index : {"0/3", "2/3"}) {
    others.push_back(start_program({FLOWMPM_EXECUTABLE, "sweep", "sweep.toml", "--shard", shard_index, "--output",
                                    "shards", "--threads", "1"},
                                   dir.path));
  }
  for (const Running& other : others) {
    const Result r = wait_for(other);
    INFO("shard printed:\n" << r.output);
    CHECK(r.status == 2);
  }
  const Result collected = dir.run({"--collect", "--output", "shards"});
  INFO("--collect printed:\n" << collected.output);
  CHECK(collected.status == 2);
  CHECK(contains(collected.output, "collected 6 of 6 cases: 3 completed, 3 failed (001, 003, 005), 0 missing"));
  CHECK(results_of(dir.path / "shards/sweep.csv") == one);
}

TEST_CASE("docs/slurm_sweep.sh as the tasks of a job array runs the shards; alone it collects the table") {
  SweepDir dir;
  dir.sweep(failing_sweep);
  REQUIRE(dir.run({"--output", "one"}).status == 2);
  // Slurm numbers the tasks of --array=3-5 from 3; they are shards 0 to 2.
  const std::string script = std::string(FLOWMPM_SOURCE_DIR) + "/docs/slurm_sweep.sh";
  const std::string program = std::string("FLOWMPM=") + FLOWMPM_EXECUTABLE;
  for (const int task : {3, 4, 5}) {
    const Result r = wait_for(start_program(
        {"/bin/bash", script, "sweep.toml", "--output", "array"}, dir.path,
        {program, "SLURM_ARRAY_TASK_ID=" + std::to_string(task), "SLURM_ARRAY_TASK_MIN=3", "SLURM_ARRAY_TASK_COUNT=3"}));
    INFO("task " << task << " printed:\n" << r.output);
    CHECK(contains(r.output, "shard " + std::to_string(task - 3) + "/3"));
    CHECK(r.status == (task == 5 ? 0 : 2));  // shards 0 and 1 hold the failing cases 003 and 001
  }
  const Result collect =
      wait_for(start_program({"/bin/bash", script, "sweep.toml", "--output", "array"}, dir.path,
                             {program, "SLURM_ARRAY_TASK_ID=", "SLURM_ARRAY_TASK_COUNT="}));
  INFO("collecting printed:\n" << collect.output);
  CHECK(contains(collect.output, "collected 4 of 4 cases: 2 completed, 2 failed (001, 003), 0 missing"));
  CHECK(results_of(dir.path / "array/sweep.csv") == results_of(dir.path / "one/sweep.csv"));
}

TEST_CASE("a bad sweep file stops the sweep up front with one message naming the problem, writing nothing") {
  SweepDir dir;
  auto rejected = [&](const std::string& body, std::initializer_list<std::string> fragments) {
    dir.sweep(body);
    const Result r = dir.run();
    INFO("sweep file:\n" << body << "\nprinted:\n" << r.output);
    CHECK(r.status == 1);
    CHECK(non_empty_lines(r.output).size() == 1);
    for (const std::string& fragment : fragments) CHECK_MESSAGE(contains(r.output, fragment), fragment);
    CHECK(files_in(dir.path) == std::vector<std::string>{"base.toml", "sweep.toml"});
  };
  SUBCASE("an unknown key") {
    rejected("varry = 1\n", {"sweep.toml:3", "varry", "unknown key"});
  }
  SUBCASE("zipped lists of unequal lengths") {
    rejected("[[zip]]\n\"analysis.dt\" = [0.01, 0.001]\n\"analysis.end_time\" = [0.1, 0.1, 0.1]\n",
             {"sweep.toml:5", "zip[0].analysis.end_time", "3 values", "zip[0].analysis.dt has 2", "equal lengths"});
  }
  SUBCASE("a key the case does not have") {
    rejected("[vary]\n\"analysis.shceme\" = [\"usf\"]\n",
             {"case 000", "analysis.shceme=\"usf\"", "analysis.shceme", "unknown key"});
  }
  SUBCASE("a value the case rejects, in the second case") {
    rejected("[vary]\n\"analysis.dt\" = [0.01, 0.05]\n", {"case 001", "analysis.dt=0.05", "stable"});
  }
  SUBCASE("a key varied twice") {
    rejected("[vary]\n\"analysis.dt\" = [0.01]\n[[zip]]\n\"analysis.dt\" = [0.001]\n",
             {"sweep.toml:6", "analysis.dt is varied twice", "sweep.toml:4"});
  }
  SUBCASE("an empty list") {
    rejected("[vary]\n\"analysis.dt\" = []\n", {"sweep.toml:4", "vary.analysis.dt", "non-empty array"});
  }
  SUBCASE("a dotted key left unquoted") {
    rejected("[vary]\nanalysis.dt = [0.01]\n", {"vary.analysis", "quote a dotted key"});
  }
  SUBCASE("a base case that does not exist") {
    write_text(dir.path / "sweep.toml", "base = \"nowhere.toml\"\n");
    const Result r = dir.run();
    INFO(r.output);
    CHECK(r.status == 1);
    CHECK(contains(r.output, "sweep.toml:1: base"));
    CHECK(contains(r.output, "nowhere.toml does not exist"));
    CHECK(files_in(dir.path) == std::vector<std::string>{"base.toml", "sweep.toml"});
  }
  SUBCASE("a sweep file that does not exist") {
    const Result r = run_flowmpm({"sweep", "missing.toml"}, dir.path);
    CHECK(r.status == 1);
    CHECK(contains(r.output, "missing.toml: no such file"));
  }
}

TEST_CASE("sweep command-line misuse") {
  SweepDir dir;
  dir.sweep("");
  auto misuse = [&](const std::vector<std::string>& args, const std::string& fragment) {
    const Result r = run_flowmpm(args, dir.path);
    INFO("printed:\n" << r.output);
    CHECK(r.status == 1);
    CHECK(contains(r.output, fragment));
    CHECK(files_in(dir.path) == std::vector<std::string>{"base.toml", "sweep.toml"});
  };
  misuse({"sweep"}, "no sweep file");
  misuse({"sweep", "sweep.toml", "--jobs", "0"}, "--jobs");
  misuse({"sweep", "sweep.toml", "--set", "analysis.dt=0.001"}, "--set");
  misuse({"run", "base.toml", "--jobs", "2"}, "--jobs");
  misuse({"sweep", "sweep.toml", "--shard", "3/3"}, "--shard: expected I/N, whole numbers with 0 <= I < N");
  misuse({"sweep", "sweep.toml", "--shard", "1"}, "--shard: expected I/N");
  misuse({"sweep", "sweep.toml", "--shard", "-1/2"}, "--shard: expected I/N");
  misuse({"sweep", "sweep.toml", "--mpi", "--shard", "0/2"}, "--mpi excludes --shard");
  misuse({"sweep", "sweep.toml", "--mpi", "--jobs", "2"}, "--jobs excludes --mpi");
  misuse({"sweep", "sweep.toml", "--collect", "--shard", "0/2"}, "--shard excludes --collect");
#ifndef FLOWMPM_MPI
  misuse({"sweep", "sweep.toml", "--mpi"}, "--mpi: this flowmpm was built without MPI");
#endif
}

TEST_CASE("started by mpirun as several processes, flowmpm asks for --mpi instead of running everything N times") {
  SweepDir dir;
  dir.sweep("");
  for (const std::string variable : {"OMPI_COMM_WORLD_SIZE=2", "PMI_SIZE=2"}) {
    INFO(variable);
    const Result sweep = run_flowmpm({"sweep", "sweep.toml"}, dir.path, {variable});
    CHECK(sweep.status == 1);
    CHECK(contains(sweep.output, "started by an MPI launcher as 2 processes, each of which would run the whole "
                                 "sweep; add --mpi"));
    const Result run = run_flowmpm({"run", "base.toml"}, dir.path, {variable});
    CHECK(run.status == 1);
    CHECK(contains(run.output, "run a case as one process"));
    CHECK(files_in(dir.path) == std::vector<std::string>{"base.toml", "sweep.toml"});
  }
}
