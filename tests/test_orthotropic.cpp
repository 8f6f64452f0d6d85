// Orthotropic and transversely isotropic elasticity (materials/orthotropic.hpp,
// materials/transversely_isotropic.hpp) at a material point and in whole
// cases, against closed forms. Material: hybrid poplar strands ([Le 2010],
// Table 3.1; docs/REFERENCES.md) with L = x, R = y, T = z.
//
// Tolerances:
//  - Strain-driven material points: the model is linear, so the stress is
//    C eps up to round-off amplified by the condition number of C (about
//    E_L / G_RT = 90): 1e-11 of the largest stress.
//  - Mixed control (the driver zeroes the free stresses to 1e-13 of the
//    largest one, by Newton on a finite-difference Jacobian of relative
//    step 1e-7 that is exact for a linear model): moduli to 1e-9.
//  - Rigid rotations are applied as Cayley increments chosen to sum to the
//    stated angle exactly; quaternion round-off over 200 increments: 1e-11.
//  - Wave speed: the direction search is refined to 1e-7 rad, so the
//    maximum is found to (1e-7)^2 relative: 1e-9 against closed forms and
//    sampled directions.
//  - Whole cases (explicit dynamics loaded smoothly, triangular velocity
//    pulse): the dynamic residue is about 4 / (omega T)^2 of the static
//    strain, 1e-4 here; the off-axis blocks shear and their axes turn with
//    them, which moves the apparent modulus by about eps d ln E / d phi,
//    1e-4 at the strain of 1e-4 used (measured: 1.3e-4 lamina, poplar
//    below 1e-4; 3e-6 on the thermal stress): moduli, thermal stress and
//    strains within 0.1 %, stresses that should vanish below 0.1 % of the
//    one that does not.
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "discretisation/shapes/shape_linear.hpp"
#include "engine/simulation.hpp"
#include "material_point_driver.hpp"
#include "test_helpers.hpp"

using namespace flowmpm;
using flowmpm::testing::MaterialPoint;
using flowmpm::testing::material_from_text;
using flowmpm::testing::material_error;

namespace {

constexpr double EL = 9936e6, ER = 914e6, ET = 427e6, GLR = 745e6, GLT = 686e6, GRT = 109e6;
constexpr double nuLR = 0.31, nuLT = 0.39, nuRT = 0.70;
constexpr double rho = 350.0;
constexpr double pi = std::numbers::pi;

const std::string poplar_text =
    "type = \"orthotropic\"\ndensity = 350.0\nEx = 9936e6\nEy = 914e6\nEz = 427e6\n"
    "Gxy = 745e6\nGxz = 686e6\nGyz = 109e6\nnuxy = 0.31\nnuxz = 0.39\nnuyz = 0.70\n";

Orthotropic poplar(const std::string& extra = "") {
  return std::get<Orthotropic>(material_from_text(poplar_text + extra));
}

// The 6 x 6 compliance with engineering shear strains, built here from the
// published constants, and the stiffness C = S^-1.
Eigen::Matrix<double, 6, 6> compliance6() {
  Eigen::Matrix<double, 6, 6> S = Eigen::Matrix<double, 6, 6>::Zero();
  S(0, 0) = 1 / EL, S(1, 1) = 1 / ER, S(2, 2) = 1 / ET;
  S(0, 1) = S(1, 0) = -nuLR / EL;
  S(0, 2) = S(2, 0) = -nuLT / EL;
  S(1, 2) = S(2, 1) = -nuRT / ER;
  S(3, 3) = 1 / GRT, S(4, 4) = 1 / GLT, S(5, 5) = 1 / GLR;
  return S;
}
Eigen::Matrix<double, 6, 6> stiffness6() { return compliance6().inverse(); }

using Vector6 = Eigen::Matrix<double, 6, 1>;
Vector6 engineering(const Voigt& e) { return (Vector6() << e[0], e[1], e[2], 2 * e[3], 2 * e[4], 2 * e[5]).finished(); }
Voigt voigt(const Vector6& s) { return {s[0], s[1], s[2], s[3], s[4], s[5]}; }

double largest(const Voigt& a) {
  double m = 0.0;
  for (double v : a) m = std::max(m, std::abs(v));
  return m;
}
void check_close(const Voigt& a, const Voigt& b, double rel) {
  const double scale = std::max(largest(a), largest(b));
  for (int i = 0; i < 6; ++i) {
    CAPTURE(i);
    CHECK(std::abs(a[i] - b[i]) <= rel * scale);
  }
}

// 1 / E of uniaxial stress along x, material axis 1 at theta from x, from
// the in-plane compliances S11, S22, S12, S66 (Lekhnitskii).
double off_axis_compliance(double S11, double S22, double S12, double S66, double theta) {
  const double c = std::cos(theta), s = std::sin(theta);
  return c * c * c * c * S11 + (2 * S12 + S66) * c * c * s * s + s * s * s * s * S22;
}

Eigen::Matrix3d Rz(double a) { Eigen::Matrix3d R; R << std::cos(a), -std::sin(a), 0, std::sin(a), std::cos(a), 0, 0, 0, 1; return R; }
Eigen::Matrix3d Ry(double a) { Eigen::Matrix3d R; R << std::cos(a), 0, std::sin(a), 0, 1, 0, -std::sin(a), 0, std::cos(a); return R; }
Eigen::Matrix3d Rx(double a) { Eigen::Matrix3d R; R << 1, 0, 0, 0, std::cos(a), -std::sin(a), 0, std::sin(a), std::cos(a); return R; }

template <StressState S, class M>
MaterialPoint<M, S> strained(const M& m, const Voigt& eps, int steps = 10, const ParticleInit& init = {}) {
  MaterialPoint<M, S> p(m, init);
  Voigt d;
  for (int i = 0; i < 6; ++i) d[i] = eps[i] / steps;
  for (int k = 0; k < steps; ++k) p.strain(d);
  return p;
}

const Voigt general_strain{1e-3, -4e-4, 6e-4, 2e-4, -3e-4, 5e-4};

}  // namespace

TEST_CASE("3D: stress C eps for given strains, and the inverse eps = S sigma") {
  const auto p = strained<StressState::three_d>(poplar(), general_strain);
  check_close(p.sigma, voigt(stiffness6() * engineering(general_strain)), 1e-11);
  const Vector6 back = compliance6() * (Vector6() << p.sigma[0], p.sigma[1], p.sigma[2], p.sigma[3], p.sigma[4], p.sigma[5]).finished();
  for (int i = 0; i < 6; ++i) CHECK(back[i] == doctest::Approx(engineering(general_strain)[i]).epsilon(1e-11));
}

TEST_CASE("reciprocity: nuyx, nuzx, nuzy give the same material as nuxy, nuxz, nuyz") {
  const std::string text =
      "type = \"orthotropic\"\ndensity = 350.0\nEx = 9936e6\nEy = 914e6\nEz = 427e6\n"
      "Gxy = 745e6\nGxz = 686e6\nGyz = 109e6\nnuyx = " + std::to_string(nuLR * ER / EL) +
      "\nnuzx = " + std::to_string(nuLT * ET / EL) + "\nnuzy = " + std::to_string(nuRT * ET / ER) + "\n";
  const Orthotropic a = std::get<Orthotropic>(material_from_text(text)), b = poplar();
  // std::to_string keeps 6 decimals: the ratios agree to 1e-6 / 0.017.
  CHECK((a.C_n - b.C_n).norm() <= 1e-4 * b.C_n.norm());
  CHECK(a.parameters.nuxy == doctest::Approx(nuLR).epsilon(1e-4));
}

TEST_CASE("plane strain: eps_zz = 0 and sigma = C eps with the 3D C") {
  const Voigt eps{1e-3, -4e-4, 0, 0, 0, 5e-4};
  const auto p = strained<StressState::plane_strain>(poplar(), eps);
  CHECK(p.eps[2] == 0.0);
  check_close(p.sigma, voigt(stiffness6() * engineering(eps)), 1e-11);
}

TEST_CASE("plane stress: sigma = Q eps, eps_zz = S13 sigma_xx + S23 sigma_yy") {
  const Voigt eps{1e-3, -4e-4, 0, 0, 0, 5e-4};
  const auto p = strained<StressState::plane_stress>(poplar(), eps);
  const double nuRL = nuLR * ER / EL, d = 1 - nuLR * nuRL;
  CHECK(p.sigma[0] == doctest::Approx(EL / d * eps[0] + nuLR * ER / d * eps[1]).epsilon(1e-11));
  CHECK(p.sigma[1] == doctest::Approx(nuLR * ER / d * eps[0] + ER / d * eps[1]).epsilon(1e-11));
  CHECK(p.sigma[5] == doctest::Approx(2 * GLR * eps[5]).epsilon(1e-11));
  CHECK(p.sigma[2] == 0.0);
  CHECK(p.eps[2] == doctest::Approx(-nuLT / EL * p.sigma[0] - nuRT / ER * p.sigma[1]).epsilon(1e-11));
}

TEST_CASE("1D uniaxial stress: sigma = Ex eps, lateral strains -nu_xy eps and -nu_xz eps") {
  const auto p = strained<StressState::uniaxial_stress>(poplar(), {2e-3, 0, 0, 0, 0, 0});
  CHECK(p.sigma[0] == doctest::Approx(EL * 2e-3).epsilon(1e-12));
  CHECK(p.eps[1] == doctest::Approx(-nuLR * 2e-3).epsilon(1e-12));
  CHECK(p.eps[2] == doctest::Approx(-nuLT * 2e-3).epsilon(1e-12));
}

TEST_CASE("off-axis modulus of material axes rotated about z (3D, plane stress, plane strain)") {
  const Orthotropic m = poplar();
  const Eigen::Matrix<double, 6, 6> S = compliance6();
  for (double deg : {0.0, 15.0, 30.0, 45.0, 60.0, 90.0}) {
    CAPTURE(deg);
    ParticleInit init;
    init.axes_degrees = {deg, 0.0, 0.0};
    const double theta = deg * pi / 180;
    const double expected = 1 / off_axis_compliance(1 / EL, 1 / ER, -nuLR / EL, 1 / GLR, theta);
    MaterialPoint<Orthotropic, StressState::three_d> p3(m, init);
    MaterialPoint<Orthotropic, StressState::plane_stress> ps(m, init);
    for (int k = 0; k < 5; ++k) {
      p3.mixed({2e-4, 0, 0, 0, 0, 0}, {1, 2, 3, 4, 5});
      ps.mixed({2e-4, 0, 0, 0, 0, 0}, {1, 5});
    }
    CHECK(p3.sigma[0] / p3.eps[0] == doctest::Approx(expected).epsilon(1e-9));
    CHECK(ps.sigma[0] / ps.eps[0] == doctest::Approx(expected).epsilon(1e-9));
    // Plane strain: the in-plane compliances reduced by eps_zz = 0,
    // S~ij = Sij - Si3 Sj3 / S33.
    auto reduced = [&](int i, int j) { return S(i, j) - S(i, 2) * S(j, 2) / S(2, 2); };
    const double plane_strain = 1 / off_axis_compliance(reduced(0, 0), reduced(1, 1), reduced(0, 1), S(5, 5), theta);
    MaterialPoint<Orthotropic, StressState::plane_strain> pe(m, init);
    for (int k = 0; k < 5; ++k) pe.mixed({2e-4, 0, 0, 0, 0, 0}, {1, 5});
    CHECK(pe.sigma[0] / pe.eps[0] == doctest::Approx(plane_strain).epsilon(1e-9));
  }
}

TEST_CASE("3D axes R = Rz Ry Rx: sigma = R C (R^T eps R) R^T") {
  const Orthotropic m = poplar();
  ParticleInit init;
  init.axes_degrees = {30.0, 40.0, 50.0};
  const Eigen::Matrix3d R = Rz(30 * pi / 180) * Ry(40 * pi / 180) * Rx(50 * pi / 180);
  const auto p = strained<StressState::three_d>(m, general_strain, 10, init);
  const Voigt eps_m = voigt_of(R.transpose() * tensor_of(general_strain) * R);
  const Voigt sigma_m = voigt(stiffness6() * engineering(eps_m));
  check_close(p.sigma, voigt_of(R * tensor_of(sigma_m) * R.transpose()), 1e-11);

  // Rotated 90 degrees about z, the L axis lies along y: uniaxial stress
  // along y has modulus E_L; 90 degrees about y puts L along -z.
  init.axes_degrees = {90.0, 0.0, 0.0};
  MaterialPoint<Orthotropic, StressState::three_d> along_y(m, init);
  along_y.mixed({0, 1e-3, 0, 0, 0, 0}, {0, 2, 3, 4, 5});
  CHECK(along_y.sigma[1] / along_y.eps[1] == doctest::Approx(EL).epsilon(1e-9));
  init.axes_degrees = {0.0, 90.0, 0.0};
  MaterialPoint<Orthotropic, StressState::three_d> along_z(m, init);
  along_z.mixed({0, 0, 1e-3, 0, 0, 0}, {0, 1, 3, 4, 5});
  CHECK(along_z.sigma[2] / along_z.eps[2] == doctest::Approx(EL).epsilon(1e-9));
}

TEST_CASE("objectivity: a rigid rotation turns stress and axes with the body and loads nothing") {
  const Orthotropic m = poplar();
  // Pre-strained in 3D, then turned 90 degrees about n in 200 spin increments
  // W dt = [w]x with |w| = 2 tan(theta / 400), so that the Cayley steps add
  // up to 90 degrees exactly.
  auto p = strained<StressState::three_d>(m, general_strain);
  const Voigt sigma0 = p.sigma, eps_m0 = p.state.eps;
  const Eigen::Vector3d n = Eigen::Vector3d(1, 2, 3).normalized();
  const Eigen::Vector3d w = 2 * std::tan(0.5 * pi / 2 / 200) * n;
  Eigen::Matrix3d W;
  W << 0, -w.z(), w.y(), w.z(), 0, -w.x(), -w.y(), w.x(), 0;
  for (int k = 0; k < 200; ++k) p.step(W);
  const Eigen::Matrix3d Q = Eigen::AngleAxisd(pi / 2, n).toRotationMatrix();
  check_close(p.sigma, voigt_of(Q * tensor_of(sigma0) * Q.transpose()), 1e-11);
  check_close(p.state.eps, eps_m0, 1e-11);
  for (int i = 0; i < 6; ++i) CHECK(p.eps[i] == doctest::Approx(general_strain[i]).epsilon(1e-12));

  // 2D: axes along x turned 90 degrees about z; then tension along y meets
  // the L direction: modulus E_L in plane stress.
  MaterialPoint<Orthotropic, StressState::plane_stress> q(m);
  const double wz = 2 * std::tan(0.5 * pi / 2 / 100);
  Eigen::Matrix3d Wz = Eigen::Matrix3d::Zero();
  Wz(0, 1) = -wz, Wz(1, 0) = wz;
  for (int k = 0; k < 100; ++k) q.step(Wz);
  CHECK(largest(q.sigma) == 0.0);
  q.mixed({0, 1e-3, 0, 0, 0, 0}, {0, 5});
  CHECK(q.sigma[1] / q.eps[1] == doctest::Approx(EL).epsilon(1e-9));
}

TEST_CASE("thermal expansion: free expansion is stress free, constrained gives -C alpha dT") {
  // dT ramps from 0 to 40 K over 10 s; wood-like alpha (1/K) per axis.
  const std::string thermal = "alpha = [3e-6, 30e-6, 40e-6]\ntemperature_change = [[0.0, 0.0], [10.0, 40.0]]\n";
  const Orthotropic m = poplar(thermal);
  const Eigen::Vector3d alpha(3e-6, 30e-6, 40e-6);
  const double dT = 40.0;
  const Vector6 th = (Vector6() << alpha * dT, 0, 0, 0).finished();
  const Vector6 constrained = -stiffness6() * th;  // material axes
  const double scale = constrained.cwiseAbs().maxCoeff();

  SUBCASE("3D, axes rotated: eps = R alpha dT R^T is stress free; eps = 0 gives R (-C alpha dT) R^T") {
    ParticleInit init;
    init.axes_degrees = {30.0, 40.0, 50.0};
    const Eigen::Matrix3d R = Rz(30 * pi / 180) * Ry(40 * pi / 180) * Rx(50 * pi / 180);
    const Eigen::Matrix3d free_strain = R * Eigen::Matrix3d(alpha.asDiagonal()) * R.transpose();
    MaterialPoint<Orthotropic, StressState::three_d> free(m, init), fixed(m, init);
    for (int k = 0; k < 10; ++k) {
      free.strain(voigt_of(free_strain * (dT / 10)));
      fixed.strain({0, 0, 0, 0, 0, 0});
    }
    CHECK(largest(free.sigma) <= 1e-12 * scale);
    check_close(fixed.sigma, voigt_of(R * tensor_of(voigt(constrained)) * R.transpose()), 1e-11);
  }
  SUBCASE("plane strain, free in plane: sigma_zz = -Ez alpha_z dT, eps_xx = (alpha_x + nu_zx alpha_z) dT") {
    MaterialPoint<Orthotropic, StressState::plane_strain> p(m);
    for (int k = 0; k < 10; ++k) p.mixed({0, 0, 0, 0, 0, 0}, {0, 1, 5});
    CHECK(p.sigma[2] == doctest::Approx(-ET * alpha[2] * dT).epsilon(1e-9));
    CHECK(p.eps[0] == doctest::Approx((alpha[0] + nuLT * ET / EL * alpha[2]) * dT).epsilon(1e-9));
    CHECK(p.eps[1] == doctest::Approx((alpha[1] + nuRT * ET / ER * alpha[2]) * dT).epsilon(1e-9));
  }
  SUBCASE("plane stress, free: no stress, eps_zz = alpha_z dT; constrained in plane: sigma = -Q alpha dT") {
    MaterialPoint<Orthotropic, StressState::plane_stress> free(m), fixed(m);
    for (int k = 0; k < 10; ++k) {
      free.mixed({0, 0, 0, 0, 0, 0}, {0, 1, 5});
      fixed.strain({0, 0, 0, 0, 0, 0});
    }
    CHECK(largest(free.sigma) <= 1e-9 * scale);
    CHECK(free.eps[2] == doctest::Approx(alpha[2] * dT).epsilon(1e-9));
    // eps_in-plane = S2 sigma + alpha2 dT = 0 with sigma_zz = 0, S2 the
    // in-plane 2 x 2 compliance: sigma = -S2^-1 alpha2 dT.
    Eigen::Matrix2d S2;
    S2 << 1 / EL, -nuLR / EL, -nuLR / EL, 1 / ER;
    const Eigen::Vector2d s = -S2.inverse() * Eigen::Vector2d(alpha[0], alpha[1]) * dT;
    CHECK(fixed.sigma[0] == doctest::Approx(s[0]).epsilon(1e-11));
    CHECK(fixed.sigma[1] == doctest::Approx(s[1]).epsilon(1e-11));
  }
  SUBCASE("1D constrained: sigma = -Ex alpha_x dT, lateral strains (alpha_y + nu_xy alpha_x) dT") {
    auto p = strained<StressState::uniaxial_stress>(m, {0, 0, 0, 0, 0, 0});
    CHECK(p.sigma[0] == doctest::Approx(-EL * alpha[0] * dT).epsilon(1e-12));
    CHECK(p.eps[1] == doctest::Approx((alpha[1] + nuLR * alpha[0]) * dT).epsilon(1e-12));
    CHECK(p.eps[2] == doctest::Approx((alpha[2] + nuLT * alpha[0]) * dT).epsilon(1e-12));
  }
  SUBCASE("the temperature change is evaluated at the end of the step") {
    auto p = strained<StressState::uniaxial_stress>(m, {0, 0, 0, 0, 0, 0}, 4);  // t = 4 s, dT = 16 K
    CHECK(p.sigma[0] == doctest::Approx(-EL * alpha[0] * 16.0).epsilon(1e-12));
  }
}

TEST_CASE("solvent expansion: constrained stress -C (alpha dT + beta c)") {
  const Orthotropic m = poplar(
      "alpha = [3e-6, 30e-6, 40e-6]\ntemperature_change = 20.0\nbeta = [0.01, 0.2, 0.3]\nconcentration = 0.05\n");
  const Vector6 th = (Vector6() << 3e-6 * 20 + 0.01 * 0.05, 30e-6 * 20 + 0.2 * 0.05, 40e-6 * 20 + 0.3 * 0.05, 0, 0, 0).finished();
  const auto p = strained<StressState::three_d>(m, {0, 0, 0, 0, 0, 0}, 1);
  check_close(p.sigma, voigt(-stiffness6() * th), 1e-11);
}

TEST_CASE("wave speed: largest quasi-P speed over all directions") {
  // Isotropic limit: sqrt((lambda + 2 mu) / rho).
  const Orthotropic iso = std::get<Orthotropic>(material_from_text(
      "type = \"orthotropic\"\ndensity = 1000.0\nEx = 1e9\nEy = 1e9\nEz = 1e9\nGxy = 4e8\nGxz = 4e8\nGyz = 4e8\n"
      "nuxy = 0.25\nnuxz = 0.25\nnuyz = 0.25\n"));
  CHECK(iso.wave_speed() == doctest::Approx(std::sqrt(1e9 * 0.75 / (1.25 * 0.5) / 1000.0)).epsilon(1e-9));

  const Orthotropic m = poplar();
  const Eigen::Matrix<double, 6, 6> C = stiffness6();
  CHECK(m.wave_speed() >= std::sqrt(C(0, 0) / rho) * (1 - 1e-12));
  // No sampled direction is faster, and the fastest sampled is within 1e-6.
  std::mt19937 gen(5);
  std::normal_distribution<double> normal;
  double fastest = 0.0;
  for (int k = 0; k < 20000; ++k) {
    Eigen::Vector3d n(normal(gen), normal(gen), normal(gen));
    n.normalize();
    Eigen::Matrix3d G = Eigen::Matrix3d::Zero();
    // Gamma_ik = C_ijkl n_j n_l through the Voigt map of (i, j).
    const int v[3][3] = {{0, 5, 4}, {5, 1, 3}, {4, 3, 2}};
    for (int i = 0; i < 3; ++i)
      for (int kk = 0; kk < 3; ++kk)
        for (int j = 0; j < 3; ++j)
          for (int l = 0; l < 3; ++l) G(i, kk) += C(v[i][j], v[kk][l]) * n[j] * n[l];
    fastest = std::max(fastest, std::sqrt(Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(G).eigenvalues()[2] / rho));
  }
  // 20000 random directions come within about 0.02 rad of any direction,
  // where the speed is within (0.02)^2 of its maximum.
  CHECK(fastest <= m.wave_speed() * (1 + 1e-9));
  CHECK(fastest >= m.wave_speed() * (1 - 4e-4));
  MESSAGE("poplar wave speed " << m.wave_speed() << " m/s, sqrt(C11 / rho) = " << std::sqrt(C(0, 0) / rho)
          << " m/s, fastest of 20000 sampled directions " << fastest << " m/s");
  // Along the grain, the bar wave of [Le 2010]'s E_L = 9936 MPa at the
  // strands' 350 kg/m^3 (docs/REFERENCES.md) is sqrt(E_L / rho) = 5.33 km/s;
  // the P wave, its lateral strain held, is faster by the Poisson coupling
  // (C11 > E_L), here by 1.5 %.
  CHECK(m.wave_speed() == doctest::Approx(std::sqrt(9936e6 / 350.0)).epsilon(0.02));
}

TEST_CASE("validation names the key and the condition") {
  const std::string base =
      "type = \"orthotropic\"\ndensity = 350.0\nEy = 914e6\nEz = 427e6\nGxy = 745e6\nGxz = 686e6\nGyz = 109e6\n"
      "nuxz = 0.39\nnuyz = 0.70\n";
  CHECK(material_error(base + "Ex = 9936e6\nnuxy = 0.31\nnuyx = 0.03\n").find("nuyx: expected only one of nuxy and nuyx") != std::string::npos);
  CHECK(material_error(base + "Ex = 9936e6\n").find("nuxy: missing; expected one Poisson ratio of the pair, nuxy or nuyx") != std::string::npos);
  CHECK(material_error(base + "Ex = 0.0\nnuxy = 0.31\n").find("Ex: expected a positive Young's modulus in Pa") != std::string::npos);
  CHECK(material_error(base + "Ex = 9936e6\nnuxy = 4.0\n").find("nuxy: expected Poisson ratios with nuxy * nuyx < 1") != std::string::npos);
  const std::string iso =
      "type = \"orthotropic\"\ndensity = 1.0\nEx = 1.0\nEy = 1.0\nEz = 1.0\nGxy = 1.0\nGxz = 1.0\nGyz = 1.0\n";
  CHECK(material_error(iso + "nuxy = 0.6\nnuxz = 0.6\nnuyz = 0.6\n").find("the compliance is not positive definite: 1 - nuxy nuyx") != std::string::npos);
  CHECK(material_error(poplar_text + "alpha = [1e-6, 1e-6, 1e-6]\n").find("temperature_change: missing; expected a temperature change in K (alpha is given)") != std::string::npos);
  CHECK(material_error(poplar_text + "concentration = 0.1\n").find("beta: missing") != std::string::npos);
  CHECK(material_error(poplar_text + "alpha = [1e-6, 1e-6]\ntemperature_change = 1.0\n").find("alpha: expected an array of 3 numbers") != std::string::npos);
  CHECK(material_error(poplar_text + "nu_xy = 0.3\n").find("nu_xy: unknown key") != std::string::npos);
}

TEST_CASE("transversely isotropic, axis z: the orthotropic material it maps to, isotropic about z") {
  const std::string ti =
      "type = \"transversely_isotropic\"\naxis = \"z\"\ndensity = 1500.0\nEA = 140e9\nET = 10e9\nGA = 5e9\n"
      "nuAT = 0.3\nnuT = 0.45\n";
  const auto m = std::get<TransverselyIsotropic>(material_from_text(ti));
  const auto o = std::get<Orthotropic>(material_from_text(
      "type = \"orthotropic\"\ndensity = 1500.0\nEx = 10e9\nEy = 10e9\nEz = 140e9\nGxy = " +
      std::to_string(10e9 / 2.9) + "\nGxz = 5e9\nGyz = 5e9\nnuxy = 0.45\nnuzx = 0.3\nnuzy = 0.3\n"));
  const auto a = strained<StressState::three_d>(m, general_strain);
  const auto b = strained<StressState::three_d>(o, general_strain);
  check_close(a.sigma, b.sigma, 1e-6);  // Gxy printed to 6 decimals
  // Isotropy in the transverse plane: turning the axes about z changes nothing.
  ParticleInit init;
  init.axes_degrees = {37.0, 0.0, 0.0};
  check_close(strained<StressState::three_d>(m, general_strain, 10, init).sigma, a.sigma, 1e-11);
  // Axial tension: modulus EA and lateral contraction nuAT.
  MaterialPoint<TransverselyIsotropic, StressState::three_d> p(m);
  p.mixed({0, 0, 1e-3, 0, 0, 0}, {0, 1, 3, 4, 5});
  CHECK(p.sigma[2] / p.eps[2] == doctest::Approx(140e9).epsilon(1e-9));
  CHECK(-p.eps[0] / p.eps[2] == doctest::Approx(0.3).epsilon(1e-9));
}

TEST_CASE("transversely isotropic, axis y: EA along y, ET and nuT in the x-z plane") {
  const auto m = std::get<TransverselyIsotropic>(material_from_text(
      "type = \"transversely_isotropic\"\naxis = \"y\"\ndensity = 1500.0\nEA = 140e9\nET = 10e9\nGA = 5e9\n"
      "nuTA = 0.02\nnuT = 0.45\n"));
  MaterialPoint<TransverselyIsotropic, StressState::three_d> y(m), x(m);
  y.mixed({0, 1e-3, 0, 0, 0, 0}, {0, 2, 3, 4, 5});
  CHECK(y.sigma[1] / y.eps[1] == doctest::Approx(140e9).epsilon(1e-9));
  CHECK(-y.eps[0] / y.eps[1] == doctest::Approx(0.02 * 140.0 / 10.0).epsilon(1e-9));
  x.mixed({1e-3, 0, 0, 0, 0, 0}, {1, 2, 3, 4, 5});
  CHECK(x.sigma[0] / x.eps[0] == doctest::Approx(10e9).epsilon(1e-9));
  CHECK(-x.eps[2] / x.eps[0] == doctest::Approx(0.45).epsilon(1e-9));
  // In-plane shear xz is the transverse shear GT = ET / (2 (1 + nuT)).
  const auto s = strained<StressState::three_d>(m, {0, 0, 0, 0, 1e-3, 0});
  CHECK(s.sigma[4] == doctest::Approx(2 * 10e9 / 2.9 * 1e-3).epsilon(1e-11));
}

TEST_CASE("transversely isotropic validation") {
  const std::string base =
      "type = \"transversely_isotropic\"\ndensity = 1500.0\nEA = 140e9\nET = 10e9\nGA = 5e9\nnuT = 0.45\n";
  CHECK(material_error(base + "axis = \"z\"\nnuAT = 0.3\nnuTA = 0.02\n").find("nuTA: expected only one of nuAT and nuTA") != std::string::npos);
  CHECK(material_error(base + "axis = \"x\"\nnuAT = 0.3\n").find("axis: expected one of \"z\", \"y\"") != std::string::npos);
  CHECK(material_error(base + "axis = \"z\"\nnuAT = 3.0\n").find("nuAT: expected an axial Poisson ratio with 2 nuAT nuTA < 1 - nuT") != std::string::npos);
}

namespace {

// Mean stress and strain of the first body at the end of the case.
template <int D>
BodyMeans run(const Case& c) {
  auto sim = testing::simulation<D, LinearShape>(c);
  for (std::int64_t s = 0; s < c.time_control.steps; ++s) sim.advance();
  return sim.diagnostics(c.system.bodies.size()).bodies[0];
}

}  // namespace

TEST_CASE("whole case: off-axis tension of a poplar strand block, apparent modulus") {
  // configs/materials/orthotropic_poplar_offaxis.toml: one 10 mm cell, 8
  // particles, L axis at 30 degrees from x about z, pulled along y to
  // eps_yy = 1e-4; uniaxial stress, so sigma_yy / eps_yy = 1 / S'_22(30 deg)
  // = E at 60 degrees from L.
  const Case c = read_case(testing::config("materials/orthotropic_poplar_offaxis.toml"));
  const BodyMeans b = run<3>(c);
  const double expected = 1 / off_axis_compliance(1 / EL, 1 / ER, -nuLR / EL, 1 / GLR, 60 * pi / 180);
  CHECK(b.strain[1] == doctest::Approx(1e-4).epsilon(1e-9));
  MESSAGE("off-axis block: sigma_yy / eps_yy = " << b.stress[1] / b.strain[1] << " Pa, analytical " << expected
          << " Pa; sigma_xx = " << b.stress[0] << " Pa, eps_xy = " << b.strain[5]);
  CHECK(b.stress[1] / b.strain[1] == doctest::Approx(expected).epsilon(1e-3));
  CHECK(std::abs(b.stress[0]) < 1e-3 * b.stress[1]);
  // The off-axis block shears: eps_xy has the sign of S'_26 (nonzero).
  CHECK(std::abs(b.strain[5]) > 1e-5);
}

TEST_CASE("whole case: a free block heated in plane strain") {
  // configs/materials/orthotropic_thermal_block.toml: 2D plane strain, no
  // constraint, dT ramped to 40 K: sigma_xx = sigma_yy = 0, sigma_zz =
  // -Ez alpha_z dT, eps_xx = (alpha_x + nu_zx alpha_z) dT.
  const Case c = read_case(testing::config("materials/orthotropic_thermal_block.toml"));
  const BodyMeans b = run<2>(c);
  const double dT = 40.0, ax = 3e-6, ay = 30e-6, az = 40e-6;
  MESSAGE("thermal block: sigma_zz = " << b.stress[2] << " Pa (analytical " << -ET * az * dT << "), sigma_xx = "
          << b.stress[0] << ", sigma_yy = " << b.stress[1] << " Pa, eps_xx = " << b.strain[0] << " ("
          << (ax + nuLT * ET / EL * az) * dT << "), eps_yy = " << b.strain[1] << " ("
          << (ay + nuRT * ET / ER * az) * dT << ")");
  CHECK(b.stress[2] == doctest::Approx(-ET * az * dT).epsilon(1e-3));
  CHECK(std::abs(b.stress[0]) < 1e-3 * ET * az * dT);
  CHECK(std::abs(b.stress[1]) < 1e-3 * ET * az * dT);
  CHECK(b.strain[0] == doctest::Approx((ax + nuLT * ET / EL * az) * dT).epsilon(1e-3));
  CHECK(b.strain[1] == doctest::Approx((ay + nuRT * ET / ER * az) * dT).epsilon(1e-3));
}

TEST_CASE("whole case: off-axis tension of a transversely isotropic lamina in plane stress") {
  // configs/materials/transversely_isotropic_lamina.toml: fibres (axis "y")
  // at 30 degrees from the load along y, one 10 mm cell, 4 particles.
  const Case c = read_case(testing::config("materials/transversely_isotropic_lamina.toml"));
  const BodyMeans b = run<2>(c);
  const double EA = 181e9, ET_ = 10.3e9, GA = 7.17e9, nuAT = 0.28;
  const double expected = 1 / off_axis_compliance(1 / EA, 1 / ET_, -nuAT / EA, 1 / GA, 30 * pi / 180);
  MESSAGE("lamina: sigma_yy / eps_yy = " << b.stress[1] / b.strain[1] << " Pa, analytical " << expected
          << " Pa; sigma_xx = " << b.stress[0] << " Pa, sigma_zz = " << b.stress[2] << " Pa");
  CHECK(b.strain[1] == doctest::Approx(1e-4).epsilon(1e-9));
  CHECK(b.stress[1] / b.strain[1] == doctest::Approx(expected).epsilon(1e-3));
  CHECK(std::abs(b.stress[0]) < 1e-3 * b.stress[1]);
  CHECK(b.stress[2] == 0.0);
}

TEST_CASE("cylindrical material axes: each particle's x axis points away from the centre") {
  // A 2D disc-like block around (0.5, 0.5) with material_axes_center: the
  // initial axes of every particle are a rotation about z by its polar
  // angle plus the body's angle (10 degrees here), to round-off.
  const Case c = testing::case_from_text("cylindrical_axes",
                                         "[analysis]\ndimension = 2\ndt = 1e-7\nsteps = 1\n"
                                         "[grid]\ncell_size = 0.1\ncells = [10, 10]\n"
                                         "[materials.wood]\n" + poplar_text +
                                         "[[bodies]]\nmaterial = \"wood\"\nmin = [0.2, 0.2]\nmax = [0.8, 0.8]\n"
                                         "particles_per_cell = 2\nmaterial_axes = [10.0]\n"
                                         "material_axes_center = [0.5, 0.5]\n");
  auto sim = testing::simulation<2, LinearShape>(c);
  const auto& batch = sim.system().batches.at(0);
  const auto& states = std::get<StateArray<Orthotropic>>(batch.states);
  REQUIRE(states.size() == batch.size());
  for (std::size_t p = 0; p < batch.size(); ++p) {
    const double angle = std::atan2(batch.x[p][1] - 0.5, batch.x[p][0] - 0.5) + 10.0 * pi / 180.0;
    const Eigen::Matrix3d R = states[p].axes.toRotationMatrix();
    CHECK(R(0, 0) == doctest::Approx(std::cos(angle)).epsilon(1e-12));
    CHECK(R(1, 0) == doctest::Approx(std::sin(angle)).epsilon(1e-12));
    CHECK(R(2, 2) == doctest::Approx(1.0).epsilon(1e-12));
  }
}
