// Stability on hard cases (issue "Accuracy you can see"). Case (a), cell
// crossing under large deformation, is in test_verification.cpp
// (large-amplitude bar: linear stress error > 10 %, uGIMP and B-splines
// < 2 %).
#include <doctest/doctest.h>

#include <hdf5.h>

#include <atomic>
#include <fstream>
#include <iterator>

#include "app/run_case.hpp"
#include "engine/simulation.hpp"
#include "test_helpers.hpp"

using namespace flowmpm;

namespace {

std::string message_of(const Case& c, bool write = false) {
  try {
    testing::run(c, write);
  } catch (const SimulationError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("(b) a time step above the stable limit is rejected when the case is read") {
  // Bar: h = 1/32 m, c = 10 m/s, so the limit is h / c = 3.125e-3 s.
  CHECK_THROWS_WITH_AS(read_case(testing::config("verification/bar_vibration_small.toml"),
                                 {"analysis.dt=4e-3", "analysis.end_time=0.4"}),
                       doctest::Contains("(h/c = 0.003125 s"), CaseError);
  CHECK_THROWS_AS(read_case(testing::config("verification/bar_vibration_small.toml"),
                            {"analysis.dt=\"auto\"", "analysis.cfl=1.5"}),
                  CaseError);
}

TEST_CASE("(b) the blow-up guard stops a runaway run and writes the last good state first") {
  // A bar falling freely under 100 m/s^2 gains speed until it passes 1.5
  // times its wave speed (15 m/s) at t = 0.15 s; the guard (factor lowered
  // to 1.5 for the test) stops it there. uGIMP, because with linear shape
  // functions the bar's tip runs ahead of free fall (cell-crossing noise)
  // and trips the guard earlier. The state kept every 10 steps is written
  // to results.h5 (output otherwise only at step 0).
  const auto dir = std::filesystem::temp_directory_path() / "flowmpm-tests" / "guard";
  std::filesystem::remove_all(dir);
  const Case c = testing::case_from_text("guard", R"(
[analysis]
dimension = 1
shape_function = "gimp"
dt = 6.25e-4
end_time = 0.5
gravity = [-100.0]
guard_speed_factor = 1.5
[grid]
origin = [-3.5]
cell_size = 0.03125
cells = [150]
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
[output]
every = 100000
directory = ")" + dir.string() + "\"\n");
  const std::string message = message_of(c, true);
  CHECK(message.find("blow-up at step") != std::string::npos);
  CHECK(message.find("1.5 times the fastest wave speed") != std::string::npos);
  const auto at = message.find("the last good state (step ");
  REQUIRE(at != std::string::npos);
  const long good = std::stol(message.substr(at + 26));
  CHECK(good > 200);  // 0.15 s / 6.25e-4 s = 240 steps
  const hid_t file = H5Fopen((dir / "results.h5").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  REQUIRE(file >= 0);
  char group[32];
  std::snprintf(group, sizeof group, "/steps/%08ld", good);
  CHECK(H5Oexists_by_name(file, group, H5P_DEFAULT) > 0);  // the link, and the step file it names
  H5Fclose(file);
}

TEST_CASE("(c) nearly incompressible elasticity, nu = 0.49: stable and accurate") {
  // The column of test_verification with nu = 0.49: measured 0.52 %.
  for (std::string shape : {"linear", "bspline2"}) {
    CAPTURE(shape);
    const auto s = testing::run(read_case(testing::config("hard/incompressible_column.toml"),
                                 {"analysis.shape_function=" + shape}));
    CHECK(s.errors.at("displacement") < 0.01);
  }
}

TEST_CASE("(d) two elastic blocks colliding: energy balance error bounded with uGIMP and FLIP, PIC dissipates") {
  // No external work: kinetic + stored energy is conserved in the continuum.
  // NairnMPM's author reports FLIP losing about 3 % over a two-disk impact
  // ([NairnMPM]). Measured balance error: uGIMP FLIP 3.6 %; PIC loses more
  // than FLIP for every shape function.
  const Case gimp = read_case(testing::config("hard/impact_2d.toml"));
  const RunSummary flip = testing::run(gimp);
  CHECK(flip.energy_error < 0.05);
  // Lost, not gained: the start's 2 x rho A v^2 / 2 = 0.04 J (0.2 m squares
  // at 1 m/s, rho = 1).
  CHECK(flip.kinetic_energy + flip.stored_energy < 0.04);
  for (std::string shape : {"linear", "gimp", "bspline2"}) {
    CAPTURE(shape);
    auto error_of = [&](const std::string& update) {
      const RunSummary s = testing::run(read_case(testing::config("hard/impact_2d.toml"),
                                         {"analysis.shape_function=" + shape, "analysis.velocity_update=" + update}));
      return s.energy_error;
    };
    CHECK(error_of("pic") > error_of("flip"));
  }
}

TEST_CASE("(e) particles leaving the grid stop the run with a clear error, not a crash") {
  // The policy: the grid must hold the material; a particle that would
  // leave it is not moved, the step fails, and the run stops (exit 2).
  const std::string message = message_of(read_case(testing::config("hard/impact_2d.toml"),
                                                   {"bodies.0.velocity=[-20.0, 0.0]"}));
  CHECK(message.find("outside the grid") != std::string::npos);
  CHECK(message.find("a particle at (") != std::string::npos);
  CHECK(message.find("step ") == 0);
}

TEST_CASE("an interrupted run stops after its step, keeps what it wrote and says so in the summary") {
  // The interrupt lands on a step that is already an output step (here
  // step 0): it must not be written twice (HDF5 refuses a second group).
  const auto dir = std::filesystem::temp_directory_path() / "flowmpm-tests" / "interrupted";
  std::filesystem::remove_all(dir);
  Case c = read_case(testing::config("verification/bar_vibration_small.toml"), {"output.every=1"});
  c.output.directory = dir;
  const std::atomic<bool> interrupt{true};
  RunOptions options;
  options.interrupt = &interrupt;
  CHECK_THROWS_WITH_AS(run_case(c, options), doctest::Contains("interrupted at step 0"), SimulationError);
  std::ifstream summary(dir / "summary.json");
  const std::string text((std::istreambuf_iterator<char>(summary)), std::istreambuf_iterator<char>());
  CHECK(text.find("\"status\": \"interrupted at step 0\"") != std::string::npos);
  CHECK(std::filesystem::exists(dir / "results.h5"));
}
