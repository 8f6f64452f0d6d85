// Isotropic linear elasticity, small strain ([Sulsky 1994]):
//   d sigma = lambda tr(d eps) I + 2 mu d eps,
//   lambda = E nu / ((1 + nu)(1 - 2 nu)), mu = E / (2 (1 + nu)).
// Rate form, so that it composes with return mapping later.
#pragma once
#include <cmath>

#include "core/voigt.hpp"
#include "materials/material_input.hpp"
#include "materials/lame.hpp"
#include "materials/stress_state.hpp"

namespace flowmpm {

class ParameterTable;

struct LinearElastic {
  static constexpr const char* type_name = "linear_elastic";

  struct Parameters {
    double density = 0.0;          // kg/m^3
    double youngs_modulus = 0.0;   // Pa
    double poisson_ratio = 0.0;    // -
  };
  struct State {};  // no internal variables
  State initial_state(const ParticleInit&) const { return {}; }

  Parameters parameters;
  double lambda = 0.0, mu = 0.0;

  explicit LinearElastic(const Parameters& p)
      : parameters(p),
        lambda(lame_lambda(p.youngs_modulus, p.poisson_ratio)),
        mu(lame_mu(p.youngs_modulus, p.poisson_ratio)) {}

  // Reads and validates [materials.NAME] (type = "linear_elastic").
  static LinearElastic read(ParameterTable& table);

  double density() const { return parameters.density; }

  // The fastest wave the model carries (P wave, constrained modulus), m/s.
  double wave_speed() const { return std::sqrt((lambda + 2.0 * mu) / parameters.density); }

  // Stress update for the strain increment `deps`. For reduced stress
  // states the out-of-plane components of `deps` are set here (uniaxial
  // stress: d eps_yy = d eps_zz = -nu d eps_xx; plane stress:
  // d eps_zz = -lambda / (lambda + 2 mu) (d eps_xx + d eps_yy)).
  template <StressState Kind>
  void update(State&, Voigt& sigma, Voigt& deps, const MaterialInput&) const {
    if constexpr (Kind == StressState::uniaxial_stress) {
      deps[1] = deps[2] = -parameters.poisson_ratio * deps[0];
      sigma[0] += parameters.youngs_modulus * deps[0];
      return;
    }
    if constexpr (Kind == StressState::plane_stress) {
      // d sigma_zz = lambda (deps_xx + deps_yy + deps_zz) + 2 mu deps_zz = 0
      deps[2] = -lambda / (lambda + 2.0 * mu) * (deps[0] + deps[1]);
    }
    // plane strain: deps_zz = 0 as given, so sigma_zz = lambda (deps_xx + deps_yy)
    const double trace = deps[0] + deps[1] + deps[2];
    for (int i = 0; i < 3; ++i) sigma[i] += lambda * trace + 2.0 * mu * deps[i];
    for (int i = 3; i < 6; ++i) sigma[i] += 2.0 * mu * deps[i];
  }

  // Strain energy per unit volume, sigma : eps / 2 (all of the strain is elastic).
  double stored_energy(const State&, const Voigt& sigma, const Voigt& eps) const {
    return 0.5 * double_contraction(sigma, eps);
  }
};

}  // namespace flowmpm
