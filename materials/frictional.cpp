#include "materials/frictional.hpp"

#include "core/number_text.hpp"
#include "core/parameter_table.hpp"
#include "materials/parameter_reading.hpp"

namespace flowmpm {

FrictionalParameters read_frictional(ParameterTable& t) {
  FrictionalParameters p;
  std::tie(p.density, p.youngs_modulus, p.poisson_ratio) = read_isotropic_elasticity(t);
  constexpr double radian = std::numbers::pi / 180.0;
  const double phi = t.number("friction_angle");
  t.require(phi > 0.0 && phi < 90.0, "friction_angle", "a friction angle phi in (0, 90) degrees");
  p.friction_angle = phi * radian;
  p.cohesion = t.number_or("cohesion", 0.0);
  t.require(p.cohesion >= 0.0, "cohesion", "a cohesion c >= 0 in Pa");
  const double psi = t.number_or("dilation_angle", 0.0);
  t.require(psi >= 0.0 && psi <= phi, "dilation_angle",
            "a dilation angle psi in [0, phi] = [0, " + readable_text(phi) + "] degrees");
  p.dilation_angle = psi * radian;
  p.tension_cutoff = t.number_or("tension_cutoff", p.apex());
  t.require(p.tension_cutoff >= 0.0 && p.tension_cutoff <= p.apex(), "tension_cutoff",
            "a tension cut-off T in [0, c cot phi] = [0, " + readable_text(p.apex()) +
                "] Pa (c cot phi: the apex of the yield surface)");
  p.transport = TransportProperties::read(t, isotropic_axes);
  p.expansion = Expansion::read(t, isotropic_axes, p.transport);
  return p;
}

}  // namespace flowmpm
