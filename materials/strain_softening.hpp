// Linear strain-softening damage ([Vignjevic], eqs. 5.98 and
// 5.99), small strain, isotropic elasticity (E, nu; lambda, mu):
//   sigma = (1 - omega) C eps,   secant unloading towards the origin,
//   omega(kappa) = 0                                          kappa <= eps_i,
//                  eps_f (kappa - eps_i) / (kappa (eps_f - eps_i))   eps_i < kappa < eps_f,
//                  1                                          kappa >= eps_f,
// kappa the largest equivalent strain reached (irreversible). Along a
// monotonic path the stress falls linearly from E eps_i at eps_i to 0 at
// eps_f, with tangent E_t = -E eps_i / (eps_f - eps_i).
// Equivalent strain: energy norm eps_eq = sqrt(eps : C : eps / E), which is
// |eps_xx| in uniaxial stress and sqrt(M / E) eps_xx in uniaxial strain
// (M = lambda + 2 mu). It treats tension and compression alike (as the
// one-dimensional law of [Vignjevic] in |eps|): a model of tensile cracking under
// tensile loading, not of compressive crushing.
// Dissipation: Y d omega with Y = eps : C : eps / 2 = E kappa^2 / 2 while
// damage grows, which integrates in closed form to
//   d g = (1/2) E eps_i eps_f d kappa / (eps_f - eps_i)   on eps_i < kappa < eps_f,
// so failure dissipates g_f = (1/2) E eps_i eps_f per unit volume on any
// path.
// Crack band (given the fracture energy G_c, J/m^2, instead of eps_f): in
// terms of the opening w of the band where the material softens (an
// equivalent strain times a length) the law is the linear cohesive law
//   E eps_eq (1 - omega) = f (1 - w / w_c),  f = E eps_i,  w_c = 2 G_c / (E eps_i),
// so that a band that breaks dissipates G_c per unit area whatever its
// width [Bazant 1983]. e = omega eps_eq is a particle's inelastic
// equivalent strain, its share of the opening per unit width. Two ways to
// measure w:
//  - local (no nonlocal_length): the band is the particle's cell, w = h e,
//    h the cell size (ParticleInit::cell_length), i.e. the law above with
//    eps_f = w_c / h = 2 G_c / (E eps_i h) per particle. Right when the
//    softening localises into one cell (the particles of a cell share their
//    velocity gradient), e.g. at a notch.
//  - nonlocal (nonlocal_length l): w = L e_bar, e_bar the average of e over
//    the neighbours with the weight alpha = exp(-r^2 / (2 l^2)) cut at 4 l
//    ([Pijaudier-Cabot 1987]; discretisation/nonlocal/nonlocal_average.hpp), L =
//    sqrt(2 pi) l erf(2 sqrt 2) the weight's integral across a plane. The
//    Gaussian is the product of its 1D factors, so across a planar band
//    narrower than l that spans the window, L e_bar is the band's whole
//    opening, the sum over its particles of e times their width: the band
//    dissipates G_c however many particles, cells or rows it covers. The
//    softening variable is a nonlocal inelastic strain, as in nonlocal
//    softening plasticity ([Bazant 1988], [Vermeer 1994]; compared in
//    [Jirasek 2003]), times L to make it an opening. Onset stays local: a
//    particle softens once its own eps_eq has reached eps_i, then on the
//    band's law (an elastic neighbour of an opening band is not weakened by
//    it; one that reaches eps_i joins the band, its damage jumping to the
//    band's, instead of starting a band of its own). A particle alone in its
//    band follows the local law with its own width c = L V_p / sum alpha V
//    (h at 1 particle per cell, to 1e-4) instead of the cell.
//    Update, with W_o = L nonlocal_others the neighbours' part of the
//    opening (made consistent with the step's end by the engine,
//    tasks/nonlocal_settle.hpp) and c e the particle's own: in strain units
//    s = eps_i (1 - W_o / w_c) the band's strength and r = eps_i c / w_c,
//    eps_eq (1 - omega) = s - r omega eps_eq gives
//      omega(eps_eq) = (eps_eq - s) / ((1 - r) eps_eq)  in [0, 1]
//    (eq. 5.99 for W_o = 0, c = h), kept at its largest, with Y d omega =
//    E s d eps_eq / (2 (1 - r)) in closed form along a step, plus Y times
//    any jump of omega where the band's strength fell below the particle's
//    stress.
// The band must soften, eps_f > eps_i, i.e. h < 2 G_c / (E eps_i^2); larger
// cells are an error, and so is l below the cell size.
// The total strain is kept in the state and turns with the material
// (rotation.hpp); the reduced states: plane strain eps_zz = 0; plane stress
// eps_zz = -lambda / (lambda + 2 mu) (eps_xx + eps_yy); uniaxial stress
// eps_yy = eps_zz = -nu eps_xx (sigma_yy = sigma_zz = 0 for any omega < 1).
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <optional>

#include "core/voigt.hpp"
#include "materials/material_input.hpp"
#include "materials/rotation.hpp"
#include "materials/lame.hpp"
#include "materials/state_variable.hpp"
#include "materials/stress_state.hpp"
#include "materials/transport_properties.hpp"

namespace flowmpm {

class ParameterTable;

struct StrainSoftening {
  static constexpr const char* type_name = "strain_softening";

  struct Parameters {
    double density = 0.0;            // kg/m^3
    double youngs_modulus = 0.0;     // E (Pa)
    double poisson_ratio = 0.0;      // -
    double initiation_strain = 0.0;  // eps_i (-)
    // Exactly one of: eps_f (-), the same for every particle, or G_c (J/m^2),
    // giving eps_f = 2 G_c / (E eps_i h) per particle.
    std::optional<double> failure_strain;
    std::optional<double> fracture_energy;
    TransportProperties transport;  // heat capacity, conductivity, diffusivity (scalars)
    // With fracture_energy only: l (m) of the nonlocal band opening; absent:
    // the band is the particle's cell. Read as default_nonlocal_length when
    // the case gives none, absent when it gives 0.
    std::optional<double> nonlocal_length;
  };
  // The default l: the snap-back length w_c / eps_i = 2 G_c / (E eps_i^2),
  // the widest band that can soften on the law without snapping back
  // (twice Hillerborg's E G_c / f^2, [Hillerborg 1976]): a band that forms
  // narrower than it fits in the window (docs/theory/softening.md).
  static double default_nonlocal_length(const Parameters& p) {
    return 2.0 * *p.fracture_energy / (p.youngs_modulus * p.initiation_strain * p.initiation_strain);
  }
  struct State {
    Voigt eps{};              // total strain
    double kappa = 0.0;       // largest equivalent strain reached
    double eps_f = 0.0;       // failure strain of this particle in a band of its cell
    double omega = 0.0;       // damage
    double opening = 0.0;     // inelastic equivalent strain omega eps_eq (the nonlocal source)
    double dissipated = 0.0;  // energy dissipated per unit volume (J/m^3)
  };

  Parameters parameters;
  double lambda = 0.0, mu = 0.0;
  double w_c = 0.0;     // band opening at failure, 2 G_c / (E eps_i) (m)
  double window = 0.0;  // L = sqrt(2 pi) l erf(2 sqrt 2) (m); 0: local

  explicit StrainSoftening(const Parameters& p)
      : parameters(p),
        lambda(lame_lambda(p.youngs_modulus, p.poisson_ratio)),
        mu(lame_mu(p.youngs_modulus, p.poisson_ratio)),
        w_c(p.fracture_energy ? 2.0 * *p.fracture_energy / (p.youngs_modulus * p.initiation_strain) : 0.0),
        window(p.nonlocal_length
                   ? std::sqrt(2.0 * std::numbers::pi) * *p.nonlocal_length * std::erf(2.0 * std::numbers::sqrt2)
                   : 0.0) {}

  // Reads and validates [materials.NAME] (type = "strain_softening").
  static StrainSoftening read(ParameterTable& table);

  // Damage omega (-) and the energy dissipated per unit volume (J/m^3).
  static constexpr std::array<StateVariable, 2> state_variables{{{"damage", "-"}, {"dissipated_energy", "J/m^3"}}};
  void state_values(const State& s, double* out) const {
    out[0] = s.omega;
    out[1] = s.dissipated;
  }

  // eps_f in a band of width init.cell_length; throws CaseError if the crack
  // band would snap back (eps_f <= eps_i).
  State initial_state(const ParticleInit& init) const;

  double density() const { return parameters.density; }
  const TransportProperties& transport() const { return parameters.transport; }
  // P wave of the undamaged material, sqrt((lambda + 2 mu) / rho) (m/s).
  double wave_speed() const { return std::sqrt((lambda + 2.0 * mu) / parameters.density); }

  // Nonlocal band opening (materials/nonlocal_model.hpp).
  double nonlocal_length() const { return parameters.nonlocal_length.value_or(0.0); }
  double nonlocal_source(const State& s) const { return s.opening; }
  // Onset is local: below it the update does not read the average.
  bool nonlocal_read(const State& s) const { return s.kappa >= parameters.initiation_strain; }

  // omega(kappa) of eq. 5.99: the damage of the local crack band.
  double damage(double kappa, double eps_f) const {
    const double eps_i = parameters.initiation_strain;
    if (kappa <= eps_i) return 0.0;
    if (kappa >= eps_f) return 1.0;
    return eps_f * (kappa - eps_i) / (kappa * (eps_f - eps_i));
  }

  // Energy-norm equivalent strain of a total strain (|eps_xx| in uniaxial stress).
  template <StressState Kind>
  double equivalent_strain(const Voigt& e) const {
    if constexpr (Kind == StressState::uniaxial_stress) {
      return std::abs(e[0]);
    } else {
      const double tr = e[0] + e[1] + e[2];
      return std::sqrt((lambda * tr * tr + 2.0 * mu * double_contraction(e, e)) / parameters.youngs_modulus);
    }
  }

  template <StressState Kind>
  void update(State& state, Voigt& sigma, Voigt& deps, const MaterialInput& in) const {
    const double E = parameters.youngs_modulus, nu = parameters.poisson_ratio;
    const bool nonlocal = window > 0.0 && in.nonlocal_self_weight > 0.0;
    Voigt& e = state.eps;
    // At the start of the step (the rotation below keeps it).
    const double eps_a = nonlocal ? equivalent_strain<Kind>(e) : 0.0;
    // eps_eq at the end of the step; lambda tr(eps) serves it and the stress
    // (one product for both, as the local law has always rounded it).
    double eps_b = 0.0, lambda_tr = 0.0;
    if constexpr (Kind == StressState::uniaxial_stress) {
      e[0] += deps[0];
      deps[1] = -nu * e[0] - e[1];
      deps[2] = -nu * e[0] - e[2];
      e[1] = e[2] = -nu * e[0];
      eps_b = std::abs(e[0]);
    } else {
      rotate_with_spin<Kind>(e, in.dL);
      if constexpr (Kind == StressState::plane_stress) {
        const double e_zz = -lambda / (lambda + 2.0 * mu) * (e[0] + deps[0] + e[1] + deps[1]);
        deps[2] = e_zz - e[2];
      }
      for (int i = 0; i < 6; ++i) e[i] += deps[i];
      const double tr = e[0] + e[1] + e[2];
      lambda_tr = lambda * tr;
      eps_b = std::sqrt((lambda_tr * tr + 2.0 * mu * double_contraction(e, e)) / E);
    }
    if (nonlocal) {
      band_damage(state, eps_a, eps_b, in);
    } else {
      cell_damage(state, eps_b);
    }
    state.opening = state.omega * eps_b;
    const double intact = 1.0 - state.omega;
    if constexpr (Kind == StressState::uniaxial_stress) {
      sigma = {intact * E * e[0], 0.0, 0.0, 0.0, 0.0, 0.0};
    } else {
      for (int i = 0; i < 3; ++i) sigma[i] = intact * (lambda_tr + 2.0 * mu * e[i]);
      for (int i = 3; i < 6; ++i) sigma[i] = intact * 2.0 * mu * e[i];
      if constexpr (Kind == StressState::plane_stress) sigma[2] = 0.0;  // round-off only
    }
  }

  // The local law (eq. 5.99 in kappa) to eps_eq, with its dissipation.
  void cell_damage(State& state, double eps_eq) const {
    const double E = parameters.youngs_modulus, eps_i = parameters.initiation_strain, eps_f = state.eps_f;
    if (eps_eq > state.kappa) {
      const double from = std::max(state.kappa, eps_i), to = std::min(eps_eq, eps_f);
      if (to > from) state.dissipated += 0.5 * E * eps_i * eps_f * (to - from) / (eps_f - eps_i);
      state.kappa = eps_eq;
    }
    state.omega = damage(state.kappa, eps_f);
  }

  // The band's law (header) over a step from eps_eq = eps_a to eps_b, with
  // its dissipation.
  void band_damage(State& state, double eps_a, double eps_b, const MaterialInput& in) const {
    const double E = parameters.youngs_modulus, eps_i = parameters.initiation_strain;
    const bool past_onset = state.kappa >= eps_i;
    state.kappa = std::max(state.kappa, eps_b);
    if (state.kappa < eps_i || state.omega >= 1.0) return;  // not at onset yet, or broken
    const double s = eps_i * (1.0 - window * in.nonlocal_others / w_c);
    const double r = eps_i * window * in.nonlocal_self_weight / w_c;  // eps_i c / w_c
    auto omega_at = [&](double eps) {
      if (s <= 0.0) return 1.0;  // the band is open: no strength left
      if (eps <= s) return 0.0;
      return std::min(1.0, (eps - s) / ((1.0 - r) * eps));
    };
    double& omega = state.omega;
    // Where the band's strength fell below this particle's stress: omega
    // jumps, dissipating Y d omega = (1/2) E eps^2 d omega at fixed strain.
    auto jump_to = [&](double eps, double to) {
      if (to > omega) state.dissipated += 0.5 * E * eps * eps * (to - omega), omega = to;
    };
    const double start = past_onset ? eps_a : eps_i;  // where softening may start in this step
    if (r >= 1.0) {
      // Its own width c alone is beyond the snap-back length w_c / eps_i (a
      // particle with few neighbours, e.g. at a free end): brittle, it
      // breaks where its strain passes the band's strength.
      if (eps_b > s) jump_to(std::max(s, std::min(start, eps_b)), 1.0);
    } else if (eps_b > start) {
      jump_to(start, omega_at(start));
      if (s > 0.0 && omega < 1.0) {
        // Along the law from where it reaches the current omega to eps_b
        // (or to failure at s / r).
        const double from = std::max(start, s / (1.0 - (1.0 - r) * omega)), to = std::min(eps_b, s / r);
        if (to > from) state.dissipated += 0.5 * E * s * (to - from) / (1.0 - r);
        omega = std::max(omega, omega_at(eps_b));
      }
    } else {
      jump_to(eps_b, omega_at(eps_b));
    }
  }

  // Recoverable (secant) energy per unit volume, (1 - omega) eps : C : eps / 2
  // = sigma : eps / 2 with the state's total strain; what damage took is in
  // State::dissipated.
  double stored_energy(const State& state, const Voigt& sigma, const Voigt&) const {
    return 0.5 * double_contraction(sigma, state.eps);
  }
  // Energy dissipated per unit volume by damage so far (J/m^3).
  double dissipated_energy(const State& state) const { return state.dissipated; }
};

}  // namespace flowmpm
