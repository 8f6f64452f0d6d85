#include "materials/expansion.hpp"

#include <string>

#include "core/parameter_table.hpp"

namespace flowmpm {

Expansion Expansion::read(ParameterTable& t, const AxisLayout& layout, const TransportProperties& transport) {
  Expansion e;
  struct Driver {
    const char* coefficients;
    const char* driver;
    const char* coefficient_what;
    const char* driver_what;
    bool transported;      // the material conducts heat / diffuses solvent
    const char* property;  // what transports it
  };
  const Driver drivers[2] = {
      {"alpha", "temperature_change", "thermal expansion coefficients in 1/K", "a temperature change in K",
       transport.conducts(), "a conductivity"},
      {"beta", "concentration", "solvent expansion coefficients per unit weight fraction",
       "a solvent concentration (weight fraction)", transport.diffuses(), "a diffusivity"}};
  for (int k = 0; k < 2; ++k) {
    const Driver& d = drivers[k];
    if (!t.has(d.coefficients) && !t.has(d.driver)) continue;
    if (!t.has(d.coefficients)) {
      t.fail(d.coefficients, std::string(d.coefficient_what) + ", " + layout.description + " (" + d.driver +
                                 " is given)");
    }
    const std::array<double, 3> values = read_axis_values(t, d.coefficients, layout);
    (k == 0 ? e.alpha : e.beta) = values;
    (k == 0 ? e.thermal : e.solvent) = true;
    if (d.transported) {
      if (t.has(d.driver)) {
        t.fail(d.driver, std::string("no uniform ") + d.driver + " in a material with " + d.property +
                             ": each particle's own value drives the expansion");
      }
      if (k == 0 && !transport.reference_temperature) {
        t.fail("reference_temperature",
               "the stress-free temperature in K (alpha is given and the temperature is conducted)");
      }
      continue;
    }
    if (!t.has(d.driver)) {
      t.fail(d.driver, std::string(d.driver_what) + " (" + d.coefficients + " is given), or " + d.property +
                           " so that each particle's own value is transported");
    }
    TimeFunction f = t.time_function(d.driver, d.driver_what);
    if (k == 1) {
      for (const auto& [time, c] : f.points) {
        t.require(c >= 0.0 && c <= 1.0, d.driver, "a solvent concentration (weight fraction) in [0, 1]");
      }
    }
    (k == 0 ? e.temperature_change : e.concentration) = std::move(f);
  }
  return e;
}

}  // namespace flowmpm
