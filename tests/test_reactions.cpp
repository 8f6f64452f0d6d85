// The reactions of the constrained node sets (tasks/grid_update.hpp
// measure_reactions; timeseries.csv reaction.<set>.<axis>), against statics.
//  - The 2D column under self weight on a fixed base (configs/verification/
//    column_self_weight_2d.toml): it oscillates about equilibrium, and over
//    whole periods of its fundamental mode (T = 4 H / c; the higher modes'
//    periods divide T) the base reaction averages to the weight,
//    rho g H w = 2 N/m. Linear shape functions: within 0.5 % (measured
//    0.16 % over one period; the discrete period differs a little from T).
//    bspline2: within 2 % (measured 1.0 %; there the base is a mirror plane
//    whose images share the support with the rollers' at the corners).
//  - The uniaxial-stress block (Case III, quasi-static): the top reaction
//    of a step is the force of the stresses at its start,
//    sum_p V_p sigma_yy,p / h (the top nodes move at a constant velocity, so
//    they carry no inertia), to round-off; and at t = 0.1 s it is
//    sigma_yy A = -1 N within 1.1 % (one step of load, 1 %, behind the
//    stress at the end of the step, and the volume change, 0.06 %).
#include <doctest/doctest.h>

#include "discretisation/shapes/shape_bspline.hpp"
#include "discretisation/shapes/shape_linear.hpp"
#include "test_helpers.hpp"

using namespace flowmpm;

namespace {

template <class Shape>
double mean_base_reaction(const std::string& shape) {
  const Case c = read_case(testing::config("verification/column_self_weight_2d.toml"),
                           {"analysis.shape_function=" + shape});
  auto sim = testing::simulation<2, Shape>(c);
  const auto& constraints = sim.system().constraints;
  const auto base = std::ranges::find_if(constraints, [](const NodeConstraint& k) { return k.name == "base" && k.axis == 1; });
  REQUIRE(base != constraints.end());
  double sum = 0.0;
  for (std::int64_t s = 0; s < c.time_control.steps; ++s) {
    sim.advance();
    sum += base->reaction;
  }
  return sum / static_cast<double>(c.time_control.steps);
}

}  // namespace

TEST_CASE("a column's base carries its weight, on average over a period") {
  // c = sqrt(M / rho) = 116.0 m/s, T = 4 H / c = 0.0345 s = the case's end time.
  const double weight = 1.0 * 10.0 * 1.0 * 0.2;
  CHECK(mean_base_reaction<LinearShape>("linear") == doctest::Approx(weight).epsilon(0.005));
  CHECK(mean_base_reaction<QuadraticBSpline>("bspline2") == doctest::Approx(weight).epsilon(0.02));
}

TEST_CASE("the loaded top of the uniaxial block reacts with the block's stress times its area") {
  const Case c = read_case(testing::config("uniaxial_stress/case3_usl.toml"));
  auto sim = testing::simulation<3, LinearShape>(c);
  auto& system = sim.system();
  const auto top = std::ranges::find_if(system.constraints, [](const NodeConstraint& k) { return k.name == "top"; });
  REQUIRE(top != system.constraints.end());
  const double h = system.grid.h[1];
  for (std::int64_t s = 0; s < c.time_control.steps; ++s) {
    double force = 0.0;  // sum_p V_p sigma_yy,p / h at the start of the step
    for (const auto& b : system.batches)
      for (std::size_t p = 0; p < b.size(); ++p) force += b.volume[p] * b.stress[p][1] / h;
    sim.advance();
    CAPTURE(s);
    CHECK(top->reaction == doctest::Approx(force).epsilon(1e-12).scale(1e-6));
  }
  CHECK(top->reaction == doctest::Approx(-1.0).epsilon(0.011));
}
