// Objectivity: a pre-stressed material turned rigidly a quarter turn keeps
// its stress along the material direction it was in (the stress turns with
// the body and a rigid rotation does not load it), for linear_elastic
// (Hughes-Winget rate), neo_hookean (F carried) and orthotropic (axes and
// strain in material axes carried): a material point turned by a pure spin,
// exact to round-off, and the shipped spun bar, whole.
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>

#include "discretisation/shapes/shape_gimp.hpp"
#include "material_point_driver.hpp"
#include "test_helpers.hpp"

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
// sigma0's xx, sigma_xx its yy, sigma_xy changes sign; zz stays; to
// `tolerance` (Pa).
void check_turned(const Voigt& sigma, const Voigt& sigma0, double tolerance) {
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
    check_turned(quarter_turn(LinearElastic(p), sigma0), sigma0, 1e-12 * sigma0[0]);
  }
  SUBCASE("neo_hookean") {
    NeoHookean::Parameters p;
    p.density = 1000.0, p.youngs_modulus = 1e6, p.poisson_ratio = 0.3;
    const NeoHookean model(p);
    // The stress is E times F's strain: F's round-off over the 1000 turns
    // (measured 1e-13) times E.
    check_turned(quarter_turn(model, sigma0), sigma0, 1e-12 * p.youngs_modulus);
    // The same with a stress of 30 % of E: large strain, still exact.
    const Voigt large{3e5, -1e5, 2e4, 0.0, 0.0, 5e4};
    check_turned(quarter_turn(model, large), large, 1e-12 * p.youngs_modulus);
  }
  SUBCASE("orthotropic, axes along the bar") {
    Orthotropic::Parameters p;
    p.density = 500.0, p.Ex = 1e7, p.Ey = 1e6, p.Ez = 5e5;
    p.Gxy = 7e5, p.Gxz = 6e5, p.Gyz = 1e5;
    p.nuxy = 0.3, p.nuxz = 0.4, p.nuyz = 0.5;
    const Voigt s0{1.0e3, 0.0, 0.0, 0.0, 0.0, 2.0e2};
    check_turned(quarter_turn(Orthotropic(p), s0), s0, 1e-12 * s0[0]);
  }
}

namespace {

// The shipped spun bar (configs/verification/spun_prestressed_bar.toml) of
// `material`, run to its quarter turn: the angle its particles turned (the
// best rigid fit about their centroid), the bar's mean stress in its own
// frame (turned back by that angle) beside the mean it started with, and
// its mean strain (the engine's sum of sym(L) dt, global axes): the
// deformation the turn cost.
struct Spun {
  double turned = 0.0;
  Voigt mean{}, mean0{}, strain{};
};

Spun spun_bar(const std::string& material, const std::vector<std::string>& settings = {}) {
  std::vector<std::string> set = settings;
  set.push_back("bodies.0.material=" + material);
  const Case c = read_case(testing::config("verification/spun_prestressed_bar.toml"), set);
  auto sim = testing::simulation<2, GimpShape>(c);
  const auto& b = sim.system().batches[0];
  const std::size_t n = b.size();
  auto centroid = [&] {
    Vec<2> c = Vec<2>::Zero();
    for (std::size_t p = 0; p < n; ++p) c += b.x[p] / static_cast<double>(n);
    return c;
  };
  const Vec<2> c0 = centroid();
  std::vector<Vec<2>> r0(n);
  Spun s;
  for (std::size_t p = 0; p < n; ++p) {
    r0[b.id[p]] = b.x[p] - c0;
    for (int i = 0; i < 6; ++i) s.mean0[i] += b.stress[p][i] / static_cast<double>(n);
  }
  const double dt = c.time_step.fixed_dt();
  while (sim.system().t < c.time_step.end_time() - 0.5 * dt) sim.advance();
  const Vec<2> c1 = centroid();
  double cross = 0.0, dot = 0.0;
  for (std::size_t p = 0; p < n; ++p) {
    const Vec<2> a = r0[b.id[p]], r = b.x[p] - c1;
    cross += a[0] * r[1] - a[1] * r[0];
    dot += a.dot(r);
  }
  s.turned = std::atan2(cross, dot);
  const Eigen::Matrix3d R = Eigen::AngleAxisd(s.turned, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  for (std::size_t p = 0; p < n; ++p) {
    const Voigt body = to_material(R, b.stress[p]);
    for (int i = 0; i < 6; ++i) {
      s.mean[i] += body[i] / static_cast<double>(n);
      s.strain[i] += b.strain[p][i] / static_cast<double>(n);
    }
  }
  return s;
}

}  // namespace

TEST_CASE("the shipped spun bar keeps its stress in its own frame: linear_elastic, neo_hookean, orthotropic") {
  // Measured (uGIMP, USL, APIC as shipped, 5554 steps; the mean stress in
  // the bar's frame over the mean axial stress it started with, 666.6 Pa;
  // the mean strain over the mean axial prestrain, that stress over the
  // axial modulus):
  //                 turned    axial    across    shear     strain xx, yy, xy
  //   elastic       1.57051   1.0074   -0.0002   0.00008   -0.0005 0.0053 0.0001
  //   rubber        1.57051   1.0074   -0.0002   0.00008   -0.0005 0.0053 0.0001
  //   wood          1.57052   0.9944   -0.0004   0.00011   -0.0002 -0.0009 -0.0001
  // APIC keeps the angular momentum, so the bar turns the quarter (0.02 %
  // short) and its steady stress stays. Asserted: the turn within 0.1 %,
  // the stress along the axis within 1 % of its magnitude (axial, across
  // and shear), the deformation below 1 % of the prestrain.
  constexpr double quarter = pi / 2.0;
  const std::pair<std::string, double> materials[] = {{"elastic", 1e6}, {"rubber", 1e6}, {"wood", 2e6}};
  for (const auto& [material, modulus] : materials) {
    CAPTURE(material);
    const Spun s = spun_bar(material);
    const double axial = s.mean0[0], prestrain = axial / modulus;
    CHECK(std::abs(s.turned - quarter) < 1e-3 * quarter);
    CHECK(std::abs(s.mean[0] / axial - 1.0) < 0.01);
    CHECK(std::abs(s.mean[1] - s.mean0[1]) < 0.01 * axial);
    CHECK(std::abs(s.mean[5]) < 0.01 * axial);
    for (int i : {0, 1, 5}) CHECK(std::abs(s.strain[i]) < 0.01 * prestrain);
  }
}

TEST_CASE("the spun bar with FLIP: the stress turns, the transfers lose the spin") {
  // Measured (FLIP, otherwise as shipped):
  //                 turned   axial   across    shear    strain xx, yy, xy
  //   elastic       1.5514   0.9695  -0.0029   0.0259   -0.023 -0.011 -0.017
  //   rubber        1.5514   0.9694  -0.0029   0.0259   -0.023 -0.011 -0.017
  //   wood          1.5518   0.9634  -0.0006   0.0012   -0.017 -0.021  0.049
  // linear_elastic before its stress turned (main at d0bffca, the same
  // case): turned 1.5516, axial 0.968, across -0.004, shear 0.023, but
  // strain xx -0.99 and yy +0.96: the stress a free bar holds is fixed by
  // its equilibrium (the centripetal acceleration, free faces), so a model
  // whose stress does not turn deforms until it holds it again, by the
  // whole prestrain. Asserted: the turn FLIP's transfers allow (1.2 % lag,
  // docs/theory/kinematics.md); the stress along the axis within 1 % across
  // it, 3 % in shear (the spin slowing down as the transfers lose angular
  // momentum shears the bar: about 0.8 % by the virial theorem, plus its
  // vibration) and 5 % along it (the steady stress goes as omega^2); the
  // deformation below 6 % of the prestrain.
  constexpr double quarter = pi / 2.0;
  const std::pair<std::string, double> materials[] = {{"elastic", 1e6}, {"rubber", 1e6}, {"wood", 2e6}};
  for (const auto& [material, modulus] : materials) {
    CAPTURE(material);
    const Spun s = spun_bar(material, {"analysis.velocity_update=flip"});
    const double axial = s.mean0[0], prestrain = axial / modulus;
    CHECK(s.turned > 0.98 * quarter);
    CHECK(s.turned < quarter);
    CHECK(s.mean[0] / axial > 0.95);
    CHECK(s.mean[0] / axial < 1.0);
    CHECK(std::abs(s.mean[1] - s.mean0[1]) < 0.01 * axial);
    CHECK(std::abs(s.mean[5]) < 0.03 * axial);
    for (int i : {0, 1, 5}) CHECK(std::abs(s.strain[i]) < 0.06 * prestrain);
  }
}
