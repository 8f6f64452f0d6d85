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
// path. Crack band: given the fracture energy G_c (J/m^2) instead of eps_f,
// each particle takes eps_f = 2 G_c / (E eps_i h), h the cell size
// (ParticleInit::cell_length): the strain localises in a band one cell wide
// (the particles of a cell share their velocity gradient), so the band that
// fails dissipates G_c per unit crack area whatever the resolution and the
// number of particles per cell. The band must soften,
// eps_f > eps_i, i.e. h < 2 G_c / (E eps_i^2); larger particles are an error.
// The total strain is kept in the state and turns with the material
// (rotation.hpp); the reduced states: plane strain eps_zz = 0; plane stress
// eps_zz = -lambda / (lambda + 2 mu) (eps_xx + eps_yy); uniaxial stress
// eps_yy = eps_zz = -nu eps_xx (sigma_yy = sigma_zz = 0 for any omega < 1).
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

#include "core/voigt.hpp"
#include "materials/material_input.hpp"
#include "materials/rotation.hpp"
#include "materials/lame.hpp"
#include "materials/state_variable.hpp"
#include "materials/stress_state.hpp"

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
  };
  struct State {
    Voigt eps{};            // total strain
    double kappa = 0.0;     // largest equivalent strain reached
    double eps_f = 0.0;     // failure strain of this particle
    double dissipated = 0.0;  // energy dissipated per unit volume (J/m^3)
  };

  Parameters parameters;
  double lambda = 0.0, mu = 0.0;

  explicit StrainSoftening(const Parameters& p)
      : parameters(p),
        lambda(lame_lambda(p.youngs_modulus, p.poisson_ratio)),
        mu(lame_mu(p.youngs_modulus, p.poisson_ratio)) {}

  // Reads and validates [materials.NAME] (type = "strain_softening").
  static StrainSoftening read(ParameterTable& table);

  // Damage omega (-) and the energy dissipated per unit volume (J/m^3).
  static constexpr std::array<StateVariable, 2> state_variables{{{"damage", "-"}, {"dissipated_energy", "J/m^3"}}};
  void state_values(const State& s, double* out) const {
    out[0] = damage(s.kappa, s.eps_f);
    out[1] = s.dissipated;
  }

  // eps_f in a band of width init.cell_length; throws CaseError if the crack
  // band would snap back (eps_f <= eps_i).
  State initial_state(const ParticleInit& init) const;

  double density() const { return parameters.density; }
  // P wave of the undamaged material, sqrt((lambda + 2 mu) / rho) (m/s).
  double wave_speed() const { return std::sqrt((lambda + 2.0 * mu) / parameters.density); }

  // omega(kappa) of eq. 5.99.
  double damage(double kappa, double eps_f) const {
    const double eps_i = parameters.initiation_strain;
    if (kappa <= eps_i) return 0.0;
    if (kappa >= eps_f) return 1.0;
    return eps_f * (kappa - eps_i) / (kappa * (eps_f - eps_i));
  }

  template <StressState Kind>
  void update(State& state, Voigt& sigma, Voigt& deps, const MaterialInput& in) const {
    const double E = parameters.youngs_modulus, nu = parameters.poisson_ratio;
    Voigt& e = state.eps;
    double eps_eq = 0.0;
    if constexpr (Kind == StressState::uniaxial_stress) {
      e[0] += deps[0];
      deps[1] = -nu * e[0] - e[1];
      deps[2] = -nu * e[0] - e[2];
      e[1] = e[2] = -nu * e[0];
      eps_eq = std::abs(e[0]);
    } else {
      rotate_with_spin(e, in.dL);
      if constexpr (Kind == StressState::plane_stress) {
        const double e_zz = -lambda / (lambda + 2.0 * mu) * (e[0] + deps[0] + e[1] + deps[1]);
        deps[2] = e_zz - e[2];
      }
      for (int i = 0; i < 6; ++i) e[i] += deps[i];
      const double tr = e[0] + e[1] + e[2];
      eps_eq = std::sqrt((lambda * tr * tr + 2.0 * mu * double_contraction(e, e)) / E);
    }
    const double eps_i = parameters.initiation_strain, eps_f = state.eps_f;
    if (eps_eq > state.kappa) {
      const double from = std::max(state.kappa, eps_i), to = std::min(eps_eq, eps_f);
      if (to > from) state.dissipated += 0.5 * E * eps_i * eps_f * (to - from) / (eps_f - eps_i);
      state.kappa = eps_eq;
    }
    const double intact = 1.0 - damage(state.kappa, eps_f);
    if constexpr (Kind == StressState::uniaxial_stress) {
      sigma = {intact * E * e[0], 0.0, 0.0, 0.0, 0.0, 0.0};
    } else {
      const double tr = e[0] + e[1] + e[2];
      for (int i = 0; i < 3; ++i) sigma[i] = intact * (lambda * tr + 2.0 * mu * e[i]);
      for (int i = 3; i < 6; ++i) sigma[i] = intact * 2.0 * mu * e[i];
      if constexpr (Kind == StressState::plane_stress) sigma[2] = 0.0;  // round-off only
    }
  }

  // Recoverable (secant) energy per unit volume, (1 - omega) eps : C : eps / 2
  // = sigma : eps / 2 with the state's total strain; what damage took is in
  // State::dissipated.
  double stored_energy(const State& state, const Voigt& sigma, const Voigt&) const {
    return 0.5 * double_contraction(sigma, state.eps);
  }
};

}  // namespace flowmpm
