// Lamé constants of isotropic linear elasticity from Young's modulus E and
// Poisson's ratio nu:
//   lambda = E nu / ((1 + nu)(1 - 2 nu)),  mu = G = E / (2 (1 + nu)).
#pragma once

namespace flowmpm {

inline double lame_lambda(double E, double nu) { return E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu)); }
inline double lame_mu(double E, double nu) { return E / (2.0 * (1.0 + nu)); }

}  // namespace flowmpm
