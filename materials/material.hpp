// The registry of constitutive models (docs/ARCHITECTURE.md "Materials").
// A model is a value type with
//   static constexpr const char* type_name;          // the case file's `type`
//   static Model read(ParameterTable&);              // parameters, validated
//   struct State;                                    // internal variables per particle, plain
//                                                    // data: checkpoints store its bytes
//   State initial_state(const ParticleInit&) const;
//   template <StressState Kind>
//   void update(State&, Voigt& sigma, Voigt& deps, const MaterialInput&) const;
//   double stored_energy(const State&, const Voigt& sigma, const Voigt& eps) const;
//                                                    // recoverable energy per unit volume (J/m^3)
//   double density() const;                          // kg/m^3
//   double wave_speed() const;                       // fastest wave, m/s (stable dt)
//   const TransportProperties& transport() const;    // heat capacity, conductivity,
//                                                    // diffusivity, T_ref (transport_properties.hpp)
// and optionally
//   named state variables for output (materials/state_variable.hpp);
//   a nonlocal average of a state variable (materials/nonlocal_model.hpp);
//   double dissipated_energy(const State&) const;    // J/m^3 dissipated so far (plastic work, damage)
//   double expansion_work(const State&, const Voigt& sigma, const MaterialInput&) const;
//                                                    // J/m^3 done on the body: -sigma : d eps_expansion
//                                                    // for the energy balance (engine/energy_balance.hpp);
//   bool expands() const;                            // false: the engine skips expansion_work
//   static constexpr bool supports(StressState);     // false for a stress state it has no update for
//                                                    // (its update is then never called): the case
//                                                    // reader refuses its material there
//   Eigen::Quaterniond material_axes(const State&) const;  // models with material axes: R, material
//                                                    // to global; the conductivity and diffusivity turn with it
// `update` is pure apart from its outputs: stress, state, and for reduced
// stress states the out-of-plane strain components of deps. MaterialInput
// carries the particle's temperature change and concentration when the
// scene conducts heat or diffuses solvent; models with expansion take them
// from there unless a uniform function of time drives it
// (materials/expansion.hpp). The engine dispatches on this variant once per
// particle batch, never per particle.
// Adding a model is one new file and one line in the variant below.
#pragma once
#include <concepts>
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

#include "core/registry.hpp"
#include "materials/drucker_prager.hpp"
#include "materials/linear_elastic.hpp"
#include "materials/mohr_coulomb.hpp"
#include "materials/neo_hookean.hpp"
#include "materials/nonlocal_model.hpp"
#include "materials/orthotropic.hpp"
#include "materials/strain_softening.hpp"
#include "materials/transversely_isotropic.hpp"
#include "materials/von_mises.hpp"

namespace flowmpm {

using Material = std::variant<LinearElastic, Orthotropic, TransverselyIsotropic, VonMises, StrainSoftening, NeoHookean,
                              MohrCoulomb, DruckerPrager>;
using Materials = Registry<Material>;

// The internal variables of every particle of a batch, one array per model.
template <class Model>
using StateArray = std::vector<typename Model::State>;

struct NamedMaterial {
  std::string name;
  Material model;
};

// Reads a [materials.NAME] table: `type` picks the model, which reads the rest.
inline Material read_material(ParameterTable& table) { return Materials::read(table, "type"); }

inline double density(const Material& m) {
  return std::visit([](const auto& model) { return model.density(); }, m);
}
inline double wave_speed(const Material& m) {
  return std::visit([](const auto& model) { return model.wave_speed(); }, m);
}
// l (m) of a model asking for a nonlocal average, 0 for the others.
inline double nonlocal_length(const Material& m) {
  return std::visit(
      [](const auto& model) -> double {
        if constexpr (NonlocalModel<std::decay_t<decltype(model)>>) {
          return model.nonlocal_length();
        } else {
          return 0.0;
        }
      },
      m);
}
// Whether the model has an update for the stress state (supports above;
// true for a model that does not declare it).
inline bool supports(const Material& m, StressState kind) {
  return std::visit(
      [&](const auto& model) {
        using M = std::decay_t<decltype(model)>;
        if constexpr (requires { M::supports(kind); }) {
          return M::supports(kind);
        } else {
          return true;
        }
      },
      m);
}
inline const char* type_name(const Material& m) { return Materials::name_of(m); }
inline const TransportProperties& transport(const Material& m) {
  return std::visit([](const auto& model) -> const TransportProperties& { return model.transport(); }, m);
}

// A model whose transport tensors turn with its material axes.
template <class Model>
concept HasMaterialAxes = requires(const Model& m, const typename Model::State& s) {
  { m.material_axes(s) } -> std::convertible_to<Eigen::Quaterniond>;
};

}  // namespace flowmpm
