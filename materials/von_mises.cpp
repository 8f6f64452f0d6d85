#include "materials/von_mises.hpp"

#include <sstream>
#include <stdexcept>

#include "core/parameter_table.hpp"
#include "materials/parameter_reading.hpp"

namespace flowmpm {

void VonMises::newton_failure(const char* what, double q_trial, double residual) {
  std::ostringstream s;
  s << "von_mises: " << what << " did not converge to |residual| <= " << newton_tolerance
    << " q_trial in " << newton_iterations << " iterations (q_trial = " << q_trial
    << " Pa, |residual| = " << residual << " Pa)";
  throw std::runtime_error(s.str());
}

VonMises VonMises::read(ParameterTable& t) {
  Parameters p;
  std::tie(p.density, p.youngs_modulus, p.poisson_ratio) = read_isotropic_elasticity(t);
  p.yield_stress = t.number("yield_stress");
  t.require(p.yield_stress > 0.0, "yield_stress", "a positive initial yield stress sigma_0 in Pa");
  const std::string hardening = t.choice("hardening", {"linear", "power"});
  if (hardening == "linear") {
    p.hardening = Hardening::linear;
    p.hardening_modulus = t.number("hardening_modulus");
    t.require(p.hardening_modulus >= 0.0, "hardening_modulus",
              "a hardening modulus H = d sigma_Y / d eps_p >= 0 in Pa (0: perfectly plastic)");
    for (const char* key : {"reference_strain", "hardening_exponent"}) {
      if (t.has(key)) t.fail(key, "no power-law parameter with hardening = \"linear\"");
    }
  } else {
    p.hardening = Hardening::power;
    p.reference_strain = t.number("reference_strain");
    t.require(p.reference_strain > 0.0, "reference_strain", "a positive reference strain eps_0");
    p.hardening_exponent = t.number("hardening_exponent");
    t.require(p.hardening_exponent > 0.0 && p.hardening_exponent <= 1.0, "hardening_exponent",
              "a hardening exponent n in (0, 1]");
    if (t.has("hardening_modulus")) t.fail("hardening_modulus", "no hardening_modulus with hardening = \"power\"");
  }
  p.transport = TransportProperties::read(t, isotropic_axes);
  p.expansion = Expansion::read(t, isotropic_axes, p.transport);
  return VonMises(p);
}

}  // namespace flowmpm
