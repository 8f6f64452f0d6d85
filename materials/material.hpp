// The registry of constitutive models. A model is a value type with
// Parameters, a State of internal variables and a pure, const update
// (DESIGN.md "Materials"); the engine dispatches on this variant once per
// particle batch, never per particle. Adding a model means adding it to the
// variant and to read_material() in material.cpp, nothing in engine/ or tasks/.
#pragma once
#include <string>
#include <variant>
#include <vector>

#include "materials/linear_elastic.hpp"

namespace flowmpm {

class TableReader;

using Material = std::variant<LinearElastic>;

// The internal variables of every particle of a batch, one array per model.
template <class Model>
using StateArray = std::vector<typename Model::State>;

struct NamedMaterial {
  std::string name;
  Material model;
};

// Reads [materials.NAME]: `type` picks the model, which reads the rest.
Material read_material(TableReader& table);

// The names of all registered models, for messages.
std::string material_type_names();

inline double density(const Material& m) {
  return std::visit([](const auto& model) { return model.density(); }, m);
}
inline double wave_speed(const Material& m) {
  return std::visit([](const auto& model) { return model.wave_speed(); }, m);
}
inline const char* type_name(const Material& m) {
  return std::visit([](const auto& model) { return std::decay_t<decltype(model)>::type_name; }, m);
}

}  // namespace flowmpm
