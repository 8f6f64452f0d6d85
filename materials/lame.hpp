// Lamé constants of isotropic linear elasticity from Young's modulus E and
// Poisson's ratio nu:
//   lambda = E nu / ((1 + nu)(1 - 2 nu)),  mu = G = E / (2 (1 + nu)).
#pragma once
#include "core/voigt.hpp"

namespace flowmpm {

inline double lame_lambda(double E, double nu) { return E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu)); }
inline double lame_mu(double E, double nu) { return E / (2.0 * (1.0 + nu)); }

// Elastic strain energy per unit volume of a stress in an isotropic
// material, sigma : C^-1 : sigma / 2 = p^2 / (2 K) + s : s / (4 G), p the
// mean stress and s the deviator (any stress state: the stress holds the
// elastic strain).
inline double isotropic_stored_energy(const Voigt& sigma, double K, double mu) {
  const double p = (sigma[0] + sigma[1] + sigma[2]) / 3.0;
  Voigt s = sigma;
  for (int i = 0; i < 3; ++i) s[i] -= p;
  return p * p / (2.0 * K) + double_contraction(s, s) / (4.0 * mu);
}

}  // namespace flowmpm
