// The stable time step (engine/stable_time_step.hpp, docs/STABILITY.md):
// every shape function and scheme runs 2000 steps at the largest time step
// the case reader accepts, on the vibrating bar (1D, a free end) and on the
// column settling under gravity (2D, free surfaces, roller sides), and the
// energy balance holds.
#include <doctest/doctest.h>

#include <cmath>
#include <string>

#include "engine/schemes.hpp"
#include "engine/stable_time_step.hpp"
#include "io/case/case_file.hpp"
#include "test_helpers.hpp"

using namespace flowmpm;

namespace {

// The case at the largest accepted dt, for 2000 steps.
RunSummary run_at_limit(const std::string& config, const std::string& scheme, const std::string& shape) {
  Case c = read_case(testing::config(config), {"analysis.scheme=" + scheme, "analysis.shape_function=" + shape});
  set_time_control(c, {.dt = stable_time_step(c.system, *c.scheme).dt(), .steps = 2000});
  return testing::run(c);
}

}  // namespace

TEST_CASE("2000 steps at the largest accepted time step: no blow-up, the energy balance holds") {
  // Measured balance errors at the limit: bar 1.2-2.6 %, column 0.5-6.2 %
  // (USF, first order, the largest); a blow-up takes it to 60-100 % within
  // a hundred steps (tests/test_energy_balance.cpp), and the guard stops it.
  for (const char* config : {"verification/bar_vibration_small.toml", "verification/column_self_weight_2d.toml"}) {
    for (const char* scheme : {"usl", "musl", "usf"}) {
      for (const char* shape : {"linear", "gimp", "bspline2", "bspline3"}) {
        CAPTURE(config);
        CAPTURE(scheme);
        CAPTURE(shape);
        const RunSummary s = run_at_limit(config, scheme, shape);
        CHECK(s.steps == 2000);
        CHECK(s.energy_error < 0.07);
      }
    }
  }
}
