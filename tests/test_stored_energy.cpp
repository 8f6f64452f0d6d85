// The materials' stored energy (materials/material.hpp: stored_energy), the
// figure the diagnostics and the energy balance use, against closed forms.
// Work is integrated along each path by the trapezoidal rule, which is
// exact for a stress linear in the strain within each increment (all the
// paths below: elastic, perfectly plastic, linear softening, with the
// increments' kinks on the law's kinks), so the balances hold to round-off:
// 1e-12 of the work.
//  - Elastic loading: stored = work done, W = sigma : eps / 2.
//  - von Mises: stored = the elastic part, p^2 / (2K) + s : s / (4G), and
//    work - stored = the plastic work, sigma_Y eps_p for perfect plasticity.
//  - Strain softening: work = stored + the dissipation the state holds.
//  - Orthotropic with thermal expansion: a free expansion stores nothing; a
//    constrained one stores sigma : S : sigma / 2 (not sigma : eps / 2,
//    which would count the thermal strain).
#include <doctest/doctest.h>

#include <cmath>

#include "material_point_driver.hpp"

using namespace flowmpm;
using flowmpm::testing::MaterialPoint;
using flowmpm::testing::material_from_text;

namespace {

// Drives `p` by `n` equal increments of `deps` and returns the work done
// per unit volume, sum of (sigma_before + sigma_after) : deps / 2.
template <class Point>
double load(Point& p, const Voigt& deps, int n) {
  double work = 0.0;
  for (int k = 0; k < n; ++k) {
    const Voigt before = p.sigma;
    const Voigt eps_before = p.eps;
    p.strain(deps);
    Voigt d, mean;
    for (int i = 0; i < 6; ++i) {
      d[i] = p.eps[i] - eps_before[i];
      mean[i] = 0.5 * (before[i] + p.sigma[i]);
    }
    work += double_contraction(mean, d);
  }
  return work;
}

const std::string elastic = "density = 1000.0\nyoungs_modulus = 2e9\npoisson_ratio = 0.3\n";

}  // namespace

TEST_CASE("linear elastic: stored energy = work done = sigma : eps / 2") {
  const auto m = std::get<LinearElastic>(material_from_text("type = \"linear_elastic\"\n" + elastic));
  MaterialPoint<LinearElastic, StressState::three_d> p(m);
  const double work = load(p, {1e-4, -2e-5, 3e-5, 1e-5, -4e-5, 2e-5}, 10);
  CHECK(m.stored_energy(p.state, p.sigma, p.eps) == doctest::Approx(work).epsilon(1e-12));
  CHECK(m.stored_energy(p.state, p.sigma, p.eps) == doctest::Approx(0.5 * double_contraction(p.sigma, p.eps)));
}

TEST_CASE("von Mises: stored energy is the elastic part; the rest of the work is plastic") {
  const auto m = std::get<VonMises>(material_from_text("type = \"von_mises\"\n" + elastic +
                                                       "yield_stress = 2e6\nhardening = \"linear\"\nhardening_modulus = 0.0\n"));
  const double E = 2e9, sigma_Y = 2e6;
  SUBCASE("1D, perfectly plastic: stored sigma_Y^2 / (2E), plastic work sigma_Y eps_p") {
    MaterialPoint<VonMises, StressState::uniaxial_stress> p(m);
    // To 4 times the yield strain, in steps that land on the yield strain.
    const double work = load(p, {sigma_Y / E / 10.0, 0, 0, 0, 0, 0}, 40);
    CHECK(p.state.eps_p == doctest::Approx(3.0 * sigma_Y / E).epsilon(1e-12));
    const double stored = m.stored_energy(p.state, p.sigma, p.eps);
    CHECK(stored == doctest::Approx(sigma_Y * sigma_Y / (2.0 * E)).epsilon(1e-12));
    CHECK(work - stored == doctest::Approx(sigma_Y * p.state.eps_p).epsilon(1e-12));
    // What the engine reported before the contract, sigma : eps / 2, counts
    // the plastic strain as stored: here 4 times too much.
    CHECK(0.5 * double_contraction(p.sigma, p.eps) == doctest::Approx(4.0 * stored).epsilon(1e-12));
  }
  SUBCASE("3D uniaxial strain: stored p^2 / (2K) + s : s / (4G)") {
    MaterialPoint<VonMises, StressState::three_d> p(m);
    load(p, {1e-4, 0, 0, 0, 0, 0}, 50);  // 5e-3, beyond yield at sigma_Y / (2G) = 1.3e-3
    REQUIRE(p.state.eps_p > 0.0);
    const double pressure = (p.sigma[0] + p.sigma[1] + p.sigma[2]) / 3.0;
    Voigt s = p.sigma;
    for (int i = 0; i < 3; ++i) s[i] -= pressure;
    const double G = m.mu, K = m.K;
    CHECK(m.stored_energy(p.state, p.sigma, p.eps) ==
          doctest::Approx(pressure * pressure / (2.0 * K) + double_contraction(s, s) / (4.0 * G)).epsilon(1e-12));
    // On the yield surface, q = sigma_Y: the deviatoric part is sigma_Y^2 / (6G).
    CHECK(double_contraction(s, s) / (4.0 * G) == doctest::Approx(sigma_Y * sigma_Y / (6.0 * G)).epsilon(1e-10));
  }
}

TEST_CASE("strain softening: work = stored + dissipated, through damage to failure") {
  const auto m = std::get<StrainSoftening>(material_from_text(
      "type = \"strain_softening\"\n" + elastic + "initiation_strain = 1e-4\nfailure_strain = 7e-4\n"));
  MaterialPoint<StrainSoftening, StressState::uniaxial_stress> p(m);
  double work = 0.0;
  for (int k = 1; k <= 8; ++k) {  // to 8 eps_i, in steps of eps_i / 10
    work += load(p, {1e-4 / 10.0, 0, 0, 0, 0, 0}, 10);
    CAPTURE(k);
    CHECK(m.stored_energy(p.state, p.sigma, p.eps) + p.state.dissipated == doctest::Approx(work).epsilon(1e-12));
  }
  // Broken: nothing stored, all of (1/2) E eps_i eps_f dissipated.
  CHECK(m.stored_energy(p.state, p.sigma, p.eps) == 0.0);
  CHECK(p.state.dissipated == doctest::Approx(0.5 * 2e9 * 1e-4 * 7e-4).epsilon(1e-12));
}

TEST_CASE("orthotropic with thermal expansion: the expansion strain stores nothing") {
  const std::string poplar =
      "type = \"orthotropic\"\ndensity = 350.0\nEx = 9936e6\nEy = 914e6\nEz = 427e6\nGxy = 745e6\n"
      "Gxz = 686e6\nGyz = 109e6\nnuxy = 0.31\nnuxz = 0.39\nnuyz = 0.70\n"
      "alpha = [3e-6, 30e-6, 40e-6]\ntemperature_change = [[0.0, 0.0], [1.0, 40.0]]\n";
  const auto m = std::get<Orthotropic>(material_from_text(poplar));
  SUBCASE("free expansion: no stress, no stored energy") {
    MaterialPoint<Orthotropic, StressState::three_d> p(m);
    // Heated to dT = 40 K in 10 increments with the free strain alpha dT.
    for (int k = 0; k < 10; ++k) p.strain({3e-6 * 4.0, 30e-6 * 4.0, 40e-6 * 4.0, 0, 0, 0}, 0.1);
    for (double s : p.sigma) CHECK(std::abs(s) < 1e-6);
    CHECK(m.stored_energy(p.state, p.sigma, p.eps) < 1e-15);
  }
  SUBCASE("plane strain, heated: sigma_zz = -E_T alpha_T dT stores sigma_zz^2 / (2 E_T) and more") {
    MaterialPoint<Orthotropic, StressState::plane_strain> p(m);
    // In-plane strains free (mixed control), eps_zz held at 0.
    for (int k = 0; k < 10; ++k) p.mixed({0, 0, 0, 0, 0, 0}, {0, 1, 5}, 0.1);
    const Eigen::Vector3d sigma(p.sigma[0], p.sigma[1], p.sigma[2]);
    CHECK(std::abs(p.sigma[0]) < 1e-6 * std::abs(p.sigma[2]));
    CHECK(p.sigma[2] == doctest::Approx(-427e6 * 40e-6 * 40.0).epsilon(1e-9));
    const double expected = 0.5 * sigma.dot(Orthotropic::compliance(m.parameters) * sigma);
    CHECK(m.stored_energy(p.state, p.sigma, p.eps) == doctest::Approx(expected).epsilon(1e-12));
    CHECK(expected == doctest::Approx(p.sigma[2] * p.sigma[2] / (2.0 * 427e6)).epsilon(1e-9));
    // sigma : eps / 2 with eps_zz = 0 reports nothing of it.
    CHECK(std::abs(0.5 * double_contraction(p.sigma, p.eps)) < 1e-9 * expected);
  }
}
