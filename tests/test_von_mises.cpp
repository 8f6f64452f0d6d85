// Von Mises plasticity (materials/von_mises.hpp) at a material point and in
// a whole case, against closed forms ([Wilkins 1964], [Simo 1998];
// NairnMPM's materials notes). Steel-like: E = 200 GPa, nu = 0.3,
// sigma_0 = 250 MPa, linear hardening H = 2 GPa, or the power law
// sigma_Y = sigma_0 (1 + eps_p / 0.01)^0.2.
//
// Tolerances:
//  - Linear hardening: the 3D and plane-strain return is closed form and
//    the paths are piecewise linear, so yield points and slopes hold to
//    round-off: 1e-10 relative. Plane stress and the power law converge
//    their Newton iterations to 1e-12 of the trial stress: 1e-9.
//  - Mixed control: the driver zeroes the free stresses to 1e-13 of the
//    largest stress (tests/material_point_driver.hpp): 1e-9.
//  - Plane strain uniaxial stress tends to sigma_xx = 2 sigma_0 / sqrt(3)
//    as the elastic part of eps_zz decays, exponentially in eps_p E /
//    sigma_0; at 40 yield strains it is within 1e-6.
//  - Whole case (1D bar, quasi-static loading with a smooth velocity
//    ramp, 40 particles): the inertial and wave error of the mean stress
//    is of the order (T / t_ramp)^2 = 1e-2 of the ramp's dynamic stress
//    rho c v = 1.4 MPa, 1e-4 of sigma_0 (measured 7e-5 on the yield strain);
//    one step loads 1.4e-4 of the yield strain: yield load, yield strain and
//    the hardening slope within 0.1 %. The same for the 2D plate (16
//    particles, plane stress and plane strain; measured 3e-5 and 2e-4).
#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "discretisation/shapes/shape_linear.hpp"
#include "engine/simulation.hpp"
#include "material_point_driver.hpp"
#include "test_helpers.hpp"

using namespace flowmpm;
using flowmpm::testing::MaterialPoint;
using flowmpm::testing::material_from_text;
using flowmpm::testing::material_error;

namespace {

constexpr double E = 200e9, nu = 0.3, sigma0 = 250e6, H = 2e9;
constexpr double G = E / (2 * (1 + nu)), K = E / (3 * (1 - 2 * nu));
constexpr double eps_y = sigma0 / E;

const std::string elastic = "type = \"von_mises\"\ndensity = 7850.0\nyoungs_modulus = 200e9\npoisson_ratio = 0.3\n"
                            "yield_stress = 250e6\n";
VonMises linear_hardening(double h = H) {
  return std::get<VonMises>(material_from_text(elastic + "hardening = \"linear\"\nhardening_modulus = " +
                                               std::to_string(h) + "\n"));
}
VonMises power_law() {
  return std::get<VonMises>(material_from_text(
      elastic + "hardening = \"power\"\nreference_strain = 0.01\nhardening_exponent = 0.2\n"));
}

double q_of(const Voigt& s) {
  const double p = (s[0] + s[1] + s[2]) / 3;
  Voigt d = s;
  for (int i = 0; i < 3; ++i) d[i] -= p;
  return std::sqrt(1.5 * double_contraction(d, d));
}

// Uniaxial stress along x to eps_x in n increments, by the stress state's
// own means: 1D directly, plane stress with sigma_yy = sigma_xy = 0 solved,
// 3D with every other stress solved.
template <StressState S>
void pull(MaterialPoint<VonMises, S>& p, double d_eps, int n) {
  for (int k = 0; k < n; ++k) {
    if constexpr (S == StressState::uniaxial_stress) p.strain({d_eps, 0, 0, 0, 0, 0});
    if constexpr (S == StressState::plane_stress) p.mixed({d_eps, 0, 0, 0, 0, 0}, {1, 5});
    if constexpr (S == StressState::three_d) p.mixed({d_eps, 0, 0, 0, 0, 0}, {1, 2, 3, 4, 5});
  }
}

template <StressState S>
void check_uniaxial(double tol) {
  const VonMises m = linear_hardening();
  MaterialPoint<VonMises, S> p(m);
  // Just below and at the yield strain: elastic, sigma = E eps.
  pull(p, eps_y / 10 * (1 - 1e-9), 10);
  CHECK(p.state.eps_p == 0.0);
  CHECK(p.sigma[0] == doctest::Approx(sigma0 * (1 - 1e-9)).epsilon(tol));
  // Post-yield slope E H / (E + H) and the plastic strain eps - sigma / E.
  pull(p, eps_y / 10, 10);
  const double s1 = p.sigma[0], e1 = p.eps[0];
  pull(p, eps_y / 10, 10);
  const double tangent = E * H / (E + H);
  CHECK((p.sigma[0] - s1) / (p.eps[0] - e1) == doctest::Approx(tangent).epsilon(1e3 * tol));
  CHECK(p.state.eps_p == doctest::Approx(p.eps[0] - p.sigma[0] / E).epsilon(tol));
  CHECK(q_of(p.sigma) == doctest::Approx(sigma0 + H * p.state.eps_p).epsilon(tol));
  // Lateral strains: -nu sigma / E elastic, -eps_p / 2 plastic.
  CHECK(p.eps[1] == doctest::Approx(-nu * p.sigma[0] / E - 0.5 * p.state.eps_p).epsilon(1e3 * tol));
  // Unloading is elastic with slope E.
  const double s2 = p.sigma[0], ep2 = p.state.eps_p;
  pull(p, -eps_y / 10, 5);
  CHECK((s2 - p.sigma[0]) == doctest::Approx(E * eps_y / 2).epsilon(1e3 * tol));
  CHECK(p.state.eps_p == ep2);
}

}  // namespace

TEST_CASE("uniaxial stress: yield at sigma_0, post-yield slope E H / (E + H), elastic unloading") {
  SUBCASE("1D") { check_uniaxial<StressState::uniaxial_stress>(1e-10); }
  SUBCASE("3D (lateral stresses held at zero)") { check_uniaxial<StressState::three_d>(1e-9); }
  SUBCASE("plane stress (sigma_yy held at zero)") { check_uniaxial<StressState::plane_stress>(1e-9); }
}

TEST_CASE("plane strain, uniaxial stress: yield at sigma_0 / sqrt(1 - nu + nu^2), limit 2 sigma_0 / sqrt(3)") {
  const VonMises m = linear_hardening(0.0);
  MaterialPoint<VonMises, StressState::plane_strain> p(m);
  // Elastic: sigma_zz = nu sigma_xx, q = sigma_xx sqrt(1 - nu + nu^2), eps_xx = (1 - nu^2) sigma_xx / E.
  const double sigma_yield = sigma0 / std::sqrt(1 - nu + nu * nu);
  const double eps_yield = (1 - nu * nu) * sigma_yield / E;
  for (int k = 0; k < 10; ++k) p.mixed({eps_yield / 10 * (1 - 1e-9), 0, 0, 0, 0, 0}, {1, 5});
  CHECK(p.state.eps_p == 0.0);
  CHECK(p.sigma[0] == doctest::Approx(sigma_yield * (1 - 1e-9)).epsilon(1e-10));
  CHECK(p.sigma[2] == doctest::Approx(nu * p.sigma[0]).epsilon(1e-9));
  p.mixed({1e-6 * eps_yield, 0, 0, 0, 0, 0}, {1, 5});
  CHECK(p.state.eps_p > 0.0);
  for (int k = 0; k < 400; ++k) p.mixed({eps_y / 10, 0, 0, 0, 0, 0}, {1, 5});
  CHECK(p.sigma[0] == doctest::Approx(2 * sigma0 / std::sqrt(3.0)).epsilon(1e-6));
  CHECK(q_of(p.sigma) == doctest::Approx(sigma0).epsilon(1e-12));
}

TEST_CASE("equal biaxial strain, plane strain and 3D: yield at sigma_0 / (2 G), slope 2 K + 2 G H / (3 (3 G + H))") {
  const VonMises m = linear_hardening();
  const double eps_yield = sigma0 / (2 * G);
  MaterialPoint<VonMises, StressState::plane_strain> p(m);
  MaterialPoint<VonMises, StressState::three_d> p3(m);
  const Voigt d{eps_yield / 10 * (1 - 1e-9), eps_yield / 10 * (1 - 1e-9), 0, 0, 0, 0};
  for (int k = 0; k < 10; ++k) p.strain(d), p3.strain(d);
  CHECK(p.state.eps_p == 0.0);
  CHECK(q_of(p.sigma) == doctest::Approx(sigma0 * (1 - 1e-9)).epsilon(1e-10));
  const Voigt d2{eps_yield / 10, eps_yield / 10, 0, 0, 0, 0};
  for (int k = 0; k < 10; ++k) p.strain(d2), p3.strain(d2);
  const double s1 = p.sigma[0], e1 = p.eps[0];
  for (int k = 0; k < 10; ++k) p.strain(d2), p3.strain(d2);
  CHECK(p.state.eps_p > 0.0);
  CHECK((p.sigma[0] - s1) / (p.eps[0] - e1) == doctest::Approx(2 * K + 2 * G * H / (3 * (3 * G + H))).epsilon(1e-9));
  // The pressure is elastic, p = 2 K eps; plane strain is 3D with eps_zz = 0.
  CHECK((p.sigma[0] + p.sigma[1] + p.sigma[2]) / 3 == doctest::Approx(2 * K * p.eps[0]).epsilon(1e-10));
  for (int i = 0; i < 6; ++i) CHECK(p3.sigma[i] == doctest::Approx(p.sigma[i]).epsilon(1e-12));
}

TEST_CASE("equal biaxial strain, plane stress: yield at (1 - nu) sigma_0 / E, slope 1 / ((1 - nu) / E + 1 / (2 H))") {
  const VonMises m = linear_hardening();
  const double eps_yield = (1 - nu) * sigma0 / E;
  MaterialPoint<VonMises, StressState::plane_stress> p(m);
  MaterialPoint<VonMises, StressState::three_d> p3(m);
  auto load = [&](double d, int n) {
    for (int k = 0; k < n; ++k) p.strain({d, d, 0, 0, 0, 0}), p3.mixed({d, d, 0, 0, 0, 0}, {2});
  };
  load(eps_yield / 10 * (1 - 1e-9), 10);
  CHECK(p.state.eps_p == 0.0);
  CHECK(p.sigma[0] == doctest::Approx(sigma0 * (1 - 1e-9)).epsilon(1e-10));
  load(eps_yield / 10, 10);
  const double s1 = p.sigma[0], e1 = p.eps[0];
  load(eps_yield / 10, 10);
  CHECK((p.sigma[0] - s1) / (p.eps[0] - e1) == doctest::Approx(1 / ((1 - nu) / E + 1 / (2 * H))).epsilon(1e-9));
  CHECK(p.sigma[0] == doctest::Approx(sigma0 + H * p.state.eps_p).epsilon(1e-9));
  CHECK(p.sigma[2] == 0.0);
  // eps_zz = -2 nu sigma / E - eps_p (elastic plus plastic incompressibility).
  CHECK(p.eps[2] == doctest::Approx(-2 * nu * p.sigma[0] / E - p.state.eps_p).epsilon(1e-9));
  // The 3D return with sigma_zz held at zero by the driver agrees.
  CHECK(p3.sigma[0] == doctest::Approx(p.sigma[0]).epsilon(1e-9));
  CHECK(p3.state.eps_p == doctest::Approx(p.state.eps_p).epsilon(1e-8));
}

TEST_CASE("power-law hardening: sigma = sigma_0 (1 + eps_p / eps_0)^n on the uniaxial path") {
  const VonMises m = power_law();
  auto check = [&](const Voigt& sigma, double eps_x, double eps_p) {
    CHECK(eps_p == doctest::Approx(eps_x - sigma[0] / E).epsilon(1e-9));
    CHECK(sigma[0] == doctest::Approx(sigma0 * std::pow(1 + eps_p / 0.01, 0.2)).epsilon(1e-9));
  };
  MaterialPoint<VonMises, StressState::uniaxial_stress> p1(m);
  MaterialPoint<VonMises, StressState::three_d> p3(m);
  MaterialPoint<VonMises, StressState::plane_stress> ps(m);
  pull(p1, eps_y / 4, 80);  // to 20 yield strains, eps_p about 0.024
  pull(p3, eps_y / 4, 80);
  pull(ps, eps_y / 4, 80);
  check(p1.sigma, p1.eps[0], p1.state.eps_p);
  check(p3.sigma, p3.eps[0], p3.state.eps_p);
  check(ps.sigma, ps.eps[0], ps.state.eps_p);
  CHECK(p1.state.eps_p > 0.02);
}

TEST_CASE("plane stress: Wilkins' return keeps sigma_zz = 0 and equals the 3D return with the same eps_zz") {
  // A non-proportional in-plane path (stretch x, shear, stretch y,
  // unload x), large increments included; the 3D point is driven with the
  // eps_zz increments the plane-stress model returned.
  for (const VonMises& m : {linear_hardening(), linear_hardening(0.0), power_law()}) {
    MaterialPoint<VonMises, StressState::plane_stress> ps(m);
    MaterialPoint<VonMises, StressState::three_d> p3(m);
    const Voigt path[] = {{2e-4, 0, 0, 0, 0, 0}, {0, 0, 0, 0, 0, 3e-4}, {0, 5e-4, 0, 0, 0, 0},
                          {-1e-3, 0, 0, 0, 0, 0}, {2e-2, 1e-2, 0, 0, 0, 0}};
    for (const Voigt& d : path) {
      for (int k = 0; k < 10; ++k) {
        const double eps_zz = ps.eps[2];
        ps.strain(d);
        Voigt d3 = d;
        d3[2] = ps.eps[2] - eps_zz;
        p3.strain(d3);
        CHECK(ps.sigma[2] == 0.0);
        CHECK(std::abs(p3.sigma[2]) <= 1e-9 * sigma0);
        for (int i : {0, 1, 5}) CHECK(p3.sigma[i] == doctest::Approx(ps.sigma[i]).epsilon(1e-9));
        CHECK(p3.state.eps_p == doctest::Approx(ps.state.eps_p).epsilon(1e-9));
        if (ps.state.eps_p > 0.0 && k == 9) {
          CHECK(q_of(ps.sigma) <= m.yield_stress(ps.state.eps_p) * (1 + 1e-9));
        }
      }
    }
    CHECK(ps.state.eps_p > 0.01);
    CHECK(q_of(ps.sigma) == doctest::Approx(m.yield_stress(ps.state.eps_p)).epsilon(1e-9));
  }
}

TEST_CASE("a Newton iteration that cannot converge is a clear error") {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  MaterialPoint<VonMises, StressState::plane_stress> ps(linear_hardening());
  CHECK_THROWS_WITH_AS(ps.strain({nan, 0, 0, 0, 0, 0}),
                       doctest::Contains("plane-stress return (Newton on Wilkins' factor M) did not converge to "
                                         "|residual| <= 1e-12 q_trial in 50 iterations"),
                       std::runtime_error);
  MaterialPoint<VonMises, StressState::three_d> p3(power_law());
  CHECK_THROWS_WITH_AS(p3.strain({nan, 0, 0, 0, 0, 0}), doctest::Contains("power-law return did not converge"),
                       std::runtime_error);
}

TEST_CASE("objectivity: a rigid rotation turns the stress and causes no plastic flow") {
  const VonMises m = linear_hardening();
  MaterialPoint<VonMises, StressState::three_d> p(m);
  for (int k = 0; k < 20; ++k) p.strain({2e-4, -1e-4, 0, 5e-5, 0, 1e-4});
  const Voigt sigma0_ = p.sigma;
  const double eps_p = p.state.eps_p;
  CHECK(eps_p > 0.0);
  const Eigen::Vector3d n = Eigen::Vector3d(1, 2, 3).normalized();
  const double angle = std::numbers::pi / 2;
  const Eigen::Vector3d w = 2 * std::tan(0.5 * angle / 200) * n;  // Cayley steps summing to 90 degrees
  Eigen::Matrix3d W;
  W << 0, -w.z(), w.y(), w.z(), 0, -w.x(), -w.y(), w.x(), 0;
  for (int k = 0; k < 200; ++k) p.step(W);
  const Eigen::Matrix3d Q = Eigen::AngleAxisd(angle, n).toRotationMatrix();
  const Voigt expected = voigt_of(Q * tensor_of(sigma0_) * Q.transpose());
  for (int i = 0; i < 6; ++i) CHECK(std::abs(p.sigma[i] - expected[i]) <= 1e-11 * sigma0);
  // The turned stress lies on the yield surface up to round-off, which may
  // flow by as much.
  CHECK(p.state.eps_p == doctest::Approx(eps_p).epsilon(1e-12));
}

TEST_CASE("validation") {
  CHECK(material_error(elastic).find("hardening: missing required key") != std::string::npos);
  CHECK(material_error(elastic + "hardening = \"linear\"\n").find("hardening_modulus: missing required key") != std::string::npos);
  CHECK(material_error(elastic + "hardening = \"linear\"\nhardening_modulus = 1e9\nhardening_exponent = 0.2\n")
            .find("hardening_exponent: expected no power-law parameter with hardening = \"linear\"") != std::string::npos);
  CHECK(material_error(elastic + "hardening = \"power\"\nreference_strain = 0.01\nhardening_exponent = 1.5\n")
            .find("hardening_exponent: expected a hardening exponent n in (0, 1]") != std::string::npos);
  CHECK(material_error(elastic + "hardening = \"cubic\"\n").find("hardening: expected one of \"linear\", \"power\"") != std::string::npos);
  CHECK(material_error("type = \"von_mises\"\ndensity = 7850.0\nyoungs_modulus = 200e9\npoisson_ratio = 0.3\n"
                 "yield_stress = -1.0\nhardening = \"linear\"\nhardening_modulus = 0.0\n")
            .find("yield_stress: expected a positive initial yield stress") != std::string::npos);
}

TEST_CASE("whole case: a bar pulled in uniaxial stress yields at sigma_0 and hardens with slope E H / (E + H)") {
  // configs/materials/von_mises_bar.toml: 1D steel bar, 0.1 m, 40
  // particles, held at x = 0 and pulled at x = 0.1 m to twice the yield
  // strain with a smooth velocity ramp.
  const Case c = read_case(testing::config("materials/von_mises_bar.toml"));
  auto sim = testing::simulation<1, LinearShape>(c);
  double yield_strain = -1.0, yield_stress = 0.0;
  for (std::int64_t s = 0; s < c.time_control.steps; ++s) {
    sim.advance();
    if (yield_strain >= 0.0) continue;
    const auto& states = std::get<StateArray<VonMises>>(sim.system().batches[0].states);
    for (const auto& st : states) {
      if (st.eps_p > 0.0) {
        const BodyMeans b = sim.diagnostics(1).bodies[0];
        yield_strain = b.strain[0], yield_stress = b.stress[0];
        break;
      }
    }
  }
  const BodyMeans end = sim.diagnostics(1).bodies[0];
  const double eps_p = end.strain[0] - end.stress[0] / E;
  MESSAGE("J2 bar: first yield at mean eps = " << yield_strain << " (sigma_0 / E = " << eps_y << "), mean sigma = "
          << yield_stress << " Pa; end: eps = " << end.strain[0] << ", sigma = " << end.stress[0]
          << " Pa (sigma_0 + H eps_p = " << sigma0 + H * eps_p << ")");
  CHECK(yield_stress == doctest::Approx(sigma0).epsilon(1e-3));
  CHECK(yield_strain == doctest::Approx(eps_y).epsilon(1e-3));
  CHECK(end.strain[0] == doctest::Approx(2 * eps_y).epsilon(1e-3));
  CHECK(end.stress[0] == doctest::Approx(sigma0 + H * eps_p).epsilon(1e-3));
  // The hardening part alone, E H / (E + H) eps_y = 2.475 MPa, within 1 %.
  CHECK(end.stress[0] - sigma0 == doctest::Approx(E * H / (E + H) * (end.strain[0] - eps_y)).epsilon(1e-2));
}

TEST_CASE("whole case: a plate pulled in plane stress yields at sigma_0, in plane strain at sigma_0 / sqrt(1 - nu + nu^2)") {
  // configs/materials/von_mises_plate.toml: 10 mm square, 16 particles,
  // pulled in y to twice the yield strain, x free.
  for (const std::string state : {"plane_stress", "plane_strain"}) {
    CAPTURE(state);
    const Case c = read_case(testing::config("materials/von_mises_plate.toml"),
                             {"analysis.stress_state=\"" + state + "\""});
    auto sim = testing::simulation<2, LinearShape>(c);
    double yield_stress = -1.0;
    for (std::int64_t s = 0; s < c.time_control.steps; ++s) {
      sim.advance();
      if (yield_stress >= 0.0) continue;
      for (const auto& st : std::get<StateArray<VonMises>>(sim.system().batches[0].states)) {
        if (st.eps_p > 0.0) {
          yield_stress = sim.diagnostics(1).bodies[0].stress[1];
          break;
        }
      }
    }
    const BodyMeans end = sim.diagnostics(1).bodies[0];
    const bool plane_stress = state == "plane_stress";
    const double expected = plane_stress ? sigma0 : sigma0 / std::sqrt(1 - nu + nu * nu);
    MESSAGE(state << " plate: first yield at mean sigma_yy = " << yield_stress << " Pa (analytical " << expected
            << "); end: eps_yy = " << end.strain[1] << ", sigma_yy = " << end.stress[1] << " Pa, sigma_xx = "
            << end.stress[0] << " Pa, sigma_zz = " << end.stress[2] << " Pa");
    CHECK(yield_stress == doctest::Approx(expected).epsilon(1e-3));
    CHECK(std::abs(end.stress[0]) < 1e-3 * sigma0);
    if (plane_stress) {
      CHECK(end.stress[2] == 0.0);
      CHECK(end.stress[1] == doctest::Approx(sigma0 + E * H / (E + H) * (end.strain[1] - eps_y)).epsilon(1e-3));
    }
  }
}
