// [materials.NAME]: each model reads its own keys (materials/material.hpp).
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "core/number_text.hpp"
#include "io/case/case_limits.hpp"
#include "io/case/case_reader.hpp"
#include "io/case/case_sections.hpp"

namespace flowmpm {

namespace {

// What a scene that conducts heat or diffuses solvent asks of every
// material (each has read its own keys already): a heat capacity, and no
// uniform temperature change or concentration (the transported field
// drives the expansion).
void check_transport(std::vector<TableReader>& materials, const SystemSpec& c) {
  for (const char* field : {"heat", "solvent"}) {
    const bool heat = std::string_view(field) == "heat";
    if (heat ? !c.conducts_heat() : !c.diffuses_solvent()) continue;
    std::string carrier;
    for (const auto& m : c.materials) {
      const TransportProperties& p = transport(m.model);
      if (carrier.empty() && (heat ? p.conducts() : p.diffuses())) carrier = m.name;
    }
    const std::string why = heat ? "the scene conducts heat (material \"" + carrier + "\" has a conductivity)"
                                 : "the scene diffuses solvent (material \"" + carrier + "\" has a diffusivity)";
    for (std::size_t i = 0; i < materials.size(); ++i) {
      TableReader& m = materials[i];
      if (heat && transport(c.materials[i].model).heat_capacity == 0.0) {
        m.fail("heat_capacity", "the specific heat capacity in J/(kg K): " + why);
      }
      const char* uniform = heat ? "temperature_change" : "concentration";
      if (m.has(uniform)) {
        m.fail(uniform, std::string("no uniform ") + uniform + ": " + why + ", so each particle's own " +
                            (heat ? "temperature" : "concentration") + " drives the expansion");
      }
    }
  }
}

}  // namespace

void read_materials(TableReader& root, const toml::table& document, SystemSpec& c) {
  // Each key of [materials] names a material with its own table.
  TableReader materials = root.table("materials");
  std::vector<TableReader> material_tables;
  for (auto&& [key, value] : *document.get("materials")->as_table()) {
    TableReader m = materials.table(key.str());
    c.materials.push_back({std::string(key.str()), read_material(m)});
    m.reject_unknown_keys();
    material_tables.push_back(std::move(m));
  }
  if (c.materials.empty()) materials.fail_table("define at least one material, e.g. [materials.steel]");
  // A model without an update for the analysis's stress state.
  const StressState state = c.dimension == 1   ? StressState::uniaxial_stress
                            : c.dimension == 3 ? StressState::three_d
                            : c.plane_stress   ? StressState::plane_stress
                            : c.axisymmetric   ? StressState::axisymmetric
                                               : StressState::plane_strain;
  for (std::size_t i = 0; i < c.materials.size(); ++i) {
    if (!supports(c.materials[i].model, state)) {
      material_tables[i].fail("type", std::string("a model with a return in ") + stress_state_name(state) +
                                          ": \"" + type_name(c.materials[i].model) +
                                          "\" has none (3D, plane strain and axisymmetric only; "
                                          "set analysis.stress_state = \"plane_strain\" or use dimension = 3)");
    }
  }
  check_transport(material_tables, c);
}

}  // namespace flowmpm
