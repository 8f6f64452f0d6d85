// The linear elastic material point driven along prescribed strain paths,
// against Hooke's law in closed form (E = 1000 Pa, nu = 0.2 as in the uniaxial stress benchmark;
// lambda = 277.78 Pa, mu = 416.67 Pa). The update is incremental, so the
// path is applied in 100 increments; the result is linear, hence exact up
// to round-off (tolerance 1e-12 relative).
#include <doctest/doctest.h>

#include "materials/linear_elastic.hpp"

using namespace flowmpm;

namespace {

LinearElastic::Parameters steel_like_parameters() {
  LinearElastic::Parameters p;  // no transport, no expansion
  p.density = 1.0;
  p.youngs_modulus = 1000.0;
  p.poisson_ratio = 0.2;
  return p;
}

const LinearElastic steel_like(steel_like_parameters());

template <StressState S>
Voigt drive(const Voigt& total_strain, Voigt& strain_out) {
  Voigt sigma{};
  strain_out = {};
  LinearElastic::State state;
  for (int k = 0; k < 100; ++k) {
    Voigt deps;
    for (int i = 0; i < 6; ++i) deps[i] = total_strain[i] / 100.0;
    steel_like.update<S>(state, sigma, deps, MaterialInput{});
    for (int i = 0; i < 6; ++i) strain_out[i] += deps[i];
  }
  return sigma;
}

}  // namespace

TEST_CASE("3D: general strain against sigma = lambda tr(eps) I + 2 mu eps") {
  const Voigt eps{1e-3, -2e-4, 5e-4, 3e-4, -1e-4, 2e-4};
  Voigt strain;
  const Voigt sigma = drive<StressState::three_d>(eps, strain);
  const double E = 1000.0, nu = 0.2;
  const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
  const double tr = eps[0] + eps[1] + eps[2];
  for (int i = 0; i < 3; ++i) CHECK(sigma[i] == doctest::Approx(lambda * tr + 2 * mu * eps[i]).epsilon(1e-12));
  for (int i = 3; i < 6; ++i) CHECK(sigma[i] == doctest::Approx(2 * mu * eps[i]).epsilon(1e-12));
}

TEST_CASE("3D: uniaxial stress path gives sigma = E eps and no lateral stress") {
  // eps = (e, -nu e, -nu e) is the strain of uniaxial stress sigma_xx = E e.
  const double e = -1e-3;
  Voigt strain;
  const Voigt sigma = drive<StressState::three_d>({e, -0.2 * e, -0.2 * e, 0, 0, 0}, strain);
  CHECK(sigma[0] == doctest::Approx(1000.0 * e).epsilon(1e-12));
  CHECK(std::abs(sigma[1]) < 1e-12);
  CHECK(std::abs(sigma[2]) < 1e-12);
}

TEST_CASE("plane strain: sigma_zz = nu (sigma_xx + sigma_yy)") {
  Voigt strain;
  const Voigt sigma = drive<StressState::plane_strain>({1e-3, 4e-4, 0, 0, 0, 1e-4}, strain);
  CHECK(sigma[2] == doctest::Approx(0.2 * (sigma[0] + sigma[1])).epsilon(1e-12));
  CHECK(strain[2] == 0.0);
}

TEST_CASE("plane stress: sigma_zz = 0, sigma = E/(1-nu^2) [[1, nu], [nu, 1]] eps") {
  Voigt strain;
  const Voigt sigma = drive<StressState::plane_stress>({1e-3, 4e-4, 0, 0, 0, 1e-4}, strain);
  const double E = 1000.0, nu = 0.2, Q = E / (1 - nu * nu);
  CHECK(std::abs(sigma[2]) < 1e-12);
  CHECK(sigma[0] == doctest::Approx(Q * (1e-3 + nu * 4e-4)).epsilon(1e-12));
  CHECK(sigma[1] == doctest::Approx(Q * (4e-4 + nu * 1e-3)).epsilon(1e-12));
  CHECK(sigma[5] == doctest::Approx(E / (1 + nu) * 1e-4).epsilon(1e-12));
  CHECK(strain[2] == doctest::Approx(-nu / (1 - nu) * (1e-3 + 4e-4)).epsilon(1e-12));
}

TEST_CASE("1D uniaxial stress: sigma_xx = E eps_xx, lateral strains -nu eps_xx") {
  Voigt strain;
  const Voigt sigma = drive<StressState::uniaxial_stress>({2e-3, 0, 0, 0, 0, 0}, strain);
  CHECK(sigma[0] == doctest::Approx(2.0).epsilon(1e-12));
  CHECK(sigma[1] == 0.0);
  CHECK(sigma[2] == 0.0);
  CHECK(strain[1] == doctest::Approx(-0.2 * 2e-3).epsilon(1e-12));
  CHECK(strain[2] == doctest::Approx(-0.2 * 2e-3).epsilon(1e-12));
}

TEST_CASE("zero strain increment leaves the stress unchanged (zero stress at rest)") {
  Voigt strain;
  const Voigt sigma = drive<StressState::three_d>({0, 0, 0, 0, 0, 0}, strain);
  for (double s : sigma) CHECK(s == 0.0);
}

TEST_CASE("P-wave speed sqrt((lambda + 2 mu) / rho)") {
  // E = 1000, nu = 0.2, rho = 1: lambda + 2 mu = 1111.1 Pa, c = 33.33 m/s.
  CHECK(steel_like.wave_speed() == doctest::Approx(std::sqrt(1000.0 / 0.9)).epsilon(1e-12));
}
