// The key reference (docs/reference/) against the reader's own registry of
// keys (io/case/key_registry.hpp), both ways: every key the reader asks for
// while it reads the shipped cases is documented, and every documented key
// is one the reader asks for. Reading a case asks for every key of each
// table it reads, given or not (optional keys, a variant's keys for the
// type given), so the shipped cases, which use every section and every
// type, reach nearly every key; the probes below reach the rest (3D loads
// with a combined region, a body force, a surface flux, a uniform initial
// stress; a 3D rigid body moving along z against a contact group). A key
// that neither reaches fails the second direction until a case uses it. Not covered: the sweep file
// (docs/reference/sweep_file.md, its own reader) and the command line
// (cli.md).
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <string>

#include "io/case/case_file.hpp"
#include "io/case/key_registry.hpp"
#include "test_helpers.hpp"

using namespace flowmpm;
namespace fs = std::filesystem;

namespace {

// The first cells of the key rows of every page but the sweep file's and
// the command line's: "`analysis.dimension` | ..." -> analysis.dimension.
// A nested array of shape tables is documented as "bodies[].shape.parts[]";
// the reader asks for the key "parts".
std::set<std::string> documented_keys() {
  std::set<std::string> keys;
  const std::regex row(R"(^\|\s*`([^`]+)`\s*\|)");
  for (const auto& page : fs::directory_iterator(fs::path(FLOWMPM_SOURCE_DIR) / "docs" / "reference")) {
    const std::string name = page.path().filename().string();
    if (name == "README.md" || name == "sweep_file.md" || name == "cli.md") continue;
    std::ifstream in(page.path());
    for (std::string line; std::getline(in, line);) {
      std::smatch m;
      if (!std::regex_search(line, m, row)) continue;
      std::string key = m[1];
      if (key.ends_with("[]")) key.resize(key.size() - 2);
      keys.insert(key);
    }
  }
  return keys;
}

// Every shipped case but the sweeps, read (which fills the registry).
std::size_t read_shipped_cases() {
  std::size_t count = 0;
  for (const auto& entry : fs::recursive_directory_iterator(fs::path(FLOWMPM_SOURCE_DIR) / "configs")) {
    if (entry.path().extension() != ".toml" || entry.path().parent_path().filename() == "sweeps") continue;
    CAPTURE(entry.path().string());
    CHECK_NOTHROW(read_case(entry.path()));
    ++count;
  }
  return count;
}

// What no shipped case uses: a 3D block with a uniform initial stress, a
// heat flux through a face, a traction on a region that unites a cylinder
// and a box, a nodal force and a body force along z.
constexpr const char* probe = R"(
[analysis]
dimension = 3
dt = 1e-4
steps = 1
[grid]
origin = [0.0, 0.0, 0.0]
cell_size = 0.25
cells = [8, 8, 8]
[materials.m]
type = "linear_elastic"
density = 1000.0
youngs_modulus = 1e6
poisson_ratio = 0.3
heat_capacity = 500.0
conductivity = 1.0
[[bodies]]
name = "block"
material = "m"
min = [0.5, 0.5, 0.5]
max = [1.5, 1.5, 1.5]
particles_per_cell = 2
temperature = 300.0
initial_stress = { type = "uniform", stress = [-1.0, -1.0, -1.0, 0.0, 0.0, 0.0] }
[[node_sets]]
name = "top"
plane = "y"
at = 1.5
velocity = { y = 0.0 }
[[surface_fluxes]]
name = "sun"
body = "block"
face = "x+"
heat_flux = 100.0
[[loads]]
type = "traction"
body = "block"
face = "+z"
traction = { x = 1.0, z = -5.0 }
region = { type = "union", parts = [{ type = "cylinder", axis = "z", center = [1.0, 1.0, 1.5], radius = 0.3, length = 0.2 }, { type = "box", min = [0.5, 0.5, 1.4], max = [0.7, 0.7, 1.6] }] }
[[loads]]
type = "nodal_force"
node_set = "top"
force = { z = 1.0 }
[[loads]]
type = "body_force"
body = "block"
acceleration = { z = -1.0 }
)";

// A 3D rigid obstacle moving along z (the shipped 3D floor is at rest),
// against a contact group of two blocks.
constexpr const char* probe_rigid = R"(
[analysis]
dimension = 3
dt = 1e-4
steps = 1
[grid]
origin = [0.0, 0.0, 0.0]
cell_size = 0.25
cells = [8, 8, 8]
[materials.m]
type = "linear_elastic"
density = 1000.0
youngs_modulus = 1e6
poisson_ratio = 0.3
[[bodies]]
name = "block"
material = "m"
min = [0.5, 0.5, 0.5]
max = [1.0, 1.5, 1.0]
particles_per_cell = 2
[[bodies]]
name = "block2"
material = "m"
min = [1.0, 0.5, 0.5]
max = [1.5, 1.5, 1.0]
particles_per_cell = 2
[[contact_groups]]
name = "blocks"
bodies = ["block", "block2"]
[[bodies]]
name = "plate"
rigid = { velocity = { z = -0.1 } }
min = [0.5, 0.5, 1.0]
max = [1.5, 1.5, 1.25]
particles_per_cell = 2
[[contacts]]
bodies = ["blocks", "plate"]
law = "frictionless"
)";

std::string listed(const std::set<std::string>& keys) {
  std::string text;
  for (const std::string& k : keys) text += "\n  " + k;
  return text;
}

}  // namespace

TEST_CASE("every key the reader accepts is documented in docs/reference, and every documented key is accepted") {
  const std::size_t cases = read_shipped_cases();
  CHECK_NOTHROW(testing::case_from_text("key_reference_probe", probe));
  CHECK_NOTHROW(testing::case_from_text("key_reference_probe_rigid", probe_rigid));
  const std::set<std::string> asked = asked_keys();
  const std::set<std::string> documented = documented_keys();
  MESSAGE(cases << " shipped cases read: the reader asked for " << asked.size() << " keys; docs/reference documents "
                << documented.size());
  std::set<std::string> undocumented, unknown;
  for (const std::string& k : asked)
    if (!documented.count(k)) undocumented.insert(k);
  for (const std::string& k : documented)
    if (!asked.count(k)) unknown.insert(k);
  INFO("asked by the reader, not in docs/reference:" << listed(undocumented));
  CHECK(undocumented.empty());
  INFO("in docs/reference, never asked by the reader:" << listed(unknown));
  CHECK(unknown.empty());
}

TEST_CASE("the registry's patterns: indices become [], a material's name <name>, a combination's parts their shape") {
  CHECK(key_pattern("", "name") == "name");
  CHECK(key_pattern("analysis", "dt") == "analysis.dt");
  CHECK(key_pattern("bodies[12].shape", "radius") == "bodies[].shape.radius");
  CHECK(key_pattern("bodies[0].shape.parts[1].parts[0]", "radius") == "bodies[].shape.radius");
  CHECK(key_pattern("materials.oak", "density") == "materials.<name>.density");
  CHECK(key_pattern("materials.oak.expansion", "alpha") == "materials.<name>.expansion.alpha");
}
