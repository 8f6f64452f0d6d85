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
//    [Bazant 1985]).
//  - Nonlocal band opening at a material point: the law is piecewise linear
//    in the strain for a fixed neighbours' opening, so 1e-12 again, except
//    for the work summed over a step in which a particle breaks (a kink
//    inside the step: 1e-4). The engine's averages: 1e-12 for the weights of
//    a single source; 1e-4 for a particle's own width against h, the weight
//    being cut at 4 l where it is 3.4e-4 (the lattice sum of a cut weight
//    differs from its integral by about that times h / L), and so for the
//    notched bar's G_c with l = 20 mm.
//  - The symmetric bar without a notch ([Bazant 1985]; G_c = 5 J/m^2, waves
//    of 0.6 of the onset): 5 % of G_c, the goal of the regularisation; the
//    band covers several particles, which share the stress only
//    approximately while the waves cross it, and their Gaussian weights are
//    not all 1 (docs/theory/materials.md gives the values measured). The local
//    crack band: more than 1.2 G_c, the problem the nonlocal band solves.
#include <doctest/doctest.h>

#include <cmath>
#include <fstream>
#include <numbers>
#include <sstream>

#include "discretisation/nonlocal/nonlocal_average.hpp"
#include "discretisation/shapes/shape_bspline.hpp"
#include "discretisation/shapes/shape_linear.hpp"
#include "engine/simulation.hpp"
#include "material_point_driver.hpp"
#include "run_program.hpp"
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
// spreads over 3 to 11 particles (docs/theory/softening.md).
std::string bar_case(int N, bool regularised, int particles_per_cell = 1) {
  const double L = 0.1, h = 2 * L / N, c = std::sqrt(M / 2400.0);
  const double v0 = 0.475 * eps_i * std::sqrt(E / M) * c, ramp = 0.2 * L / c;
  const std::string softening = regularised ? "fracture_energy = 2.5\nnonlocal_length = 0\n" : "failure_strain = 2e-4\n";
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
  double dissipated_per_area = 0.0;  // J/m^2 of cross-section: the model's count
  double balance_per_area = 0.0;     // the energy balance's: work done less kinetic and stored energy
  double h = 0.0;
  double x_most_damaged = 0.0, most_damage = 0.0;
  int damaged = 0;  // particles with any damage
  int broken = 0;   // particles with omega = 1
  std::int64_t unsettled = 0;  // steps whose nonlocal averages did not settle
};

template <class Shape = LinearShape>
BarResult run_bar(const Case& c) {
  auto sim = testing::simulation<2, Shape>(c);
  for (std::int64_t s = 0; s < c.time_control.steps; ++s) sim.advance();
  const auto& model = sim.system();
  BarResult r;
  r.h = model.grid.h[1];
  const Diagnostics energy = sim.diagnostics(c.system.bodies.size());
  r.balance_per_area = (energy.dissipated_energy - energy.energy_balance()) / r.h;
  r.unsettled = model.nonlocal ? model.nonlocal->unsettled_steps : 0;
  for (const auto& b : model.batches) {
    const auto& states = std::get<StateArray<StrainSoftening>>(b.states);
    const auto& m = std::get<StrainSoftening>(model.materials[b.material]);
    for (std::size_t p = 0; p < b.size(); ++p) {
      // Energy per unit initial volume (small strain) times the initial volume m / rho.
      r.dissipated_per_area += states[p].dissipated * b.mass[p] / m.density() / r.h;
      const double omega = states[p].omega;
      if (omega > 0.0) ++r.damaged;
      if (omega == 1.0) ++r.broken;
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

// ---------------------------------------------------------------------------
// Nonlocal band opening (nonlocal_length; materials/strain_softening.hpp,
// discretisation/nonlocal/nonlocal_average.hpp, tasks/nonlocal_settle.hpp).

namespace {

StrainSoftening with_nonlocal(double l) {
  std::ostringstream s;
  s << base << "fracture_energy = 10.0\nnonlocal_length = " << l << "\n";
  return std::get<StrainSoftening>(material_from_text(s.str()));
}

// One uniaxial-stress increment d eps at a material point, with the engine's
// nonlocal inputs given by hand.
void pull_nonlocal(const StrainSoftening& m, StrainSoftening::State& state, Voigt& sigma, double d, double others,
                   double self_weight) {
  Voigt deps{d, 0, 0, 0, 0, 0};
  MaterialInput in;
  in.dL(0, 0) = d;
  in.nonlocal_others = others;
  in.nonlocal_self_weight = self_weight;
  m.update<StressState::uniaxial_stress>(state, sigma, deps, in);
}

}  // namespace

TEST_CASE("nonlocal band opening, material point: alone in its band it is the crack band of its own width") {
  // With the others' opening 0 and its own weight V_p / sum alpha V = c / L,
  // a particle follows the crack band of width c: eps_f = 2 G_c / (E eps_i c).
  const StrainSoftening m = with_nonlocal(0.05);
  const double c = 0.004, w_c = 2 * G_c / (E * eps_i);
  CHECK(m.w_c == doctest::Approx(w_c).epsilon(1e-14));
  CHECK(m.window == doctest::Approx(std::sqrt(2 * std::numbers::pi) * 0.05 * std::erf(2 * std::sqrt(2.0))).epsilon(1e-14));
  ParticleInit init;
  init.length = init.cell_length = c;
  StrainSoftening::State state = m.initial_state(init);
  Voigt sigma{};
  const double eps_f_c = w_c / c;
  double work = 0.0;
  for (int k = 1; k <= 120; ++k) {
    const double before = sigma[0];
    pull_nonlocal(m, state, sigma, eps_f_c / 100, 0.0, c / m.window);
    work += 0.5 * (before + sigma[0]) * eps_f_c / 100;
    const double eps = k * eps_f_c / 100;
    const double expected = eps <= eps_i ? E * eps : eps >= eps_f_c ? 0.0 : E * eps_i * (eps_f_c - eps) / (eps_f_c - eps_i);
    CAPTURE(eps);
    CHECK(sigma[0] == doctest::Approx(expected).epsilon(1e-12).scale(E * eps_i * 1e-2));
    CHECK(work == doctest::Approx(0.5 * sigma[0] * eps + state.dissipated).epsilon(1e-10));
    CHECK(state.opening == doctest::Approx(state.omega * eps).epsilon(1e-12));
  }
  CHECK(state.omega == 1.0);
  CHECK(state.dissipated * c == doctest::Approx(G_c).epsilon(1e-12));
}

TEST_CASE("nonlocal band opening, material point: the others' opening W_o lowers the band's strength f (1 - W_o / w_c)") {
  const StrainSoftening m = with_nonlocal(0.05);
  const double c = 0.004, w_c = 2 * G_c / (E * eps_i), self_weight = c / m.window;
  ParticleInit init;
  init.length = init.cell_length = c;
  SUBCASE("onset stays local: elastic to eps_i whatever W_o, then on the band's law (a jump of omega)") {
    StrainSoftening::State state = m.initial_state(init);
    Voigt sigma{};
    const double others = 0.5 * w_c / m.window;  // W_o = w_c / 2: the band carries f / 2 at most
    for (int k = 0; k < 9; ++k) pull_nonlocal(m, state, sigma, eps_i / 10, others, self_weight);
    CHECK(state.omega == 0.0);
    CHECK(sigma[0] == doctest::Approx(0.9 * E * eps_i).epsilon(1e-12));
    pull_nonlocal(m, state, sigma, eps_i / 10, others, self_weight);
    // (1 - omega) E eps = E s - E r omega eps, s = eps_i / 2, r = eps_i c / w_c.
    const double s = 0.5 * eps_i, r = eps_i * c / w_c;
    const double omega = (eps_i - s) / ((1 - r) * eps_i);
    CHECK(state.omega == doctest::Approx(omega).epsilon(1e-12));
    CHECK(sigma[0] == doctest::Approx((1 - omega) * E * eps_i).epsilon(1e-12));
    // The jump at eps_i dissipates Y d omega = (1/2) E eps_i^2 omega.
    CHECK(state.dissipated == doctest::Approx(0.5 * E * eps_i * eps_i * omega).epsilon(1e-12));
  }
  SUBCASE("a rise of W_o at fixed strain dissipates exactly the stored energy it releases; at failure work = dissipated") {
    StrainSoftening::State state = m.initial_state(init);
    Voigt sigma{};
    double work = 0.0, eps = 0.0;
    auto load = [&](int n, double d, double others) {
      for (int k = 0; k < n; ++k) {
        const double before = sigma[0];
        pull_nonlocal(m, state, sigma, d, others, self_weight);
        work += 0.5 * (before + sigma[0]) * d;  // exact: sigma is linear in eps inside a step of fixed W_o
        eps += d;
      }
    };
    load(20, eps_i / 10, 0.0);  // to 2 eps_i alone in its band
    const double stored = 0.5 * sigma[0] * eps, dissipated = state.dissipated;
    CHECK(work == doctest::Approx(stored + dissipated).epsilon(1e-12));
    load(1, 0.0, 0.3 * w_c / m.window);  // the neighbours open: the strength falls, no work
    const double released = stored - 0.5 * sigma[0] * eps;
    CHECK(released > 0.0);
    CHECK(state.dissipated - dissipated == doctest::Approx(released).epsilon(1e-12));
    load(100, eps_i / 10, 0.3 * w_c / m.window);  // on to failure
    CHECK(state.omega == 1.0);
    CHECK(sigma[0] == 0.0);
    // Work = dissipated at failure (the step in which it breaks has a kink
    // the trapezoid does not follow: 1e-4).
    CHECK(work == doctest::Approx(state.dissipated).epsilon(1e-4));
  }
  SUBCASE("W_o >= w_c: the band is open, a particle past onset breaks and releases what it stored") {
    StrainSoftening::State state = m.initial_state(init);
    Voigt sigma{};
    for (int k = 0; k < 15; ++k) pull_nonlocal(m, state, sigma, eps_i / 10, 0.0, self_weight);
    const double stored = 0.5 * sigma[0] * 1.5 * eps_i, dissipated = state.dissipated;
    pull_nonlocal(m, state, sigma, 0.0, 1.1 * w_c / m.window, self_weight);
    CHECK(state.omega == 1.0);
    CHECK(sigma[0] == 0.0);
    CHECK(state.dissipated - dissipated == doctest::Approx(stored).epsilon(1e-12));
  }
  SUBCASE("an own width beyond the snap-back length w_c / eps_i: brittle, it breaks at the onset") {
    StrainSoftening::State state = m.initial_state(init);
    Voigt sigma{};
    const double wide = 1.5 * (w_c / eps_i) / m.window;  // c = 1.5 w_c / eps_i
    for (int k = 0; k < 10; ++k) pull_nonlocal(m, state, sigma, eps_i / 10, 0.0, wide);
    CHECK(state.omega == 0.0);
    pull_nonlocal(m, state, sigma, eps_i / 10, 0.0, wide);
    CHECK(state.omega == 1.0);
    CHECK(sigma[0] == 0.0);
    // What it stored at the onset, (1/2) E eps_i^2.
    CHECK(state.dissipated == doctest::Approx(0.5 * E * eps_i * eps_i).epsilon(1e-12));
  }
}

TEST_CASE("nonlocal averages (engine): Gaussian weights over the initial positions, the particle itself apart") {
  // A row of 41 particles of h = 5 mm; l = 2.05 h (the cut-off 4 l = 8.2 h
  // falls between particles). Interior: sum alpha V = h^2 sum_k exp(-(k
  // h)^2 / (2 l^2)) = h L to 1e-4, L = sqrt(2 pi) l erf(2 sqrt 2) the
  // integral of the weight cut at 4 l, so a lone particle's own width L V_p
  // / sum alpha V is h (the sum over a lattice of a weight cut where it is
  // exp(-8) = 3.4e-4 differs from its integral by about that times h / L;
  // 3.5e-5 here).
  const double h = 0.005, l = 2.05 * h;
  std::ostringstream s;
  s.precision(17);
  s << "[analysis]\ndimension = 2\ndt = 1e-7\nsteps = 1\n[grid]\norigin = [0.0, 0.0]\ncell_size = " << h
    << "\ncells = [43, 1]\n[materials.concrete]\n" << base << "fracture_energy = 10.0\nnonlocal_length = " << l
    << "\n[[bodies]]\nname = \"row\"\nmaterial = \"concrete\"\nmin = [" << h << ", 0.0]\nmax = [" << 42 * h << ", "
    << h << "]\nparticles_per_cell = 1\n";
  const Case c = testing::case_from_text("nonlocal_row", s.str());
  auto sim = testing::simulation<2, LinearShape>(c);
  auto& model = sim.system();
  REQUIRE(model.nonlocal.has_value());
  auto& b = model.batches[0];
  const auto& m = std::get<StrainSoftening>(model.materials[0]);
  auto& states = std::get<StateArray<StrainSoftening>>(b.states);
  std::size_t centre = 0;
  for (std::size_t p = 0; p < b.size(); ++p)
    if (std::abs(b.x[p][0] - 21.5 * h) < 0.1 * h) centre = p;
  CHECK(m.window * b.nonlocal_self_weight[centre] == doctest::Approx(h).epsilon(1e-4));
  // One source: its neighbours get alpha V e / sum alpha V; itself and those beyond 4 l nothing.
  states[centre].opening = 1e-4;
  std::vector<std::vector<double>> average;
  nonlocal_average(model, average);
  int reached = 0;
  for (std::size_t p = 0; p < b.size(); ++p) {
    const double r = std::abs(b.x[p][0] - b.x[centre][0]);
    CAPTURE(r);
    const double expected = p == centre || r >= 4 * l ? 0.0
                            : std::exp(-r * r / (2 * l * l)) * b.nonlocal_self_weight[p] * 1e-4;
    CHECK(average[0][p] == doctest::Approx(expected).epsilon(1e-12).scale(1e-20));
    reached += average[0][p] > 0.0;
  }
  CHECK(reached == 2 * 8);  // r = h ... 8 h < 4 l on each side
}

TEST_CASE("validation: nonlocal_length goes with fracture_energy, and is at least the cell size") {
  CHECK(material_error(base + "failure_strain = 7e-4\nnonlocal_length = 0.02\n")
            .find("nonlocal_length: expected fracture_energy beside it, not failure_strain") != std::string::npos);
  CHECK(material_error(base + "fracture_energy = 10.0\nnonlocal_length = -0.01\n")
            .find("nonlocal_length: expected a nonlocal length l >= 0 in m") != std::string::npos);
  // Not given: the snap-back length 2 G_c / (E eps_i^2); 0: the crack band of one cell.
  const auto by_default = std::get<StrainSoftening>(material_from_text(base + "fracture_energy = 10.0\n"));
  CHECK(by_default.nonlocal_length() == doctest::Approx(2.0 * 10.0 / (E * eps_i * eps_i)).epsilon(1e-15));
  const auto cell = std::get<StrainSoftening>(material_from_text(base + "fracture_energy = 10.0\nnonlocal_length = 0\n"));
  CHECK(cell.nonlocal_length() == 0.0);
  const StrainSoftening m = with_nonlocal(0.005);
  ParticleInit init;
  init.length = init.cell_length = 0.01;
  CHECK_THROWS_WITH_AS(m.initial_state(init), doctest::Contains("nonlocal_length = 0.005 m is below the cell size"),
                       CaseError);
}

namespace {

// The classic bar of [Bazant 1985], symmetric, no notch: as bar_case but one
// body, both ends pulled outward at v0 = 0.6 eps_xx,i c from t = 0 (each
// step wave carries 0.6 of the onset strain; they sum to 1.2 of it where
// they meet, at the centre, at L / c); G_c = 5 J/m^2; dt = 0.45 h / c; run
// to 1.9 L / c (the waves the band sends out reach the pulled ends at 2 L /
// c). l > 0: nonlocal_length l; 0: the local crack band of a cell; < 0:
// no nonlocal_length, the default. `courant`: dt = courant h / c.
std::string symmetric_bar_case(int N, double l, int particles_per_cell = 1, const std::string& shape = "linear",
                               const std::string& scheme = "usl", double courant = 0.45) {
  const double L = 0.1, h = 2 * L / N, c = std::sqrt(M / 2400.0);
  const double v0 = 0.6 * eps_i * std::sqrt(E / M) * c;
  const int pad = shape == "linear" ? 1 : 2;  // wider stencils need a cell more around the bar
  std::ostringstream s;
  s.precision(17);
  s << "[analysis]\ndimension = 2\nscheme = \"" << scheme << "\"\nshape_function = \"" << shape
    << "\"\ndt = " << courant * h / c << "\nsteps = " << std::lround(1.9 * N / 2 / courant) << "\n"
    << "[grid]\norigin = [" << -L - pad * h << ", " << -(pad - 1) * h << "]\ncell_size = " << h << "\ncells = ["
    << N + 2 * pad << ", " << 2 * pad - 1 << "]\n"
    << "[materials.concrete]\n" << base << "fracture_energy = 5.0\n";
  if (l >= 0) s << "nonlocal_length = " << l << "\n";
  s << "[[bodies]]\nname = \"bar\"\nmaterial = \"concrete\"\nmin = [" << -L << ", 0.0]\nmax = [" << L << ", " << h
    << "]\nparticles_per_cell = " << particles_per_cell << "\n"
    << "[[node_sets]]\nname = \"lateral\"\nmin = [" << -L - pad * h << ", " << -(pad - 1) * h << "]\nmax = ["
    << L + pad * h << ", " << pad * h << "]\nvelocity = { y = 0.0 }\n";
  for (int side : {-1, 1}) {
    s << "[[node_sets]]\nname = \"" << (side < 0 ? "left" : "right") << "\"\nplane = \"x\"\nat = " << side * L
      << "\nvelocity = { x = " << side * v0 << " }\n";
  }
  return s.str();
}

}  // namespace

TEST_CASE("symmetric bar without a notch: the local crack band dissipates too much (the band is wider than a cell)") {
  // The discrete wave fronts are dispersed over several cells (more at finer
  // grids): where they meet, their sum is flat over several cells, which
  // reach the onset in one step and each soften with a cell's fracture
  // energy (docs/theory/materials.md).
  for (int N : {93, 279}) {
    CAPTURE(N);
    const BarResult r = run_bar(testing::case_from_text("softening_symmetric_local_" + std::to_string(N),
                                                        symmetric_bar_case(N, 0.0)));
    MESSAGE("local crack band, N = " << N << ": dissipated " << r.dissipated_per_area << " J/m^2 (G_c = 5), damaged "
            << r.damaged << ", broken " << r.broken);
    CHECK(r.damaged > 3);
    CHECK(r.dissipated_per_area > 1.2 * 5.0);
  }
}

TEST_CASE("symmetric bar without a notch: the nonlocal band opening dissipates G_c within 5 % at 45, 93, 279 cells") {
  // l = 20 mm (about Hillerborg's E G_c / f^2 = 16.7 mm; twice the widest
  // band that forms at these resolutions). The band covers several
  // particles, all of which break; together they dissipate G_c. 31 cells
  // are too coarse: the band that forms there is as wide as the snap-back
  // length 2 G_c / (E eps_i^2) = 33 mm (docs/theory/materials.md).
  for (int ppc : {1, 2}) {
    for (int N : {45, 93, 279}) {
      CAPTURE(N);
      CAPTURE(ppc);
      const BarResult r = run_bar(testing::case_from_text("softening_symmetric_" + std::to_string(N),
                                                          symmetric_bar_case(N, 0.02, ppc)));
      MESSAGE("nonlocal band, N = " << N << ", " << ppc << " x " << ppc << " ppc: dissipated " << r.dissipated_per_area
              << " J/m^2 (G_c = 5), damaged " << r.damaged << ", broken " << r.broken);
      CHECK(r.dissipated_per_area == doctest::Approx(5.0).epsilon(0.05));
      CHECK(r.broken > 0);
      CHECK(std::abs(r.x_most_damaged) < 0.02);
      CHECK(r.unsettled == 0);
    }
  }
}

TEST_CASE("symmetric bar without a notch, quadratic B-splines: G_c within 5 %") {
  const BarResult r = run_bar<QuadraticBSpline>(
      testing::case_from_text("softening_symmetric_bspline2", symmetric_bar_case(93, 0.02, 1, "bspline2")));
  MESSAGE("nonlocal band, bspline2, N = 93: dissipated " << r.dissipated_per_area << " J/m^2, damaged " << r.damaged);
  CHECK(r.dissipated_per_area == doctest::Approx(5.0).epsilon(0.05));
  CHECK(r.broken > 0);
  CHECK(r.unsettled == 0);
}

TEST_CASE("the notched bar with the nonlocal band opening: the notch alone breaks, G_c") {
  // Alone in its band, the notch has the crack band of its own width c = L
  // V_p / sum alpha V = h to 1e-4 (the cut weight, above).
  const BarResult r = run_bar(read_case(testing::config("materials/strain_softening_bar.toml"),
                                        {"materials.concrete.nonlocal_length=0.02", "materials.notch.nonlocal_length=0.02"}));
  CHECK(r.damaged == 1);
  CHECK(std::abs(r.x_most_damaged) < 0.5 * r.h);
  CHECK(r.dissipated_per_area == doctest::Approx(2.5).epsilon(1e-4));
}

TEST_CASE("the shipped symmetric bar (93 cells, no notch, the default band) dissipates G_c within 5 % by both counts") {
  const Case c = read_case(testing::config("materials/strain_softening_symmetric_bar.toml"));
  const BarResult r = run_bar(c);
  MESSAGE("the shipped symmetric bar: model " << r.dissipated_per_area << ", balance " << r.balance_per_area
          << " J/m^2 (damaged " << r.damaged << ")");
  CHECK(r.dissipated_per_area == doctest::Approx(5.0).epsilon(0.05));
  CHECK(r.balance_per_area == doctest::Approx(5.0).epsilon(0.05));
  CHECK(r.broken > 0);
  CHECK(std::abs(r.x_most_damaged) < 0.02);
  CHECK(r.unsettled == 0);
  // With nonlocal_length = 0 the same case is the local crack band.
  const BarResult local = run_bar(read_case(testing::config("materials/strain_softening_symmetric_bar.toml"),
                                            {"materials.concrete.nonlocal_length=0"}));
  MESSAGE("with nonlocal_length = 0: " << local.dissipated_per_area << " J/m^2 (damaged " << local.damaged << ")");
  CHECK(local.dissipated_per_area > 1.2 * 5.0);
}

TEST_CASE("symmetric bar, the default band (no nonlocal_length): G_c within 5 % at 45, 93, 279 cells by both counts") {
  // The default l is the snap-back length 2 G_c / (E eps_i^2) = 33.3 mm.
  // MUSL with dt = 0.2 h / c, as the shipped case: the balance's count
  // (work less kinetic and stored energy) exceeds the model's by what the
  // scheme loses, O(dt) where the stress lags the softening and O(h) where
  // the grid smears the opening (docs/theory/softening.md: 0.18 J/m^2 at
  // 45 cells, 0.02 at 279). Measured: model 4.99-5.06, balance 5.02-5.24.
  for (int ppc : {1, 2}) {
    for (int N : {45, 93, 279}) {
      CAPTURE(N);
      CAPTURE(ppc);
      const BarResult r = run_bar(testing::case_from_text("softening_symmetric_default_" + std::to_string(N),
                                                          symmetric_bar_case(N, -1.0, ppc, "linear", "musl", 0.2)));
      MESSAGE("default band, N = " << N << ", " << ppc << " x " << ppc << " ppc: model " << r.dissipated_per_area
              << ", balance " << r.balance_per_area << " J/m^2 (G_c = 5), damaged " << r.damaged);
      CHECK(r.dissipated_per_area == doctest::Approx(5.0).epsilon(0.05));
      CHECK(r.balance_per_area == doctest::Approx(5.0).epsilon(0.05));
      CHECK(r.broken > 0);
      CHECK(std::abs(r.x_most_damaged) < 0.02);
      CHECK(r.unsettled == 0);
    }
  }
}

TEST_CASE("the log names the crack band's l, and warns where the cells do not resolve it") {
  testing::TempDir dir("flowmpm_softening");
  auto check_log = [&](const std::string& name, const std::string& text) {
    testing::write_text(dir.path / (name + ".toml"), text);
    const testing::Result r = testing::run_flowmpm({"check", name + ".toml"}, dir.path);
    CHECK_MESSAGE(r.status == 0, r.output);
    return r.output;
  };
  // 93 cells of 2.15 mm: the default l = 33.3 mm is 15.5 cells.
  const std::string resolved = check_log("resolved", symmetric_bar_case(93, -1.0));
  CHECK(testing::contains(resolved, "nonlocal_length l = 0.0333333 m (the default, 2 G_c / (E eps_i^2)), 15.5 cells"));
  CHECK_FALSE(testing::contains(resolved, "under-resolved"));
  // 31 cells of 6.45 mm: 5.2 cells per l, where the bar dissipates +14 %.
  CHECK(testing::contains(check_log("coarse", symmetric_bar_case(31, -1.0)), "is only 5.2 cells"));
  CHECK(testing::contains(check_log("cell", symmetric_bar_case(93, 0.0)), "the crack band of one cell"));
}
