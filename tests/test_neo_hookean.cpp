// The neo-Hookean material point (materials/neo_hookean.hpp) against its
// closed forms ([Bonet 2008], section 6.4.3), E = 1000 Pa and nu = 0.3
// (lambda = 576.92 Pa, mu = 384.62 Pa) unless said otherwise.
//
// Uniaxial stress, stretch l along x: the lateral stretch s makes the
// lateral stress zero, mu (s^2 - 1) + lambda ln(l s^2) = 0 (solved here by
// bisection), and then
//   sigma_xx = mu (l^2 - s^2) / J,   J = l s^2
// (sigma_xx minus the zero lateral stress). l = 1.5: s = 0.88017,
// sigma_xx = 488.29 Pa; l = 0.7: s = 1.10793, sigma_xx = -330.12 Pa
// (Hooke's law with the engineering strain gives 500 and -300 Pa, with
// the logarithmic strain 405.5 and -356.7 Pa). The brief asks for 1 %; the
// update is exact for the model up to the iterations' tolerances, so the
// tolerances below are those.
#include <doctest/doctest.h>

#include <cmath>

#include "discretisation/shapes/shape_linear.hpp"
#include "material_point_driver.hpp"
#include "materials/neo_hookean.hpp"
#include "test_helpers.hpp"

using namespace flowmpm;
using testing::MaterialPoint;

namespace {

NeoHookean::Parameters parameters(double nu = 0.3) {
  NeoHookean::Parameters p;
  p.density = 1.0;
  p.youngs_modulus = 1000.0;
  p.poisson_ratio = nu;
  return p;
}

const NeoHookean rubber(parameters());

// The lateral stretch of uniaxial stress at stretch l, by bisection.
double lateral_stretch(const NeoHookean& m, double l) {
  double lo = 0.1, hi = 10.0;
  auto f = [&](double s) { return m.mu * (s * s - 1.0) + m.lambda * std::log(l * s * s); };
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    ((f(mid) < 0.0) == (f(lo) < 0.0) ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

double uniaxial_stress(const NeoHookean& m, double l) {
  const double s = lateral_stretch(m, l);
  return m.mu * (l * l - s * s) / (l * s * s);
}

// The velocity-gradient increment along x of each of n steps whose
// midpoint factors (1 + d/2) / (1 - d/2) multiply to the stretch l.
double axial_increment(double l, int n) {
  const double r = std::pow(l, 1.0 / n);
  return 2.0 * (r - 1.0) / (r + 1.0);
}

}  // namespace

TEST_CASE("reading: the isotropic constants, checked; expansion refused") {
  const std::string good = "type = \"neo_hookean\"\ndensity = 1100.0\nyoungs_modulus = 2e6\npoisson_ratio = 0.45\n";
  const Material m = testing::material_from_text(good);
  REQUIRE(std::holds_alternative<NeoHookean>(m));
  CHECK(std::get<NeoHookean>(m).mu == doctest::Approx(2e6 / 2.9));
  auto error = [](const std::string& text) { return testing::material_error("type = \"neo_hookean\"\n" + text); };
  CHECK(error("density = -1.0\nyoungs_modulus = 2e6\npoisson_ratio = 0.3\n").find("density") != std::string::npos);
  CHECK(error("density = 1.0\nyoungs_modulus = 0.0\npoisson_ratio = 0.3\n").find("youngs_modulus") !=
        std::string::npos);
  const std::string nu = error("density = 1.0\nyoungs_modulus = 2e6\npoisson_ratio = 0.5\n");
  CHECK(nu.find("poisson_ratio") != std::string::npos);
  CHECK(nu.find("(-1, 0.5)") != std::string::npos);
  const std::string alpha = error("density = 1.0\nyoungs_modulus = 2e6\npoisson_ratio = 0.3\nalpha = 1e-5\n");
  CHECK(alpha.find("alpha") != std::string::npos);
  CHECK(alpha.find("no thermal or solvent expansion") != std::string::npos);
}

TEST_CASE("small strain: Hooke's law, and the P wave of the undeformed material") {
  // F = I + eps with |eps| = 1e-7: the stress is lambda tr(eps) I + 2 mu eps
  // to O(eps), relative 1e-6 allowing for it.
  const Voigt eps{1e-7, -4e-8, 6e-8, 2e-8, -3e-8, 5e-8};
  MaterialPoint<NeoHookean, StressState::three_d> point(rubber);
  point.strain(eps);
  const double tr = eps[0] + eps[1] + eps[2];
  for (int i = 0; i < 6; ++i) {
    const double hooke = 2.0 * rubber.mu * eps[i] + (i < 3 ? rubber.lambda * tr : 0.0);
    CHECK(point.sigma[i] == doctest::Approx(hooke).epsilon(1e-6));
  }
  CHECK(rubber.wave_speed() == doctest::Approx(std::sqrt((rubber.lambda + 2.0 * rubber.mu) / 1.0)));
}

TEST_CASE("uniaxial stress to 1.5 and 0.7 of the length: the closed form, in 1D, plane stress and 3D") {
  const int n = 200;
  for (double l : {1.5, 0.7}) {
    CAPTURE(l);
    const double expected = uniaxial_stress(rubber, l), s = lateral_stretch(rubber, l);
    const double d = axial_increment(l, n);
    // 1D: the model solves the lateral stretch (Newton to 1e-14 in ln s).
    MaterialPoint<NeoHookean, StressState::uniaxial_stress> bar(rubber);
    for (int k = 0; k < n; ++k) bar.strain({d, 0, 0, 0, 0, 0});
    CHECK(bar.state.F(0, 0) == doctest::Approx(l).epsilon(1e-13));
    CHECK(bar.sigma[0] == doctest::Approx(expected).epsilon(1e-12));
    CHECK(bar.state.F(1, 1) == doctest::Approx(s).epsilon(1e-12));
    CHECK(bar.eps[1] == doctest::Approx(std::log(s)).epsilon(1e-12));  // the log strain the engine sums
    // Plane stress with sigma_yy = 0 held by the driver (Newton on the
    // increment to 1e-13 of the stress), 3D with sigma_yy = sigma_zz = 0.
    MaterialPoint<NeoHookean, StressState::plane_stress> sheet(rubber);
    MaterialPoint<NeoHookean, StressState::three_d> block(rubber);
    for (int k = 0; k < n; ++k) {
      sheet.mixed({d, 0, 0, 0, 0, 0}, {1});
      block.mixed({d, 0, 0, 0, 0, 0}, {1, 2});
    }
    CHECK(sheet.sigma[0] == doctest::Approx(expected).epsilon(1e-10));
    CHECK(sheet.sigma[2] == 0.0);
    CHECK(std::abs(sheet.sigma[1]) < 1e-10 * std::abs(expected));
    CHECK(block.sigma[0] == doctest::Approx(expected).epsilon(1e-10));
    CHECK(block.state.F(2, 2) == doctest::Approx(s).epsilon(1e-10));
    CHECK(std::abs(block.sigma[1]) + std::abs(block.sigma[2]) < 1e-10 * std::abs(expected));
  }
}

TEST_CASE("plane strain keeps F_zz = 1: sigma_zz = lambda ln J / J") {
  MaterialPoint<NeoHookean, StressState::plane_strain> point(rubber);
  for (int k = 0; k < 100; ++k) {
    Eigen::Matrix3d dL = Eigen::Matrix3d::Zero();
    dL(0, 0) = 3e-3, dL(1, 1) = -1e-3, dL(0, 1) = 4e-3;
    point.step(dL);
  }
  const double J = point.state.F.determinant();
  CHECK(std::abs(point.state.F(2, 2) - 1.0) < 1e-14);  // the 3 x 3 inverse's round-off
  CHECK(point.sigma[2] == doctest::Approx(rubber.lambda * std::log(J) / J).epsilon(1e-12));
  double ratio;
  rubber.state_values(point.state, &ratio);
  CHECK(ratio == doctest::Approx(J).epsilon(1e-15));
}

TEST_CASE("the stored energy is the work of the stress along a path of stretch, shear and spin") {
  // Per unit reference volume, dW = J sigma : D dt; the trapezoidal sum
  // over 4000 steps of a general (non-symmetric) L is second order: 1e-6
  // relative, measured 4.3e-9 (W = 195 J/m^3, J = 1.28).
  MaterialPoint<NeoHookean, StressState::three_d> point(rubber);
  Eigen::Matrix3d L;
  L << 0.3, 0.5, -0.1, 0.2, -0.2, 0.3, 0.1, -0.4, 0.15;
  const int n = 4000;
  const Eigen::Matrix3d dL = L / n;
  const Voigt D = voigt_of(0.5 * (dL + dL.transpose()));
  double work = 0.0;
  for (int k = 0; k < n; ++k) {
    const double J0 = point.state.F.determinant();
    const Voigt s0 = point.sigma;
    point.step(dL);
    const double J1 = point.state.F.determinant();
    work += 0.5 * (J0 * double_contraction(s0, D) + J1 * double_contraction(point.sigma, D));
  }
  const double J = point.state.F.determinant();
  CHECK(J * rubber.stored_energy(point.state, point.sigma, point.eps) == doctest::Approx(work).epsilon(1e-6));
  CHECK(work > 0.0);
}

TEST_CASE("initial stress: the stretch V whose stress it is, in 3D and in 1D") {
  ParticleInit init;
  init.stress = {120.0, -40.0, 30.0, 25.0, -60.0, 80.0};
  const NeoHookean::State s = rubber.initial_state(init);
  CHECK((s.F - s.F.transpose()).norm() < 1e-15);  // no rotation
  // Newton stops at 1e-13 of 2 mu + |lambda| + max |s_i| = 1470 Pa in J sigma.
  const Voigt sigma = rubber.stress(s.F);
  for (int i = 0; i < 6; ++i) CHECK(std::abs(sigma[i] - init.stress[i]) < 2e-10);
  // A bar in uniaxial stress: the 1D update keeps it.
  init.stress = {250.0, 0, 0, 0, 0, 0};
  MaterialPoint<NeoHookean, StressState::uniaxial_stress> bar(rubber, init);
  bar.strain({0, 0, 0, 0, 0, 0});
  CHECK(std::abs(bar.sigma[0] - 250.0) < 2e-10);
  CHECK(rubber.initial_state(ParticleInit{}).F == Eigen::Matrix3d::Identity());
}

TEST_CASE("whole case: CB-Geo's cube of neo-Hookean material compressed to 0.7 of its height") {
  // configs/uniaxial_stress/case1_usl.toml (one 1 m cell, 2 x 2 x 2
  // particles, the bottom held in y, x and z free; E = 1000 Pa, nu = 0.2)
  // with the top nodes at -0.1 m/s for 3.57 s: the material follows the
  // grid's affine field, each step multiplying F_yy by (1 + d/2) / (1 - d/2),
  // d = -0.1 dt, to l = 0.69977. Closed form: sigma_yy = mu (l^2 - s^2) / J
  // = -341.17 Pa, s = 1.07085. Measured in every particle: sigma_yy 1.8e-6
  // and F_xx 4.4e-7 from it (the free sides' lateral inertia); the brief
  // asks for 1 %, asserted 1e-4 and 1e-5.
  const Case c = read_case(testing::config("uniaxial_stress/case1_usl.toml"),
                           {"materials.elastic.type=neo_hookean", "node_sets.1.velocity={ y = -0.1 }",
                            "analysis.end_time=3.57"});
  auto sim = testing::simulation<3, LinearShape>(c);
  const double dt = c.time_step.fixed_dt();
  int steps = 0;
  while (sim.system().t < c.time_step.end_time() - 0.5 * dt) sim.advance(), ++steps;
  const double d = -0.1 * dt, l = std::pow((1.0 + 0.5 * d) / (1.0 - 0.5 * d), steps);
  const NeoHookean& m = std::get<NeoHookean>(c.system.materials[0].model);
  const double s = lateral_stretch(m, l), expected = m.mu * (l * l - s * s) / (l * s * s);
  const auto& b = sim.system().batches[0];
  const auto& states = std::get<StateArray<NeoHookean>>(b.states);
  for (std::size_t p = 0; p < b.size(); ++p) {
    CAPTURE(p);
    CHECK(b.stress[p][1] == doctest::Approx(expected).epsilon(1e-4));
    CHECK(states[p].F(1, 1) == doctest::Approx(l).epsilon(1e-9));
    CHECK(states[p].F(0, 0) == doctest::Approx(s).epsilon(1e-5));
  }
}
