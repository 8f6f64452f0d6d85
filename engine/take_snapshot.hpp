// The output fields a system offers, and its snapshot (engine/snapshot.hpp):
// the stored particle columns by name (ParticleBatch::for_each_column), the
// fields derived from them, and the models' state variables, each row at
// the particle's id.
#pragma once
#include <cmath>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "discretisation/discrete_system.hpp"
#include "engine/snapshot.hpp"
#include "materials/state_variable.hpp"

namespace flowmpm {

// The built-in fields and the state variables of `materials`' models.
inline std::vector<OutputField> output_fields_of(const std::vector<Material>& materials) {
  std::vector<OutputField> fields(std::begin(builtin_output_fields), std::end(builtin_output_fields));
  for (const Material& m : materials) {
    std::visit(
        [&](const auto& model) {
          using M = std::decay_t<decltype(model)>;
          if constexpr (HasStateVariables<M>) {
            for (const StateVariable& v : M::state_variables) {
              const bool known = std::ranges::any_of(fields, [&](const OutputField& f) { return std::string_view(f.name) == v.name; });
              if (!known) fields.push_back({v.name, 1, v.units, false});
            }
          }
        },
        m);
  }
  return fields;
}

namespace detail {

// Row `row` of field `f` from one value of a stored column.
template <int D>
void put(SnapshotField& f, std::size_t row, const Vec<D>& x) {
  for (int d = 0; d < 3; ++d) f.real[3 * row + d] = d < D ? x[d] : 0.0;
}
inline void put(SnapshotField& f, std::size_t row, double value) { f.real[row] = value; }
inline void put(SnapshotField& f, std::size_t row, const Voigt& a) {
  for (int k = 0; k < 6; ++k) f.real[6 * row + k] = a[tensor_output_order[k]];
}
inline void put(SnapshotField& f, std::size_t row, std::uint32_t value) {
  f.integer[row] = static_cast<std::int32_t>(value);
}
// A model's internal variables are written through its state variables.
template <class State>
void put(SnapshotField&, std::size_t, const State&) {}

// Fills `f` for the particles of batch `b` (rows at their ids); `material`
// is null for a rigid body (no model, no state variables).
template <int D>
void fill(SnapshotField& f, const ParticleBatch<D>& b, const Material* material) {
  const std::string_view name = f.field.name;
  const auto& id = b.id;
  b.for_each_column([&](const char* column_name, const auto& column) {
    if (name != column_name) return;
    for (std::size_t p = 0; p < column.size(); ++p) put(f, id[p], column[p]);
  });
  if (name == "displacement") {
    if (b.x0.size() != b.size())
      throw std::logic_error("the displacement field needs the initial positions (SystemSpec::keep_initial_positions)");
    for (std::size_t p = 0; p < b.size(); ++p) put<D>(f, id[p], b.x[p] - b.x0[p]);
  } else if (name == "von_mises" || name == "pressure") {
    for (std::size_t p = 0; p < b.size(); ++p) {
      const Voigt& s = b.stress[p];
      const double mean = (s[0] + s[1] + s[2]) / 3.0;
      Voigt deviator = s;
      for (int i = 0; i < 3; ++i) deviator[i] -= mean;
      f.real[id[p]] = name == "pressure" ? -mean : std::sqrt(1.5 * double_contraction(deviator, deviator));
    }
  } else if (name == "material") {
    for (std::size_t p = 0; p < b.size(); ++p) f.integer[id[p]] = b.material;
  }
  if (!material) return;
  std::visit(
      [&](const auto& model) {
        using M = std::decay_t<decltype(model)>;
        if constexpr (HasStateVariables<M>) {
          for (std::size_t k = 0; k < M::state_variables.size(); ++k) {
            if (name != M::state_variables[k].name) continue;
            const auto& states = std::get<StateArray<M>>(b.states);
            std::array<double, M::state_variables.size()> values{};
            for (std::size_t p = 0; p < b.size(); ++p) {
              model.state_values(states[p], values.data());
              f.real[id[p]] = values[k];
            }
          }
        }
      },
      *material);
}

}  // namespace detail

// Fills `s` with the fields named in `names`, in the order of
// output_fields_of(), reusing its storage. Rows are particle ids; a state
// variable is 0 for particles whose model does not have it.
template <int D, class Shape>
void take_snapshot(const DiscreteSystem<D, Shape>& system, const std::vector<std::string>& names, ParticleSnapshot& s) {
  s.step = system.step;
  s.time = system.t;
  s.count = system.particle_count();
  std::size_t k = 0;
  for (const OutputField& f : output_fields_of(system.materials)) {
    if (std::ranges::find(names, f.name) == names.end()) continue;
    if (k == s.fields.size() || std::string_view(s.fields[k].field.name) != f.name) {
      s.fields.resize(k);
      s.fields.push_back({f, {}, {}});
    }
    SnapshotField& field = s.fields[k++];
    if (f.integer) {
      field.integer.assign(s.count, 0);
    } else {
      field.real.assign(s.count * static_cast<std::size_t>(f.components), 0.0);
    }
    for (const auto& b : system.batches) detail::fill(field, b, b.material < 0 ? nullptr : &system.materials[b.material]);
  }
  s.fields.resize(k);
}

}  // namespace flowmpm
