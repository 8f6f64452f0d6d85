#include "materials/linear_elastic.hpp"

#include "core/parameter_table.hpp"
#include "materials/parameter_reading.hpp"

namespace flowmpm {

LinearElastic LinearElastic::read(ParameterTable& t) {
  Parameters p;
  std::tie(p.density, p.youngs_modulus, p.poisson_ratio) = read_isotropic_elasticity(t);
  p.transport = TransportProperties::read(t, isotropic_axes);
  p.expansion = Expansion::read(t, isotropic_axes, p.transport);
  return LinearElastic(p);
}

}  // namespace flowmpm
