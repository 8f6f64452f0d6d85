// Isotropic linear elasticity, small strain ([Sulsky 1994]):
//   d sigma = lambda tr(d eps_m) I + 2 mu d eps_m,
//   lambda = E nu / ((1 + nu)(1 - 2 nu)), mu = E / (2 (1 + nu)),
// with d eps_m = d eps - (alpha d(T - T_ref) + beta dc) I the mechanical
// part of the strain increment: the isotropic expansion takes no stress
// (materials/expansion.hpp). Rate form, objective: before the increment is
// added the stress is turned with the material, sigma <- dR sigma dR^T, dR
// the Cayley increment of the spin skew(dL) ([Hughes 1980],
// materials/rotation.hpp; a Jaumann-type rate, the same as von_mises'), so
// a rigid rotation turns the stress and does not load it. 1D has no spin.
#pragma once
#include <cmath>

#include "core/voigt.hpp"
#include "materials/expansion.hpp"
#include "materials/lame.hpp"
#include "materials/material_input.hpp"
#include "materials/rotation.hpp"
#include "materials/stress_state.hpp"
#include "materials/transport_properties.hpp"

namespace flowmpm {

class ParameterTable;

struct LinearElastic {
  static constexpr const char* type_name = "linear_elastic";

  struct Parameters {
    double density = 0.0;          // kg/m^3
    double youngs_modulus = 0.0;   // Pa
    double poisson_ratio = 0.0;    // -
    TransportProperties transport;  // heat capacity, conductivity, diffusivity (scalars)
    Expansion expansion;            // isotropic alpha, beta and what drives them
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
  const TransportProperties& transport() const { return parameters.transport; }

  // The fastest wave the model carries (P wave, constrained modulus), m/s.
  double wave_speed() const { return std::sqrt((lambda + 2.0 * mu) / parameters.density); }

  // Stress update for the strain increment `deps`. For reduced stress
  // states the out-of-plane components of `deps` are set here (uniaxial
  // stress: d eps_yy = d eps_zz = th - nu (d eps_xx - th); plane stress:
  // d eps_zz = th - lambda / (lambda + 2 mu) (d eps_xx + d eps_yy - 2 th)),
  // th the expansion increment.
  // Always inlined: out of line, its call boundary cost the particle loop
  // more than the rotation itself (docs/performance.md).
  template <StressState Kind>
  [[gnu::always_inline]] void update(State&, Voigt& sigma, Voigt& deps, const MaterialInput& in) const {
    rotate_with_spin<Kind>(sigma, in.dL);
    if (!parameters.expansion.any()) return elastic_update<Kind>(sigma, deps);
    // The update sees the mechanical increment d eps - th I; the total is restored after.
    const double th = parameters.expansion.isotropic_step(in);
    for (int i = 0; i < 3; ++i) deps[i] -= th;
    elastic_update<Kind>(sigma, deps);
    for (int i = 0; i < 3; ++i) deps[i] += th;
  }

  // Work done on the body by the isotropic expansion over one increment per
  // unit volume (J/m^3), -tr(sigma) th, for the energy balance.
  double expansion_work(const State&, const Voigt& sigma, const MaterialInput& in) const {
    return parameters.expansion.isotropic_work(sigma, in);
  }
  bool expands() const { return parameters.expansion.any(); }

  // Strain energy per unit volume from the stress, sigma : C^-1 : sigma / 2
  // = p^2 / (2 K) + s : s / (4 mu): the elastic part of the strain only
  // (not an expansion's), and a body that starts stressed
  // (initial_stress) holds its energy from t = 0 (sigma : eps / 2 counted
  // none, and the blow-up guard stopped a block on a slope whose initial
  // stress set it moving).
  double stored_energy(const State&, const Voigt& sigma, const Voigt&) const {
    const double p = (sigma[0] + sigma[1] + sigma[2]) / 3.0, K = lambda + 2.0 * mu / 3.0;
    Voigt s = sigma;
    for (int i = 0; i < 3; ++i) s[i] -= p;
    return p * p / (2.0 * K) + double_contraction(s, s) / (4.0 * mu);
  }

 private:
  // The elastic update for a mechanical strain increment.
  template <StressState Kind>
  [[gnu::always_inline]] void elastic_update(Voigt& sigma, Voigt& deps) const {
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
};

}  // namespace flowmpm
