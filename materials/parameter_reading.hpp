// Reading helpers shared by the models' parameter readers.
#pragma once
#include <tuple>

namespace flowmpm {

class ParameterTable;

// density (kg/m^3), youngs_modulus (Pa) and poisson_ratio, validated: the
// isotropic elastic constants that several models start from.
std::tuple<double, double, double> read_isotropic_elasticity(ParameterTable& t);

}  // namespace flowmpm
