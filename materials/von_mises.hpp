// Von Mises (J2) plasticity with isotropic hardening and Wilkins' radial
// return ([Wilkins 1964]; [Simo 1998]), small strain,
// isotropic linear elasticity (lambda, mu = G, K = lambda + 2 mu / 3).
//   Yield: q = sqrt(3/2 s:s) <= sigma_Y(eps_p), s the stress deviator.
//   Hardening: linear   sigma_Y = sigma_0 + H eps_p,
//              power    sigma_Y = sigma_0 (1 + eps_p / eps_0)^n  (0 < n <= 1).
// 3D and plane strain (eps_zz = 0): elastic trial sigma* = sigma + C d eps;
// if q* > sigma_Y, the plastic increment d eps_p solves
//   q* - 3 G d eps_p = sigma_Y(eps_p + d eps_p)
// (closed form d eps_p = (q* - sigma_Y) / (3 G + H) for linear hardening,
// Newton otherwise) and the deviator is scaled radially, s = M s* with
// M = 1 - 3 G d eps_p / q*, the pressure unchanged.
// Plane stress (sigma_zz = 0, eps_zz free): Wilkins' return ([Psakhie 2013],
// Appendix C). The trial is plane-stress elastic (sigma*_zz = 0); an extra
// out-of-plane strain delta and the radial factor M satisfy together
//   sigma_zz = 0:  delta = s*_zz (1 - M) / (K + 4 G M / 3),
//   yield:         F(M) = M q'(M) - sigma_Y(eps_p + (1 - M) q'(M) / (3 G)) = 0,
// q'(M) the equivalent stress of the trial corrected by delta,
// q'^2 = 3/2 s*:s* + 6 G delta s*_zz + 4 G^2 delta^2 (the quartic of
// [Psakhie 2013] when squared out). F is solved by Newton from M_0 = sigma_Y / q*, kept
// inside a bracket [lo, hi] of (0, 1] with F(lo) < 0 < F(hi) (bisection when
// a step leaves it), to |F| <= newton_tolerance q*; not converging in
// newton_iterations is a std::runtime_error. This equals the 3D radial return
// for the strain increment with d eps_zz + delta (tests/test_von_mises.cpp).
// Uniaxial stress (1D): sigma* = sigma + E d eps, d eps_p = (|sigma*| -
// sigma_Y) / (E + H) (Newton for the power law), and the lateral strains
// d eps_yy = d eps_zz = -nu d eps_e - d eps_p / 2 (plastic incompressibility).
// The stress turns with the material (rotation.hpp, Hughes-Winget), so a
// rigid rotation rotates it and does not load it. The isotropic expansion
// increment th = alpha d(T - T_ref) + beta dc takes no stress: every
// return above sees the mechanical increment d eps - th I
// (materials/expansion.hpp).
#pragma once
#include <array>
#include <cmath>

#include "core/voigt.hpp"
#include "materials/expansion.hpp"
#include "materials/lame.hpp"
#include "materials/material_input.hpp"
#include "materials/rotation.hpp"
#include "materials/state_variable.hpp"
#include "materials/stress_state.hpp"
#include "materials/transport_properties.hpp"

namespace flowmpm {

class ParameterTable;

struct VonMises {
  static constexpr const char* type_name = "von_mises";
  static constexpr double newton_tolerance = 1e-12;  // |residual| / trial q
  static constexpr int newton_iterations = 50;

  enum class Hardening { linear, power };
  struct Parameters {
    double density = 0.0;          // kg/m^3
    double youngs_modulus = 0.0;   // Pa
    double poisson_ratio = 0.0;    // -
    double yield_stress = 0.0;     // sigma_0 (Pa)
    Hardening hardening = Hardening::linear;
    double hardening_modulus = 0.0;   // linear: H = d sigma_Y / d eps_p (Pa); 0: perfectly plastic
    double reference_strain = 0.0;    // power: eps_0 (-)
    double hardening_exponent = 0.0;  // power: n (-)
    TransportProperties transport;    // heat capacity, conductivity, diffusivity (scalars)
    Expansion expansion;              // isotropic alpha, beta and what drives them
  };
  struct State {
    double eps_p = 0.0;  // equivalent plastic strain, integral of sqrt(2/3 d eps_p : d eps_p)
  };
  State initial_state(const ParticleInit&) const { return {}; }

  static constexpr std::array<StateVariable, 1> state_variables{{{"plastic_strain", "-"}}};
  void state_values(const State& s, double* out) const { out[0] = s.eps_p; }

  Parameters parameters;
  double lambda = 0.0, mu = 0.0, K = 0.0;

  explicit VonMises(const Parameters& p)
      : parameters(p),
        lambda(lame_lambda(p.youngs_modulus, p.poisson_ratio)),
        mu(lame_mu(p.youngs_modulus, p.poisson_ratio)),
        K(lambda + 2.0 * mu / 3.0) {}

  // Reads and validates [materials.NAME] (type = "von_mises").
  static VonMises read(ParameterTable& table);

  double density() const { return parameters.density; }
  const TransportProperties& transport() const { return parameters.transport; }
  // P wave of the elastic material, sqrt((lambda + 2 mu) / rho) (m/s).
  double wave_speed() const { return std::sqrt((lambda + 2.0 * mu) / parameters.density); }

  double yield_stress(double eps_p) const {
    const Parameters& p = parameters;
    if (p.hardening == Hardening::linear) return p.yield_stress + p.hardening_modulus * eps_p;
    return p.yield_stress * std::pow(1.0 + eps_p / p.reference_strain, p.hardening_exponent);
  }
  double hardening_slope(double eps_p) const {
    const Parameters& p = parameters;
    if (p.hardening == Hardening::linear) return p.hardening_modulus;
    return p.yield_stress * p.hardening_exponent / p.reference_strain *
           std::pow(1.0 + eps_p / p.reference_strain, p.hardening_exponent - 1.0);
  }

  // Throws the std::runtime_error of a Newton iteration that did not converge.
  [[noreturn]] static void newton_failure(const char* what, double q_trial, double residual);

  // d eps_p solving q* - k d eps_p = sigma_Y(eps_p + d eps_p), k = 3 G (3D) or
  // E (1D), for a trial q* above sigma_Y(eps_p). The Newton iteration of the
  // power law starts at 0 and rises monotonically (the residual is convex).
  double plastic_increment(double q_trial, double k, double eps_p) const {
    if (parameters.hardening == Hardening::linear) {
      return (q_trial - yield_stress(eps_p)) / (k + parameters.hardening_modulus);
    }
    double d = 0.0;
    for (int it = 0; it < newton_iterations; ++it) {
      const double g = q_trial - k * d - yield_stress(eps_p + d);
      if (std::abs(g) <= newton_tolerance * q_trial) return d;
      d += g / (k + hardening_slope(eps_p + d));
    }
    newton_failure("the power-law return", q_trial, std::abs(q_trial - k * d - yield_stress(eps_p + d)));
  }

  // Wilkins' plane-stress factor M and extra out-of-plane strain delta for
  // the trial deviator s* (s*_zz = -p*, since sigma*_zz = 0).
  struct PlaneStressReturn {
    double M, delta, d_eps_p;
  };
  PlaneStressReturn plane_stress_return(const Voigt& s, double q_trial, double eps_p) const {
    const double s2 = double_contraction(s, s), szz = s[2];
    const double a = K + 4.0 * mu / 3.0;
    double lo = 0.0, hi = 1.0, M = yield_stress(eps_p) / q_trial, F = 0.0;
    for (int it = 0; it < newton_iterations; ++it) {
      const double den = K + 4.0 * mu / 3.0 * M;
      const double delta = szz * (1.0 - M) / den;
      const double d_delta = -szz * a / (den * den);
      const double q = std::sqrt(1.5 * s2 + 6.0 * mu * delta * szz + 4.0 * mu * mu * delta * delta);
      const double dq = (6.0 * mu * szz + 8.0 * mu * mu * delta) * d_delta / (2.0 * q);
      const double dep = (1.0 - M) * q / (3.0 * mu);
      const double d_dep = (-q + (1.0 - M) * dq) / (3.0 * mu);
      F = M * q - yield_stress(eps_p + dep);
      if (std::abs(F) <= newton_tolerance * q_trial) return {M, delta, dep};
      (F > 0.0 ? hi : lo) = M;
      const double dF = q + M * dq - hardening_slope(eps_p + dep) * d_dep;
      const double next = M - F / dF;
      M = next > lo && next < hi ? next : 0.5 * (lo + hi);
    }
    newton_failure("the plane-stress return (Newton on Wilkins' factor M)", q_trial, std::abs(F));
  }

  template <StressState Kind>
  void update(State& state, Voigt& sigma, Voigt& deps, const MaterialInput& in) const {
    parameters.expansion.with_mechanical_increment(deps, in, [&] { mechanical_update<Kind>(state, sigma, deps, in); });
  }

  // Elastic strain energy per unit volume (lame.hpp; the plastic work is dissipated).
  double stored_energy(const State&, const Voigt& sigma, const Voigt&) const {
    return isotropic_stored_energy(sigma, K, mu);
  }

  // Work done on the body by the isotropic expansion over one increment per
  // unit volume (J/m^3), -tr(sigma) th, for the energy balance.
  double expansion_work(const State&, const Voigt& sigma, const MaterialInput& in) const {
    return parameters.expansion.isotropic_work(sigma, in);
  }
  bool expands() const { return parameters.expansion.any(); }

  // Plastic work per unit volume (J/m^3), the integral of sigma_Y(eps_p)
  // d eps_p (the radial return keeps the stress on the yield surface):
  // linear sigma_0 eps_p + H eps_p^2 / 2; power sigma_0 eps_0 / (n + 1)
  // ((1 + eps_p / eps_0)^(n + 1) - 1).
  double dissipated_energy(const State& state) const {
    const Parameters& p = parameters;
    if (p.hardening == Hardening::linear) {
      return p.yield_stress * state.eps_p + 0.5 * p.hardening_modulus * state.eps_p * state.eps_p;
    }
    const double n1 = p.hardening_exponent + 1.0;
    return p.yield_stress * p.reference_strain / n1 * (std::pow(1.0 + state.eps_p / p.reference_strain, n1) - 1.0);
  }

 private:
  // The update for a mechanical strain increment: elastic trial and return.
  template <StressState Kind>
  [[gnu::always_inline]] void mechanical_update(State& state, Voigt& sigma, Voigt& deps,
                                                const MaterialInput& in) const {
    const double E = parameters.youngs_modulus, nu = parameters.poisson_ratio;
    if constexpr (Kind == StressState::uniaxial_stress) {
      const double trial = sigma[0] + E * deps[0], q = std::abs(trial);
      const double sign = trial < 0.0 ? -1.0 : 1.0;
      const double dep = q > yield_stress(state.eps_p) ? plastic_increment(q, E, state.eps_p) : 0.0;
      sigma[0] = trial - sign * E * dep;
      deps[1] = deps[2] = -nu * (deps[0] - sign * dep) - 0.5 * sign * dep;
      state.eps_p += dep;
    } else {
      rotate_with_spin<Kind>(sigma, in.dL);
      if constexpr (Kind == StressState::plane_stress) {
        deps[2] = -lambda / (lambda + 2.0 * mu) * (deps[0] + deps[1]);
      }
      const double tr = deps[0] + deps[1] + deps[2];
      for (int i = 0; i < 3; ++i) sigma[i] += lambda * tr + 2.0 * mu * deps[i];
      for (int i = 3; i < 6; ++i) sigma[i] += 2.0 * mu * deps[i];
      if constexpr (Kind == StressState::plane_stress) sigma[2] = 0.0;  // round-off only
      const double p = (sigma[0] + sigma[1] + sigma[2]) / 3.0;
      Voigt s = sigma;
      for (int i = 0; i < 3; ++i) s[i] -= p;
      const double q2 = 1.5 * double_contraction(s, s), y = yield_stress(state.eps_p);
      if (q2 <= y * y) return;
      const double q = std::sqrt(q2);
      if constexpr (Kind == StressState::plane_stress) {
        const PlaneStressReturn r = plane_stress_return(s, q, state.eps_p);
        // s' = s* + 2 G delta (-1/3, -1/3, 2/3), p' = p* + K delta, sigma = p' I + M s'.
        const double p1 = p + K * r.delta, g = 2.0 * mu * r.delta / 3.0;
        sigma[0] = p1 + r.M * (s[0] - g);
        sigma[1] = p1 + r.M * (s[1] - g);
        sigma[2] = 0.0;  // p1 + M (s_zz + 2 g) = 0 by the choice of delta
        for (int i = 3; i < 6; ++i) sigma[i] = r.M * s[i];
        deps[2] += r.delta;
        state.eps_p += r.d_eps_p;
      } else {
        const double dep = plastic_increment(q, 3.0 * mu, state.eps_p);
        const double M = 1.0 - 3.0 * mu * dep / q;
        for (int i = 0; i < 3; ++i) sigma[i] = p + M * s[i];
        for (int i = 3; i < 6; ++i) sigma[i] = M * s[i];
        state.eps_p += dep;
      }
    }
  }
};

}  // namespace flowmpm
