#include "materials/parameter_reading.hpp"

#include "core/parameter_table.hpp"

namespace flowmpm {

std::tuple<double, double, double> read_isotropic_elasticity(ParameterTable& t) {
  const double density = t.number("density");
  t.require(density > 0.0, "density", "a positive density in kg/m^3");
  const double E = t.number("youngs_modulus");
  t.require(E > 0.0, "youngs_modulus", "a positive Young's modulus in Pa");
  const double nu = t.number("poisson_ratio");
  t.require(nu > -1.0 && nu < 0.5, "poisson_ratio", "a Poisson ratio in (-1, 0.5)");
  return {density, E, nu};
}

}  // namespace flowmpm
