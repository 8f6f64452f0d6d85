// The flowmpm command-line program, run as a separate process on case files
// written into a fresh temporary directory: bad case files and bad command
// lines give exit status 1 with one clear message and write nothing, a valid
// run writes its results (and can run again over them).
#include <doctest/doctest.h>

#include <filesystem>
#include <initializer_list>
#include <string>
#include <vector>

#include "run_program.hpp"

namespace fs = std::filesystem;
using namespace flowmpm::testing;

namespace {

// The text of a case file, line by line, for editing.
struct CaseText {
  std::vector<std::string> lines;

  static CaseText valid() {
    const fs::path source = fs::path(FLOWMPM_SOURCE_DIR) / "configs/uniaxial_stress/case1_usl.toml";
    const std::string text = read_text(source);
    REQUIRE_MESSAGE(!text.empty(), "cannot read " << source.string());
    return CaseText{lines_of(text)};
  }

  // 1-based number of the first line starting with `prefix`.
  int line_of(const std::string& prefix) const {
    for (std::size_t i = 0; i < lines.size(); ++i) {
      if (lines[i].rfind(prefix, 0) == 0) return static_cast<int>(i) + 1;
    }
    FAIL("no line starts with '" << prefix << "'");
    return 0;
  }

  // Replaces the first line starting with `prefix`; returns its number.
  int replace(const std::string& prefix, const std::string& line) {
    const int n = line_of(prefix);
    lines[static_cast<std::size_t>(n - 1)] = line;
    return n;
  }

  // Removes the first line starting with `prefix`.
  void remove(const std::string& prefix) {
    const int n = line_of(prefix);
    lines.erase(lines.begin() + (n - 1));
  }

  std::string text() const {
    std::string t;
    for (const std::string& line : lines) t += line + "\n";
    return t;
  }
};

// Writes `text` as a case file and runs both `flowmpm check` and
// `flowmpm run --output ...` on it with `extra` arguments. Each must exit 1
// with one message line naming the file (and `line` if > 0; neither if
// `line` < 0) and containing every one of `fragments`, and `run` must write
// nothing.
void expect_rejected(const TempDir& dir, const std::string& text, int line,
                     std::initializer_list<std::string> fragments,
                     const std::vector<std::string>& extra = {}) {
  const fs::path case_file = dir.path / "case.toml";
  write_text(case_file, text);
  const fs::path out = dir.path / "out";
  std::string where;
  if (line >= 0) where = case_file.string();
  if (line > 0) where.append(":").append(std::to_string(line)).append(":");

  for (const std::string command : {"check", "run"}) {
    std::vector<std::string> args{command, case_file.string()};
    if (command == "run") args.insert(args.end(), {"--threads", "2", "--output", out.string()});
    args.insert(args.end(), extra.begin(), extra.end());
    const Result r = run_flowmpm(args, dir.path);
    INFO("flowmpm " << command << " ... printed:\n" << r.output);
    CHECK(r.status == 1);
    CHECK(non_empty_lines(r.output).size() == 1);
    CHECK_MESSAGE(contains(r.output, where), "expected the location '" << where << "'");
    for (const std::string& fragment : fragments) {
      CHECK_MESSAGE(contains(r.output, fragment), "expected '" << fragment << "'");
    }
    if (command == "run") {
      CHECK_MESSAGE(!fs::exists(out), "run created " << out.string() << " for a bad case");
      // Nothing else was written either (the case's own output.directory is
      // relative to the working directory, the temporary directory).
      const std::vector<std::string> names = files_in(dir.path);
      CHECK(names == std::vector<std::string>{"case.toml"});
    }
  }
}

}  // namespace

TEST_CASE("a bad case file is rejected with one clear message and nothing is written") {
  TempDir dir("flowmpm_test_cli");
  CaseText c = CaseText::valid();

  SUBCASE("the valid case itself passes check") {
    const fs::path case_file = dir.path / "case.toml";
    write_text(case_file, c.text());
    const Result r = run_flowmpm({"check", case_file.string()}, dir.path);
    INFO(r.output);
    CHECK(r.status == 0);
    CHECK(contains(r.output, case_file.string() + ": ok"));
  }
  SUBCASE("malformed TOML: an unclosed table header bracket") {
    const int line = c.replace("[analysis]", "[analysis");
    expect_rejected(dir, c.text(), line, {"TOML", "expected"});
  }
  SUBCASE("malformed TOML: a missing comma in an array") {
    const int line = c.replace("origin = ", "origin = [0.0, 0.0 0.0]");
    expect_rejected(dir, c.text(), line, {"TOML", "expected"});
  }
  SUBCASE("malformed TOML: an unclosed array bracket") {
    // The error is in the line of `origin`; the parser notices it only on
    // the next line, so the message quotes that line and the one before it.
    const int line = c.replace("origin = ", "origin = [0.0, 0.0, 0.0");
    expect_rejected(dir, c.text(), line + 1, {"TOML", "expected", "origin = [0.0, 0.0, 0.0"});
  }
  SUBCASE("an unknown key") {
    const int line = c.replace("scheme = ", "shceme = \"usl\"");
    expect_rejected(dir, c.text(), line, {"analysis.shceme", "unknown key", "did you mean analysis.scheme?"});
  }
  SUBCASE("a value of the wrong type") {
    const int line = c.replace("dt = ", "dt = \"fast\"");
    expect_rejected(dir, c.text(), line, {"analysis.dt", "a time step in s, or \"auto\"", "fast"});
  }
  SUBCASE("a missing required key") {
    c.remove("youngs_modulus = ");
    // There is no line of the key itself: the message points at its table.
    const int line = c.line_of("[materials.elastic]");
    expect_rejected(dir, c.text(), line, {"materials.elastic.youngs_modulus", "missing"});
  }
  SUBCASE("a negative density") {
    const int line = c.replace("density = ", "density = -1.0");
    expect_rejected(dir, c.text(), line, {"materials.elastic.density", "positive"});
  }
  SUBCASE("a Poisson ratio of 0.5") {
    const int line = c.replace("poisson_ratio = ", "poisson_ratio = 0.5");
    expect_rejected(dir, c.text(), line, {"materials.elastic.poisson_ratio", "0.5", "expected"});
  }
  SUBCASE("a body box outside the grid") {
    const int line = c.replace("max = ", "max = [2.0, 1.0, 1.0]");
    expect_rejected(dir, c.text(), line, {"bodies[0].max", "inside the grid"});
  }
  SUBCASE("a time step above the stable limit") {
    // density 1, E 1000, nu 0.2, h 1 m: the stable limit is h/c = 0.03 s.
    const int line = c.replace("dt = ", "dt = 0.05");
    expect_rejected(dir, c.text(), line, {"analysis.dt", "stable", "0.03"});
  }
  SUBCASE("an unknown scheme") {
    const int line = c.replace("scheme = ", "scheme = \"usx\"");
    expect_rejected(dir, c.text(), line, {"analysis.scheme", "\"usf\"", "\"usl\"", "\"musl\"", "usx"});
  }
  SUBCASE("an unknown shape function: the known ones are listed") {
    const int line = c.replace("shape_function = ", "shape_function = \"quadratic\"");
    expect_rejected(dir, c.text(), line,
                    {"analysis.shape_function", "\"linear\"", "\"gimp\"", "\"bspline2\"", "\"bspline3\"", "quadratic"});
  }
  SUBCASE("an unknown material type: the known ones are listed") {
    const int line = c.replace("type = ", "type = \"elastic\"");
    expect_rejected(dir, c.text(), line,
                    {"materials.elastic.type", "\"linear_elastic\"", "\"von_mises\"", "\"strain_softening\""});
  }
  SUBCASE("an unknown reference type: the known ones are listed") {
    c.lines.push_back("[reference]");
    c.lines.push_back("type = \"axial\"");
    expect_rejected(dir, c.text(), static_cast<int>(c.lines.size()),
                    {"reference.type", "\"axial_vibration\"", "\"elastic_wave\"", "\"column_self_weight\""});
  }
  SUBCASE("a reference's own check names its key") {
    c.lines.push_back("[reference]");
    c.lines.push_back("type = \"uniaxial_stress\"");
    c.lines.push_back("axis = \"w\"");
    c.lines.push_back("length = 1.0");
    c.lines.push_back("velocity = -0.01");
    expect_rejected(dir, c.text(), static_cast<int>(c.lines.size()) - 2, {"reference.axis", "\"x\", \"y\" or \"z\""});
  }
  SUBCASE("a body whose material does not exist") {
    const int line = c.replace("material = ", "material = \"steel\"");
    expect_rejected(dir, c.text(), line, {"bodies[0].material", "steel", "\"elastic\""});
  }
  SUBCASE("a node set plane off the grid node planes") {
    const int line = c.replace("at = ", "at = 0.3");
    expect_rejected(dir, c.text(), line, {"node_sets[0].at", "grid nodes", "0.3"});
  }
}

TEST_CASE("--set overrides are checked like the case file") {
  TempDir dir("flowmpm_test_cli");
  const fs::path case_file = dir.path / "case.toml";
  write_text(case_file, CaseText::valid().text());

  SUBCASE("a bad value names --set and the key") {
    expect_rejected(dir, CaseText::valid().text(), -1, {"--set", "analysis.dt", "positive"},
                    {"--set", "analysis.dt=-1"});
  }
  SUBCASE("a time step above the stable limit names --set and the key") {
    expect_rejected(dir, CaseText::valid().text(), -1, {"--set", "analysis.dt", "stable"},
                    {"--set", "analysis.dt=0.05"});
  }
  SUBCASE("an override without '=' names --set") {
    expect_rejected(dir, CaseText::valid().text(), -1, {"--set", "analysis.dt", "KEY=VALUE"},
                    {"--set", "analysis.dt"});
  }
  SUBCASE("a key as messages name it, bodies[0].velocity, works in --set as bodies.0.velocity does") {
    for (const char* key : {"bodies[0].velocity", "bodies.0.velocity"}) {
      const Result r = run_flowmpm({"check", case_file.string(), "--set", std::string(key) + "=[0.5, 0.0, 0.0]"}, dir.path);
      INFO(key << ": " << r.output);
      CHECK(r.status == 0);
    }
  }
  SUBCASE("an array of the wrong length: the message says how long it was") {
    expect_rejected(dir, CaseText::valid().text(), -1,
                    {"--set", "bodies[0].velocity", "an array of 3 numbers", "an array of 2 items"},
                    {"--set", "bodies[0].velocity=[1.0, 2.0]"});
  }
  SUBCASE("a bare string value is accepted") {
    const Result r = run_flowmpm({"check", case_file.string(), "--set", "analysis.scheme=musl"}, dir.path);
    INFO(r.output);
    CHECK(r.status == 0);
    CHECK(contains(r.output, "MUSL"));
    CHECK(contains(r.output, case_file.string() + ": ok"));
  }
}

TEST_CASE("command-line misuse") {
  TempDir dir("flowmpm_test_cli");
  const fs::path case_file = dir.path / "case.toml";
  write_text(case_file, CaseText::valid().text());

  auto misuse = [&](const std::vector<std::string>& args, const std::string& fragment) {
    const Result r = run_flowmpm(args, dir.path);
    INFO("printed:\n" << r.output);
    CHECK(r.status == 1);
    CHECK(!non_empty_lines(r.output).empty());
    CHECK_MESSAGE(contains(r.output, fragment), "expected '" << fragment << "'");
    CHECK(files_in(dir.path) == std::vector<std::string>{"case.toml"});
  };

  SUBCASE("no arguments") { misuse({}, "no command"); }
  SUBCASE("an unknown command") { misuse({"frobnicate", case_file.string()}, "frobnicate"); }
  SUBCASE("an unknown option") { misuse({"run", case_file.string(), "--bogus"}, "--bogus"); }
  SUBCASE("--threads 0") { misuse({"run", case_file.string(), "--threads", "0"}, "--threads"); }
  SUBCASE("--help") {
    const Result r = run_flowmpm({"--help"}, dir.path);
    INFO(r.output);
    CHECK(r.status == 0);
    CHECK(contains(r.output, "Usage"));
  }
  SUBCASE("a command's own --help") {
    const Result r = run_flowmpm({"run", "--help"}, dir.path);
    INFO(r.output);
    CHECK(r.status == 0);
    CHECK(contains(r.output, "--threads"));
    CHECK(contains(r.output, "--set"));
    CHECK_FALSE(contains(r.output, "--jobs"));
  }
  SUBCASE("--option=value as well as --option value") {
    const Result r = run_flowmpm({"check", case_file.string(), "--set=analysis.scheme=musl"}, dir.path);
    INFO(r.output);
    CHECK(r.status == 0);
    CHECK(contains(r.output, "MUSL"));
    const Result t = run_flowmpm({"run", case_file.string(), "--threads=2", "--quiet", "--output=out"}, dir.path);
    INFO(t.output);
    CHECK(t.status == 0);
    CHECK(contains(read_text(dir.path / "out" / "summary.json"), "\"threads\": 2"));
    fs::remove_all(dir.path / "out");
  }
  SUBCASE("--version") {
    const Result r = run_flowmpm({"--version"}, dir.path);
    INFO(r.output);
    CHECK(r.status == 0);
    CHECK(r.output.rfind("flowmpm ", 0) == 0);
  }
}

TEST_CASE("an output directory that cannot be created: exit 1, the path and the key to change") {
  TempDir dir("flowmpm_test_cli");
  const fs::path blocker = dir.path / "a_file";
  write_text(blocker, "not a directory\n");
  const fs::path case_file = dir.path / "case.toml";
  write_text(case_file, CaseText::valid().text());
  const Result r = run_flowmpm({"run", case_file.string(), "--quiet", "--output", (blocker / "out").string()}, dir.path);
  INFO(r.output);
  CHECK(r.status == 1);
  CHECK(contains(r.output, (blocker / "out").string()));
  CHECK(contains(r.output, "--output"));
}

TEST_CASE("a missing case file") {
  TempDir dir("flowmpm_test_cli");
  const fs::path missing = dir.path / "no_such_case.toml";
  const fs::path out = dir.path / "out";
  for (const std::string command : {"check", "run"}) {
    std::vector<std::string> args{command, missing.string()};
    if (command == "run") args.insert(args.end(), {"--output", out.string()});
    const Result r = run_flowmpm(args, dir.path);
    INFO("flowmpm " << command << " printed:\n" << r.output);
    CHECK(r.status == 1);
    CHECK(non_empty_lines(r.output).size() == 1);
    CHECK(contains(r.output, missing.string()));
    CHECK(!fs::exists(out));
  }
}

TEST_CASE("a valid run writes its results, and runs again over them") {
  TempDir dir("flowmpm_test_cli");
  const fs::path case_file = dir.path / "case.toml";
  write_text(case_file, CaseText::valid().text());
  const fs::path out = dir.path / "out";

  auto run_and_check = [&](const std::vector<std::string>& extra, const std::string& scheme) {
    std::vector<std::string> args{"run", case_file.string(), "--threads", "2", "--output", out.string(), "--quiet"};
    args.insert(args.end(), extra.begin(), extra.end());
    const Result r = run_flowmpm(args, dir.path);
    INFO("printed:\n" << r.output);
    REQUIRE(r.status == 0);

    for (const char* name : {"results.h5", "results.xdmf", "timeseries.csv", "summary.json"}) {
      CHECK_MESSAGE(fs::is_regular_file(out / name), "missing " << name);
      if (fs::is_regular_file(out / name)) CHECK(fs::file_size(out / name) > 0);
    }
    for (const std::string& name : files_in(out)) {
      CHECK_MESSAGE(!contains(name, ".tmp"), "leftover temporary file " << name);
    }
    for (const std::string& name : files_in(out / "steps")) {
      CHECK_MESSAGE(!contains(name, ".tmp"), "leftover temporary file steps/" << name);
    }

    const std::string summary = read_text(out / "summary.json");
    INFO("summary.json:\n" << summary);
    CHECK(contains(summary, "\"status\": \"completed\""));
    CHECK(contains(summary, "\"steps\": 10"));
    CHECK(contains(summary, "\"scheme\": \"" + scheme + "\""));

    const std::vector<std::string> rows = non_empty_lines(read_text(out / "timeseries.csv"));
    REQUIRE(!rows.empty());
    CHECK(rows[0].rfind("step,time,kinetic_energy,stored_energy,dissipated_energy", 0) == 0);
    CHECK(rows.size() >= 3);  // the header and at least 2 data rows

    CHECK(contains(read_text(out / "results.xdmf"), "steps/00000010.h5:/position"));
  };

  run_and_check({}, "USL");
  // Again into the same directory, over the earlier results: the new results
  // replace them.
  run_and_check({"--set", "analysis.scheme=musl"}, "MUSL");
}
