#include "materials/drucker_prager.hpp"

#include <stdexcept>
#include <string>

#include "core/parameter_table.hpp"

namespace flowmpm {

DruckerPrager::Cone DruckerPrager::cone(Fit fit, double phi, double psi) {
  const double sf = std::sin(phi), sp = std::sin(psi), root3 = std::sqrt(3.0);
  switch (fit) {
    case Fit::compression:
      return {6.0 * sf / (root3 * (3.0 - sf)), 6.0 * std::cos(phi) / (root3 * (3.0 - sf)),
              6.0 * sp / (root3 * (3.0 - sp))};
    case Fit::extension:
      return {6.0 * sf / (root3 * (3.0 + sf)), 6.0 * std::cos(phi) / (root3 * (3.0 + sf)),
              6.0 * sp / (root3 * (3.0 + sp))};
    case Fit::inscribed:
      return {3.0 * sf / std::sqrt(9.0 + 3.0 * sf * sf), 3.0 * std::cos(phi) / std::sqrt(9.0 + 3.0 * sf * sf),
              3.0 * sp / std::sqrt(9.0 + 3.0 * sp * sp)};
    case Fit::plane_strain: {
      const double eta = root3 * sf * std::sqrt(3.0 + sp * sp) / (3.0 + sf * sp);
      return {eta, eta / std::tan(phi), 3.0 * sp / std::sqrt(9.0 + 3.0 * sp * sp)};
    }
  }
  return {};
}

DruckerPrager DruckerPrager::read(ParameterTable& t) {
  Parameters p;
  static_cast<FrictionalParameters&>(p) = read_frictional(t);
  const std::string fit = t.choice("fit", {"plane_strain", "compression", "extension", "inscribed"});
  p.fit = fit == "compression" ? Fit::compression
          : fit == "extension" ? Fit::extension
          : fit == "inscribed" ? Fit::inscribed
                               : Fit::plane_strain;
  return DruckerPrager(p);
}

void DruckerPrager::unsupported(StressState kind) {
  throw std::logic_error(std::string("drucker_prager: no return in ") + stress_state_name(kind) +
                         " (the case reader refuses it)");
}

}  // namespace flowmpm
