// The uniaxial stress benchmark of [CB-Geo] (one 1 m cell, 8 particles,
// top nodes moving at -0.01 m/s, E = 1000 Pa, nu = 0.2), every case and
// scheme, at t = 0.1 s.
//
// Analytical: eps_yy = -0.001, sigma_yy = -1 Pa, eps_xx = eps_zz = 0.0002,
// sigma_xx = sigma_zz = 0. The block is loaded from rest, so its lateral
// inertia makes the lateral strain lag and the lateral stress oscillate:
// the error is set by how fast the loading is compared with the lateral
// period. Tolerances:
//  - eps_yy is imposed by the constrained nodes: round-off only (1e-12).
//  - Case III is quasi-static (density 0.01): within 0.2 % on sigma_yy and
//    eps_xx for every scheme, |sigma_xx| < 0.2 % of |sigma_yy|.
//  - Cases I and II carry the lateral-inertia error; they must match the
//    benchmark's published USF and USL values to the digits published: strains
//    published to 3 significant digits (tolerance 1e-6, half a unit of the
//    last digit plus the scheme's detail), stresses to 5e-4 Pa (0.05 % of
//    sigma_yy; see docs/validation/uniaxial_stress.md for where flowmpm and the published code differ).
//  - MUSL equals USF exactly in this benchmark: with zero initial stress and
//    no body force, MUSL's stress sequence is USF's with the particle
//    velocities one update later (docs/validation/uniaxial_stress.md), so they agree to round-off.
#include <doctest/doctest.h>

#include <cmath>

#include "app/run_case.hpp"
#include "test_helpers.hpp"

using namespace flowmpm;

namespace {

struct Result {
  double eps_yy, eps_xx, sigma_yy, sigma_xx, eps_zz, sigma_zz;
};

Result run(int case_number, const std::string& scheme) {
  const Case c = read_case(
      testing::config("uniaxial_stress/case" + std::to_string(case_number) + "_" + scheme + ".toml"));
  const RunSummary s = testing::run(c);
  REQUIRE(s.steps == (case_number == 1 ? 10 : 100));
  REQUIRE(s.end_time == doctest::Approx(0.1).epsilon(1e-12));
  const auto& b = s.bodies.at(0);
  return {b.mean_strain[1], b.mean_strain[0], b.mean_stress[1], b.mean_stress[0], b.mean_strain[2], b.mean_stress[2]};
}

struct Published {
  double eps_xx, sigma_yy, sigma_xx;
};
// Seed 000, USF and USL results at 0.1 s, cases I-III.
const Published usf_published[3] = {{0.000231, -0.982638, 0.043406},
                                    {0.00023, -0.983478, 0.041306},
                                    {0.000201, -0.999406, 0.001485}};
const Published usl_published[3] = {{0.000201, -0.999476, 0.0131},
                                    {0.000224, -0.986596, 0.033509},
                                    {0.0002, -1.0, 1.595325e-07}};

void check_against_published(const Result& r, const Published& p, bool check_sigma_xx) {
  CHECK(std::abs(r.eps_xx - p.eps_xx) < 1e-6);
  CHECK(std::abs(r.sigma_yy - p.sigma_yy) < 5e-4);
  if (check_sigma_xx) CHECK(std::abs(r.sigma_xx - p.sigma_xx) < 5e-4);
}

}  // namespace

TEST_CASE("every case and scheme: axial strain imposed exactly, lateral symmetry") {
  for (int k = 1; k <= 3; ++k) {
    for (const char* scheme : {"usf", "usl", "musl"}) {
      CAPTURE(k);
      CAPTURE(scheme);
      const Result r = run(k, scheme);
      CHECK(std::abs(r.eps_yy + 0.001) < 1e-12);
      CHECK(r.eps_zz == doctest::Approx(r.eps_xx).epsilon(1e-12));
      CHECK(r.sigma_zz == doctest::Approx(r.sigma_xx).epsilon(1e-9));
    }
  }
}

TEST_CASE("Case III (quasi-static) is close to analytical for every scheme") {
  for (const char* scheme : {"usf", "usl", "musl"}) {
    CAPTURE(scheme);
    const Result r = run(3, scheme);
    CHECK(r.sigma_yy == doctest::Approx(-1.0).epsilon(2e-3));
    CHECK(r.eps_xx == doctest::Approx(0.0002).epsilon(2e-2));
    CHECK(std::abs(r.sigma_xx) < 2e-3);
  }
}

TEST_CASE("USF matches the published values of cases I-III") {
  for (int k = 1; k <= 3; ++k) {
    CAPTURE(k);
    check_against_published(run(k, "usf"), usf_published[k - 1], true);
  }
}

TEST_CASE("USL matches the published values of cases I-III") {
  for (int k = 1; k <= 3; ++k) {
    CAPTURE(k);
    // The published USL Case I sigma_xx (0.0131) contradicts its own strains:
    // Hooke's law with eps_xx = eps_zz = 0.000201, eps_yy = -0.001 gives
    // sigma_xx = 0.0014 Pa (docs/validation/uniaxial_stress.md); flowmpm gives 0.0013.
    check_against_published(run(k, "usl"), usl_published[k - 1], k != 1);
  }
  const Result r = run(1, "usl");
  const double lambda = 1000.0 * 0.2 / (1.2 * 0.6), mu = 1000.0 / 2.4;
  const double hooke = lambda * (r.eps_xx + r.eps_yy + r.eps_zz) + 2 * mu * r.eps_xx;
  CHECK(r.sigma_xx == doctest::Approx(hooke).epsilon(1e-9));
}

TEST_CASE("MUSL equals USF when the initial stress and the body force are zero") {
  for (int k = 1; k <= 3; ++k) {
    CAPTURE(k);
    const Result usf = run(k, "usf"), musl = run(k, "musl");
    CHECK(musl.sigma_yy == doctest::Approx(usf.sigma_yy).epsilon(1e-12));
    CHECK(musl.sigma_xx == doctest::Approx(usf.sigma_xx).epsilon(1e-9));
    CHECK(musl.eps_xx == doctest::Approx(usf.eps_xx).epsilon(1e-12));
  }
}
