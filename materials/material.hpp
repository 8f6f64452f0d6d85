// The registry of constitutive models (DESIGN.md "Materials"). A model is a
// value type with
//   static constexpr const char* type_name;          // the case file's `type`
//   static Model read(TableReader&);                 // parameters, validated
//   struct State;                                    // internal variables per particle
//   State initial_state(const ParticleInit&) const;
//   template <StressState S>
//   void update(State&, Voigt& sigma, Voigt& deps, const MaterialInput&) const;
//   double density() const;                          // kg/m^3
//   double wave_speed() const;                       // fastest wave, m/s (stable dt)
// `update` is pure apart from its outputs: stress, state, and for reduced
// stress states the out-of-plane strain components of deps. The engine
// dispatches on this variant once per particle batch, never per particle.
// Adding a model means adding it to the variant below, nothing in engine/
// or tasks/; read_material() finds it by type_name.
#pragma once
#include <string>
#include <variant>
#include <vector>

#include "materials/linear_elastic.hpp"
#include "materials/orthotropic.hpp"
#include "materials/strain_softening.hpp"
#include "materials/transversely_isotropic.hpp"
#include "materials/von_mises.hpp"

namespace flowmpm {

class TableReader;

using Material = std::variant<LinearElastic, Orthotropic, TransverselyIsotropic, VonMises, StrainSoftening>;

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
