// Drucker-Prager perfect plasticity with a tension cut-off on the mean
// stress, small strain, isotropic elasticity (materials/frictional.hpp for
// what it shares with mohr_coulomb). Tension positive; p = tr(sigma) / 3,
// s the deviator, J = sqrt(J2) = sqrt(s : s / 2).
//   Yield ([de Souza Neto 2008], section 6.4): F = J + eta p - xi c <= 0;
//   flow potential G = J + eta_bar p (non-associated unless eta_bar = eta);
//   cut-off: p <= T, associated (n = I / 3), T in [0, xi c / eta].
// The cone matches Mohr-Coulomb's phi, c and psi by `fit`:
//   compression (outer cone, through the triaxial-compression edges):
//     eta = 6 sin phi / (sqrt 3 (3 - sin phi)), xi = 6 cos phi / (sqrt 3 (3 - sin phi));
//   extension (through the triaxial-extension edges): the same with 3 + sin phi;
//   inscribed (the cone inside the pyramid, touching its faces):
//     eta = 3 sin phi / sqrt(9 + 3 sin^2 phi), xi = 3 cos phi / sqrt(9 + 3 sin^2 phi)
//     (= 3 tan phi / sqrt(9 + 12 tan^2 phi) and 3 / sqrt(9 + 12 tan^2 phi));
//   eta_bar the same function of psi in each of the three;
//   plane_strain (the same limit load as Mohr-Coulomb in plane strain, for
//     any psi <= phi): eta_bar = 3 sin psi / sqrt(9 + 3 sin^2 psi), and
//     eta = sqrt 3 sin phi sqrt(3 + sin^2 psi) / (3 + sin phi sin psi),
//     xi = eta cot phi. At collapse in plane strain d eps_p,zz = 0, i.e.
//     s_zz = -2 eta_bar J / 3; with Mohr's circle of the in-plane stresses,
//     centre m and radius t, that gives J = t / sqrt(1 - eta_bar^2 / 3), and
//     F = 0 becomes t + m sin phi = c cos phi, Mohr-Coulomb's plane-strain
//     criterion, for the eta and xi above; then
//     d eps_p,v / (d eps_p,1 - d eps_p,3) = eta_bar / sqrt(1 - eta_bar^2 / 3)
//     = sin psi. With psi = phi it is the inscribed cone
//     ([de Souza Neto 2008], section 6.4).
//   Every fit has its apex at xi c / eta = c cot phi, Mohr-Coulomb's.
// Return ([de Souza Neto 2008], chapter 8, perfectly plastic), from the
// elastic trial (p*, s*, J*):
//   cone: dgamma = F(p*, J*) / (G + K eta eta_bar), J = J* - G dgamma,
//         p = p* - K eta_bar dgamma; taken if J >= 0 and p <= T;
//   cut-off: p = T, s = s*; taken if F(T, J*) <= 0;
//   otherwise the corner p = T, J = xi c - eta T (with T = c cot phi the
//   apex, J = 0: the cone's apex return).
// Then sigma = p I + (J / J*) s*.
#pragma once
#include <array>
#include <cmath>

#include "core/voigt.hpp"
#include "materials/frictional.hpp"

namespace flowmpm {

class ParameterTable;

enum class DruckerPragerFit { plane_strain, compression, extension, inscribed };
struct DruckerPragerParameters : FrictionalParameters {
  DruckerPragerFit fit = DruckerPragerFit::plane_strain;
};

struct DruckerPrager : FrictionalModel<DruckerPragerParameters> {
  static constexpr const char* type_name = "drucker_prager";

  using Fit = DruckerPragerFit;
  using Parameters = DruckerPragerParameters;
  // Its own type (the engine keeps one state array per model): frictional.hpp.
  struct State : FrictionalState {};
  State initial_state(const ParticleInit&) const { return {}; }


  // eta, xi and eta_bar of a fit (header).
  struct Cone {
    double eta, xi, eta_bar;
  };
  static Cone cone(Fit fit, double phi, double psi);

  Cone cone_ = {};
  double strength = 0.0;  // xi c (Pa)

  explicit DruckerPrager(const Parameters& p)
      : FrictionalModel(p),
        cone_(cone(p.fit, p.friction_angle, p.dilation_angle)),
        strength(cone_.xi * p.cohesion) {}

  // Reads and validates [materials.NAME] (type = "drucker_prager").
  static DruckerPrager read(ParameterTable& table);


  template <StressState Kind>
  void update(State& state, Voigt& sigma, Voigt& deps, const MaterialInput& in) const {
    if constexpr (!supports(Kind)) {
      unsupported(Kind);
    } else {
      parameters.expansion.with_mechanical_increment(deps, in, [&] {
        elastic_trial<Kind>(sigma, deps, in.dL, lambda, mu);
        const double p = (sigma[0] + sigma[1] + sigma[2]) / 3.0;
        const double J = std::sqrt(deviatoric_j2(sigma, p));
        if (J + cone_.eta * p <= strength && p <= parameters.tension_cutoff) return;
        Voigt s = sigma;
        for (int i = 0; i < 3; ++i) s[i] -= p;
        plastic_return<Kind>(state, sigma, s, p, J);
      });
    }
  }

  // Thrown if the engine ever updates a stress state the reader refused.
  [[noreturn]] static void unsupported(StressState kind);


 private:
  // The return (header) of the trial sigma = p* I + s*, J* = J.
  template <StressState Kind>
  [[gnu::noinline]] void plastic_return(State& state, Voigt& sigma, const Voigt& s_trial, double p_trial,
                                        double J_trial) const {
    const double T = parameters.tension_cutoff, eta = cone_.eta, eta_bar = cone_.eta_bar;
    const double F = J_trial + eta * p_trial - strength;
    double p = T, J = strength - eta * T;  // the corner
    const double dgamma = F / (mu + K * eta * eta_bar);
    if (F > 0.0 && J_trial - mu * dgamma >= 0.0 && p_trial - K * eta_bar * dgamma <= T) {
      p = p_trial - K * eta_bar * dgamma, J = J_trial - mu * dgamma;
    } else if (J_trial + eta * T <= strength) {
      J = J_trial;
    }
    const double scale = J_trial > 0.0 ? J / J_trial : 0.0;
    for (int i = 0; i < 3; ++i) sigma[i] = p + scale * s_trial[i];
    for (int i = 3; i < 6; ++i) sigma[i] = scale * s_trial[i];
    // The principal stresses before and after, for the plastic strain.
    const PrincipalAxes<Kind> deviator(s_trial);
    std::array<double, 3> trial{}, returned{};
    for (int i = 0; i < 3; ++i) {
      trial[i] = p_trial + deviator.value[i];
      returned[i] = p + scale * deviator.value[i];
    }
    record_plastic_strain(state, trial, returned, parameters.youngs_modulus, parameters.poisson_ratio);
  }
};

}  // namespace flowmpm
