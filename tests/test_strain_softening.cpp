// Linear strain-softening damage (materials/strain_softening.hpp; [Vignjevic])
// at a material point and in [Vignjevic]'s bar, against closed forms.
// Concrete-like: E = 30 GPa, nu = 0.2, eps_i = 1e-4, eps_f = 7e-4 at the
// material point (G_c = 10 J/m^2 for the crack band); in the bar G_c =
// 2.5 J/m^2, or eps_f = 2e-4 without regularisation.
//
// Tolerances:
//  - Material point: the law is piecewise linear in the strain and the
//    increments fall on its kinks, so stresses, damage and energies hold to
//    round-off: 1e-12 relative (1e-10 for a slope, a difference of stresses).
//  - The bar (2D plane strain, one row of square cells, lateral nodes held:
//    uniaxial strain; a notch of 0.9 eps_i at the centre): the damage must
//    stay in the central particle, which breaks (omega = 1). A broken
//    particle has dissipated (1/2) E eps_i eps_f per unit initial volume
//    exactly (the dissipation is integrated in closed form), so the energy
//    per unit cross-section is G_c (regularised) or (1/2) E eps_i eps_f h
//    (not regularised) to round-off: 1e-9. Without regularisation it falls
//    with h, by 9 over the factor 9 in h here (exact solution: 0 as h -> 0,
//    Bazant and Belytschko 1985).
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>
#include <sstream>

#include "discretisation/shape_linear.hpp"
#include "engine/simulation.hpp"
#include "material_point_driver.hpp"
#include "test_helpers.hpp"

using namespace flowmpm;
using flowmpm::testing::MaterialPoint;
using flowmpm::testing::material_from_text;
using flowmpm::testing::material_error;

namespace {

constexpr double E = 30e9, nu = 0.2, eps_i = 1e-4, eps_f = 7e-4, G_c = 10.0;
constexpr double M = E * (1 - nu) / ((1 + nu) * (1 - 2 * nu));  // constrained modulus
const std::string base = "type = \"strain_softening\"\ndensity = 2400.0\nyoungs_modulus = 30e9\npoisson_ratio = 0.2\n"
                         "initiation_strain = 1e-4\n";
const std::string notch = "type = \"strain_softening\"\ndensity = 2400.0\nyoungs_modulus = 30e9\npoisson_ratio = 0.2\n"
                          "initiation_strain = 0.9e-4\n";
StrainSoftening with_failure_strain() {
  return std::get<StrainSoftening>(material_from_text(base + "failure_strain = 7e-4\n"));
}
StrainSoftening with_fracture_energy() {
  return std::get<StrainSoftening>(material_from_text(base + "fracture_energy = 10.0\n"));
}

// [Vignjevic]'s monotonic curve in uniaxial stress.
double sigma_of(double eps) {
  if (eps <= eps_i) return E * eps;
  if (eps >= eps_f) return 0.0;
  return E * eps_i * (eps_f - eps) / (eps_f - eps_i);
}

using Point1D = MaterialPoint<StrainSoftening, StressState::uniaxial_stress>;

void pull(Point1D& p, double d, int n) {
  for (int k = 0; k < n; ++k) p.strain({d, 0, 0, 0, 0, 0});
}

}  // namespace

TEST_CASE("1D: elastic to eps_i, linear softening with E_t = -E eps_i / (eps_f - eps_i) to eps_f, then zero") {
  const StrainSoftening m = with_failure_strain();
  Point1D p(m);
  double work = 0.0;
  for (int k = 1; k <= 80; ++k) {  // to 8 eps_i in steps of eps_i / 10
    const double before = p.sigma[0];
    pull(p, eps_i / 10, 1);
    work += 0.5 * (before + p.sigma[0]) * eps_i / 10;
    const double eps = k * eps_i / 10;
    CAPTURE(eps);
    CHECK(p.sigma[0] == doctest::Approx(sigma_of(eps)).epsilon(1e-12).scale(E * eps_i * 1e-2));
    // omega = eps_f (eps - eps_i) / (eps (eps_f - eps_i)) (eq. 5.99) inside the band.
    const double omega = eps <= eps_i ? 0.0 : eps >= eps_f ? 1.0 : eps_f * (eps - eps_i) / (eps * (eps_f - eps_i));
    CHECK(m.damage(p.state.kappa, p.state.eps_f) == doctest::Approx(omega).epsilon(1e-12));
    // Work done = energy stored (1/2) sigma eps + energy dissipated.
    CHECK(work == doctest::Approx(0.5 * p.sigma[0] * eps + p.state.dissipated).epsilon(1e-12));
    CHECK(p.eps[1] == doctest::Approx(-nu * eps).epsilon(1e-12));
  }
  // Tangent on the softening branch (eq. 5.98).
  Point1D q(m);
  pull(q, eps_i, 2);
  const double s1 = q.sigma[0];
  pull(q, eps_i, 1);
  CHECK((q.sigma[0] - s1) / eps_i == doctest::Approx(-E * eps_i / (eps_f - eps_i)).epsilon(1e-10));
  // Broken: the energy of the whole triangle, (1/2) E eps_i eps_f.
  CHECK(p.state.dissipated == doctest::Approx(0.5 * E * eps_i * eps_f).epsilon(1e-12));
  CHECK(p.sigma[0] == 0.0);
}

TEST_CASE("1D: unloading along the secant, reloading to the same point, damage irreversible") {
  const StrainSoftening m = with_failure_strain();
  Point1D p(m);
  pull(p, eps_i / 10, 30);  // eps_u = 3 eps_i, in softening
  const double eps_u = 3 * eps_i, sigma_u = p.sigma[0], kappa = p.state.kappa, dissipated = p.state.dissipated;
  CHECK(sigma_u == doctest::Approx(sigma_of(eps_u)).epsilon(1e-12));
  const double secant = sigma_u / eps_u;  // (1 - omega) E
  pull(p, -eps_i / 10, 20);               // back to eps_i
  CHECK(p.sigma[0] == doctest::Approx(secant * eps_i).epsilon(1e-12));
  pull(p, -eps_i / 10, 10);  // to zero strain: zero stress
  CHECK(std::abs(p.sigma[0]) <= 1e-12 * sigma_u);
  CHECK(p.state.kappa == kappa);
  CHECK(p.state.dissipated == dissipated);
  pull(p, eps_i / 10, 20);  // reload to 2 eps_i: still on the secant, no healing
  CHECK(p.sigma[0] == doctest::Approx(secant * 2 * eps_i).epsilon(1e-12));
  pull(p, eps_i / 10, 10);  // back at eps_u, then on along the softening line
  CHECK(p.sigma[0] == doctest::Approx(sigma_u).epsilon(1e-12));
  pull(p, eps_i / 10, 10);
  CHECK(p.sigma[0] == doctest::Approx(sigma_of(4 * eps_i)).epsilon(1e-12));
  CHECK(p.state.dissipated > dissipated);
}

TEST_CASE("crack band: eps_f = 2 G_c / (E eps_i h), h the cell size, so a broken particle dissipates G_c / h") {
  const StrainSoftening m = with_fracture_energy();
  for (double h : {0.01, 0.005, 0.001}) {
    CAPTURE(h);
    ParticleInit init;
    init.length = h;
    init.cell_length = h;
    Point1D p(m, init);
    CHECK(p.state.eps_f == doctest::Approx(2 * G_c / (E * eps_i * h)).epsilon(1e-14));
    const double eps_f_h = p.state.eps_f;
    pull(p, eps_f_h / 100, 110);
    CHECK(p.state.dissipated * h == doctest::Approx(G_c).epsilon(1e-12));
    CHECK(p.sigma[0] == 0.0);
  }
  // Cells too large for the band (eps_f <= eps_i, a snap-back) are an error.
  ParticleInit coarse;
  coarse.length = coarse.cell_length = 0.1;  // 2 G_c / (E eps_i^2) = 0.0667 m
  CHECK_THROWS_WITH_AS(m.initial_state(coarse),
                       doctest::Contains("cells of size h = 0.1 m are too large for the crack band"), CaseError);
}

TEST_CASE("uniaxial strain (3D and plane strain): damage starts at eps_xx = eps_i sqrt(E / M), same energy") {
  // Energy-norm equivalent strain: eps_eq^2 = eps : C : eps / E = M eps_xx^2 / E.
  const StrainSoftening m = with_failure_strain();
  const double onset = eps_i * std::sqrt(E / M);
  MaterialPoint<StrainSoftening, StressState::three_d> p3(m);
  MaterialPoint<StrainSoftening, StressState::plane_strain> pe(m);
  for (int k = 0; k < 10; ++k) p3.strain({onset / 10, 0, 0, 0, 0, 0}), pe.strain({onset / 10, 0, 0, 0, 0, 0});
  CHECK(p3.state.kappa == doctest::Approx(eps_i).epsilon(1e-12));
  CHECK(p3.sigma[0] == doctest::Approx(M * onset).epsilon(1e-12));
  CHECK(p3.sigma[1] == doctest::Approx(M * nu / (1 - nu) * onset).epsilon(1e-12));
  CHECK(p3.state.dissipated == 0.0);
  for (int k = 0; k < 100; ++k) p3.strain({onset / 10, 0, 0, 0, 0, 0}), pe.strain({onset / 10, 0, 0, 0, 0, 0});
  CHECK(p3.state.dissipated == doctest::Approx(0.5 * E * eps_i * eps_f).epsilon(1e-12));
  for (int i = 0; i < 6; ++i) CHECK(pe.sigma[i] == p3.sigma[i]);
  CHECK(pe.state.dissipated == p3.state.dissipated);
  CHECK(p3.sigma[0] == 0.0);
}

TEST_CASE("plane stress: sigma_zz = 0 with eps_zz = -lambda / (lambda + 2 mu) (eps_xx + eps_yy), any damage") {
  const StrainSoftening m = with_failure_strain();
  MaterialPoint<StrainSoftening, StressState::plane_stress> p(m);
  for (int k = 0; k < 20; ++k) {  // to eps_eq of about 2.3 eps_i, inside the softening band
    p.strain({1e-5, 5e-6, 0, 0, 0, 2.5e-6});
    CHECK(p.sigma[2] == 0.0);
    CHECK(p.eps[2] == doctest::Approx(-nu / (1 - nu) * (p.eps[0] + p.eps[1])).epsilon(1e-12));
  }
  const double omega = m.damage(p.state.kappa, eps_f);
  CHECK(omega > 0.0);
  CHECK(omega < 1.0);
  const double Q = E / (1 - nu * nu);
  CHECK(p.sigma[0] == doctest::Approx((1 - omega) * Q * (p.eps[0] + nu * p.eps[1])).epsilon(1e-12));
}

TEST_CASE("objectivity: a rigid rotation turns the stress and the damage does not grow") {
  const StrainSoftening m = with_failure_strain();
  MaterialPoint<StrainSoftening, StressState::three_d> p(m);
  for (int k = 0; k < 10; ++k) p.strain({3e-5, -1e-5, 0, 0, 1e-5, 2e-5});
  const Voigt sigma0 = p.sigma;
  const double kappa = p.state.kappa;
  CHECK(m.damage(kappa, eps_f) > 0.0);
  const Eigen::Vector3d n = Eigen::Vector3d(1, -1, 2).normalized();
  const double angle = std::numbers::pi / 2;
  const Eigen::Vector3d w = 2 * std::tan(0.5 * angle / 200) * n;
  Eigen::Matrix3d W;
  W << 0, -w.z(), w.y(), w.z(), 0, -w.x(), -w.y(), w.x(), 0;
  for (int k = 0; k < 200; ++k) p.step(W);
  const Eigen::Matrix3d Q = Eigen::AngleAxisd(angle, n).toRotationMatrix();
  const Voigt expected = voigt_of(Q * tensor_of(sigma0) * Q.transpose());
  double scale = 0.0;
  for (double s : sigma0) scale = std::max(scale, std::abs(s));
  for (int i = 0; i < 6; ++i) CHECK(std::abs(p.sigma[i] - expected[i]) <= 1e-11 * scale);
  CHECK(p.state.kappa == doctest::Approx(kappa).epsilon(1e-12));
}

TEST_CASE("validation") {
  CHECK(material_error(base).find("give exactly one of failure_strain") != std::string::npos);
  CHECK(material_error(base + "failure_strain = 7e-4\nfracture_energy = 10.0\n").find("give exactly one of failure_strain") != std::string::npos);
  CHECK(material_error(base + "failure_strain = 5e-5\n").find("failure_strain: expected a failure strain eps_f above initiation_strain") != std::string::npos);
  CHECK(material_error(base + "fracture_energy = -1.0\n").find("fracture_energy: expected a positive fracture energy") != std::string::npos);
}

namespace {

// [Vignjevic]'s bar: 2 L = 200 mm along x, centred at 0, N square cells of h =
// 0.2 / N across it (N odd: the centre is a cell centre), one particle per
// cell, one row; nodes at y = 0 and y = h held in y (uniaxial strain,
// plane strain). The central particle is a notch, eps_i' = 0.9 eps_i. The
// ends move outward at v0 = 0.475 eps_xx,i c after a ramp of 0.2 L / c, so
// each step wave carries 0.475 of the intact onset strain and their sum at
// the centre (t = L / c) 0.95: above the notch's onset, below everyone
// else's. Run to 1.8 L / c (steps of 0.45 h / c): the notch has broken by
// 1.6 L / c, and the waves it sends out have not yet come back from the
// ends (2 L / c), where the pulled ends would load them again.
// Without the notch the discrete wave fronts (dispersed over a few cells)
// put the centre's neighbours at the peak stress too, and the damage
// spreads over 3 to 11 particles (README).
std::string bar_case(int N, bool regularised, int particles_per_cell = 1) {
  const double L = 0.1, h = 2 * L / N, c = std::sqrt(M / 2400.0);
  const double v0 = 0.475 * eps_i * std::sqrt(E / M) * c, ramp = 0.2 * L / c;
  const std::string softening = regularised ? "fracture_energy = 2.5\n" : "failure_strain = 2e-4\n";
  std::ostringstream s;
  s.precision(17);
  s << "[analysis]\ndimension = 2\nscheme = \"usl\"\ndt = " << 0.45 * h / c << "\nsteps = " << 2 * N << "\n"
    << "[grid]\norigin = [" << -L - h << ", 0.0]\ncell_size = " << h << "\ncells = [" << N + 2 << ", 1]\n"
    << "[materials.concrete]\n" << base << softening
    << "[materials.notch]\n" << notch << softening;
  const double x[4] = {-L, -h / 2, h / 2, L};
  const char* names[3] = {"left", "notch", "right"};
  for (int k = 0; k < 3; ++k) {
    s << "[[bodies]]\nname = \"" << names[k] << "\"\nmaterial = \"" << (k == 1 ? "notch" : "concrete")
      << "\"\nmin = [" << x[k] << ", 0.0]\nmax = [" << x[k + 1] << ", " << h << "]\nparticles_per_cell = "
      << particles_per_cell << "\n";
  }
  s << "[[node_sets]]\nname = \"lateral\"\nmin = [" << -L - h << ", 0.0]\nmax = [" << L + h << ", " << h
    << "]\nvelocity = { y = 0.0 }\n"
    << "[[node_sets]]\nname = \"left\"\nplane = \"x\"\nat = " << -L << "\nvelocity = { x = [[0.0, 0.0], [" << ramp
    << ", " << -v0 << "]] }\n"
    << "[[node_sets]]\nname = \"right\"\nplane = \"x\"\nat = " << L << "\nvelocity = { x = [[0.0, 0.0], [" << ramp
    << ", " << v0 << "]] }\n";
  return s.str();
}

struct BarResult {
  double dissipated_per_area = 0.0;  // J/m^2 of cross-section
  double h = 0.0;
  double x_most_damaged = 0.0, most_damage = 0.0;
  int damaged = 0;  // particles with any damage
};

BarResult run_bar(const Case& c) {
  auto sim = testing::simulation<2, LinearShape>(c);
  for (std::int64_t s = 0; s < c.steps; ++s) sim.advance();
  const auto& model = sim.system();
  BarResult r;
  r.h = model.grid.h[1];
  for (const auto& b : model.batches) {
    const auto& states = std::get<StateArray<StrainSoftening>>(b.states);
    const auto& m = std::get<StrainSoftening>(model.materials[b.material]);
    for (std::size_t p = 0; p < b.size(); ++p) {
      // Energy per unit initial volume (small strain) times the initial volume m / rho.
      r.dissipated_per_area += states[p].dissipated * b.mass[p] / m.density() / r.h;
      const double omega = m.damage(states[p].kappa, states[p].eps_f);
      if (omega > 0.0) ++r.damaged;
      if (omega > r.most_damage) r.most_damage = omega, r.x_most_damaged = b.x[p][0];
    }
  }
  return r;
}

}  // namespace

TEST_CASE("whole case: the bar breaks at the centre only; regularised, it dissipates G_c at any resolution") {
  for (int N : {21, 63, 189}) {
    CAPTURE(N);
    const BarResult r = run_bar(testing::case_from_text("softening_bar_" + std::to_string(N), bar_case(N, true)));
    MESSAGE("regularised, N = " << N << ": dissipated " << r.dissipated_per_area << " J/m^2 (G_c = 2.5), damaged "
            "particles " << r.damaged << ", largest damage " << r.most_damage << " at x = " << r.x_most_damaged);
    CHECK(r.damaged == 1);
    CHECK(std::abs(r.x_most_damaged) < 0.5 * r.h);
    CHECK(r.most_damage == 1.0);
    CHECK(r.dissipated_per_area == doctest::Approx(2.5).epsilon(1e-9));
  }
}

TEST_CASE("whole case: regularised, 2 x 2 particles per cell still dissipate G_c (the band is a cell)") {
  // The notch cell's four particles share their strain and break together;
  // regularising by the cell size (not the particle size, half of it) keeps
  // the dissipated energy at G_c.
  const BarResult r = run_bar(testing::case_from_text("softening_bar_2ppc", bar_case(63, true, 2)));
  MESSAGE("regularised, 2 particles per cell: dissipated " << r.dissipated_per_area << " J/m^2, damaged "
          << r.damaged);
  CHECK(r.damaged == 4);
  CHECK(r.most_damage == 1.0);
  CHECK(r.dissipated_per_area == doctest::Approx(2.5).epsilon(1e-9));
}

TEST_CASE("whole case: without regularisation the dissipated energy is (1/2) E eps_i eps_f h, falling with h") {
  double coarse = 0.0, fine = 0.0;
  for (int N : {21, 63, 189}) {
    CAPTURE(N);
    const BarResult r = run_bar(testing::case_from_text("softening_bar_local_" + std::to_string(N), bar_case(N, false)));
    const double band = 0.5 * E * 0.9 * eps_i * 2e-4 * r.h;
    MESSAGE("unregularised, N = " << N << ": dissipated " << r.dissipated_per_area << " J/m^2 ((1/2) E eps_i' eps_f h = "
            << band << "), damaged particles " << r.damaged);
    CHECK(r.damaged == 1);
    CHECK(std::abs(r.x_most_damaged) < 0.5 * r.h);
    CHECK(r.most_damage == 1.0);
    CHECK(r.dissipated_per_area == doctest::Approx(band).epsilon(1e-9));
    (N == 21 ? coarse : fine) = r.dissipated_per_area;
  }
  CHECK(coarse / fine == doctest::Approx(9.0).epsilon(1e-9));
}

TEST_CASE("the shipped strain-softening bar (63 cells) breaks at the notch and dissipates G_c") {
  const BarResult r = run_bar(read_case(testing::config("materials/strain_softening_bar.toml")));
  CHECK(r.damaged == 1);
  CHECK(std::abs(r.x_most_damaged) < 0.5 * r.h);
  CHECK(r.dissipated_per_area == doctest::Approx(2.5).epsilon(1e-9));
}
