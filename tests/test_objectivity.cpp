// Objectivity: a pre-stressed material turned rigidly a quarter turn keeps
// its stress along the material direction it was in (the stress turns with
// the body and a rigid rotation does not load it), for linear_elastic
// (Hughes-Winget rate), neo_hookean (F carried) and orthotropic (axes and
// strain in material axes carried). The brief's bound is 1 % of the stress;
// a material point turned by a pure spin is exact to round-off.
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>

#include "material_point_driver.hpp"

using namespace flowmpm;
using testing::MaterialPoint;

namespace {

constexpr double pi = std::numbers::pi;

// A point stressed sigma0 along x (plane strain, so sigma_zz too where
// the model carries it), turned a quarter turn about z in n steps of the
// spin increment whose Cayley rotations add up to pi / 2 (each
// 2 atan(w / 2) = pi / (2 n)). Returns the stress after the turn.
template <class Model>
Voigt quarter_turn(const Model& model, const Voigt& sigma0, int n = 1000) {
  ParticleInit init;
  init.stress = sigma0;
  MaterialPoint<Model, StressState::plane_strain> point(model, init);
  point.sigma = sigma0;
  const double w = 2.0 * std::tan(pi / (4.0 * n));
  Eigen::Matrix3d dL = Eigen::Matrix3d::Zero();
  dL(0, 1) = -w, dL(1, 0) = w;
  for (int k = 0; k < n; ++k) point.step(dL);
  return point.sigma;
}

// After a quarter turn about z the x axis is along y: sigma_yy takes
// sigma0's xx, sigma_xx its yy, sigma_xy changes sign; zz stays.
void check_turned(const Voigt& sigma, const Voigt& sigma0) {
  const double tolerance = 1e-12 * std::abs(sigma0[0]);
  CHECK(std::abs(sigma[1] - sigma0[0]) < tolerance);
  CHECK(std::abs(sigma[0] - sigma0[1]) < tolerance);
  CHECK(std::abs(sigma[2] - sigma0[2]) < tolerance);
  CHECK(std::abs(sigma[5] + sigma0[5]) < tolerance);
}

}  // namespace

TEST_CASE("a bar's axial stress turns with it a quarter turn: linear_elastic, neo_hookean, orthotropic") {
  const Voigt sigma0{1.0e3, 0.0, 300.0, 0.0, 0.0, 0.0};  // Pa; sigma_zz = nu sigma_xx of plane strain
  SUBCASE("linear_elastic") {
    LinearElastic::Parameters p;
    p.density = 1000.0, p.youngs_modulus = 1e6, p.poisson_ratio = 0.3;
    check_turned(quarter_turn(LinearElastic(p), sigma0), sigma0);
  }
  SUBCASE("neo_hookean") {
    NeoHookean::Parameters p;
    p.density = 1000.0, p.youngs_modulus = 1e6, p.poisson_ratio = 0.3;
    const NeoHookean model(p);
    check_turned(quarter_turn(model, sigma0), sigma0);
    // The same with a stress of 30 % of E: large strain, still exact.
    const Voigt large{3e5, -1e5, 2e4, 0.0, 0.0, 5e4};
    check_turned(quarter_turn(model, large), large);
  }
  SUBCASE("orthotropic, axes along the bar") {
    Orthotropic::Parameters p;
    p.density = 500.0, p.Ex = 1e7, p.Ey = 1e6, p.Ez = 5e5;
    p.Gxy = 7e5, p.Gxz = 6e5, p.Gyz = 1e5;
    p.nuxy = 0.3, p.nuxz = 0.4, p.nuyz = 0.5;
    const Voigt s0{1.0e3, 0.0, 0.0, 0.0, 0.0, 2.0e2};
    check_turned(quarter_turn(Orthotropic(p), s0), s0);
  }
}
