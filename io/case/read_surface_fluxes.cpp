// [[surface_fluxes]]: heat or solvent through a face of a body.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "core/number_text.hpp"
#include "io/case/case_limits.hpp"
#include "io/case/case_reader.hpp"
#include "io/case/case_sections.hpp"

namespace flowmpm {

void read_surface_flux(TableReader t, SystemSpec& c, std::size_t index) {
  SurfaceFluxSpec f;
  f.name = t.string_or("name", "surface_flux" + std::to_string(index));
  const std::string body = t.string("body");
  f.body = -1;
  std::string known;
  for (std::size_t b = 0; b < c.bodies.size(); ++b) {
    if (c.bodies[b].name == body) f.body = static_cast<int>(b);
    known += (known.empty() ? "\"" : ", \"") + c.bodies[b].name + "\"";
  }
  if (f.body < 0) t.fail("body", "the name of a body: " + known);
  std::vector<std::string> faces;
  for (int d = 0; d < c.dimension; ++d)
    for (const char* side : {"-", "+"}) faces.push_back(axis_names[d] + std::string(side));
  const std::string face = t.choice("face", faces);
  f.axis = face[0] - 'x';
  f.side = face[1] == '+' ? 1 : -1;
  if (t.has("heat_flux")) {
    t.require(c.conducts_heat(), "heat_flux", "no heat flux: no material of the scene conducts heat (conductivity)");
    f.heat = t.time_function("heat_flux", "a heat flux into the body in W/m^2");
  }
  if (t.has("solvent_flux")) {
    t.require(c.diffuses_solvent(), "solvent_flux",
              "no solvent flux: no material of the scene diffuses solvent (diffusivity)");
    f.solvent = t.time_function("solvent_flux", "a solvent flux into the body in kg/(m^2 s)");
  }
  if (!f.heat && !f.solvent) t.fail_table("give heat_flux (W/m^2) or solvent_flux (kg/(m^2 s)), or both");
  t.reject_unknown_keys();
  c.surface_fluxes.push_back(f);
}

}  // namespace flowmpm
