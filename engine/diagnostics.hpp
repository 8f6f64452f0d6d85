// What the time series and the summary report of a system's state: the
// energy balance, per body the volume-weighted mean stress and strain,
// and the reactions of the velocity constraints.
// Serial, in particle order, so the numbers do not depend on the thread count.
#pragma once
#include <array>
#include <cstdint>
#include <numbers>
#include <string>
#include <type_traits>
#include <vector>

#include "discretisation/discrete_system.hpp"

namespace flowmpm {

struct BodyMeans {
  std::array<double, 6> stress{};  // Pa, volume-weighted mean, Voigt order
  std::array<double, 6> strain{};  // -, volume-weighted mean
};

// A column of the time series after the bodies' means: the force a
// velocity constraint applied on the body along one axis in the last step
// (NodeConstraint::reaction; "reaction.<set>.<axis>"), and in a contact
// scene the contact forces and work (tasks/contact.hpp; `axis` -1 and
// `name` the whole column name); in axisymmetric analysis each force again
// over the full turn ("<column>.full_turn", 2 pi times the per-radian value).
struct Reaction {
  std::string name;
  int axis = 0;
  double value = 0.0;  // N (N/m in 2D, N/m^2 in 1D, N per radian in axisymmetric), or J for a work

  std::string column() const { return axis < 0 ? name : "reaction." + name + "." + "xyz"[axis]; }
};

struct Diagnostics {
  std::int64_t step = 0;
  double time = 0.0;            // s
  // Energy balance (engine/energy_balance.hpp), J (per unit thickness in 2D,
  // per unit cross-section in 1D).
  double kinetic_energy = 0.0;
  double stored_energy = 0.0;      // the materials' recoverable energy and the interfaces'
  double dissipated_energy = 0.0;  // plastic work, damage, damping
  WorkDone work;                   // done on the bodies since t = 0
  // kinetic + stored + dissipated - the work done: constant but for the
  // scheme's error.
  double energy_balance() const {
    return kinetic_energy + stored_energy + dissipated_energy - work.gravity - work.boundary - work.expansion -
           work.load - work.contact;
  }
  std::vector<BodyMeans> bodies;     // per body of the spec
  std::vector<Reaction> reactions;   // per constrained node set and axis, then contact
};

// `body_count`: the spec's bodies (one batch each).
template <int D, class Shape>
Diagnostics diagnostics(const DiscreteSystem<D, Shape>& system, std::size_t body_count) {
  Diagnostics row;
  row.step = system.step;
  row.time = system.t;
  row.bodies.resize(body_count);
  std::vector<double> body_volume(body_count, 0.0);
  for (const auto& b : system.batches) {
    BodyMeans& means = row.bodies[b.body];
    for (std::size_t p = 0; p < b.size(); ++p) {
      row.kinetic_energy += 0.5 * b.mass[p] * b.v[p].squaredNorm();
      for (int i = 0; i < 6; ++i) {
        means.stress[i] += b.volume[p] * b.stress[p][i];
        means.strain[i] += b.volume[p] * b.strain[p][i];
      }
      body_volume[b.body] += b.volume[p];
    }
    // The material's stored energy per unit volume (its own contract); a
    // rigid body has none.
    if (b.material < 0) continue;
    std::visit(
        [&](const auto& model) {
          using M = std::decay_t<decltype(model)>;
          const auto& states = std::get<StateArray<M>>(b.states);
          const typename M::State none{};
          for (std::size_t p = 0; p < b.size(); ++p) {
            const auto& state = states.empty() ? none : states[p];
            row.stored_energy += b.volume[p] * model.stored_energy(state, b.stress[p], b.strain[p]);
            if constexpr (requires { model.dissipated_energy(state); })
              row.dissipated_energy += b.volume[p] * model.dissipated_energy(state);
          }
        },
        system.materials[b.material]);
  }
  row.dissipated_energy += system.damping_dissipated;
  row.work = system.work;
  for (const NodeConstraint& c : system.constraints) row.reactions.push_back({c.name, c.axis, c.reaction});
  for (const Wall<D>& w : system.walls)
    for (int d = 0; d < D; ++d) row.reactions.push_back({w.name, d, w.force[d]});
  if (system.contact) {
    // Per pair the normal (pressing) and tangential forces on its first
    // body and an interface's stored energy, per rigid body the force on it
    // per axis and its work, and the contact's work on the bodies
    // (engine/energy_balance.hpp).
    for (const ContactPair& p : system.contact->pairs) {
      row.reactions.push_back({"contact." + p.name + ".normal", -1, p.normal_force});
      row.reactions.push_back({"contact." + p.name + ".tangential", -1, p.tangential_force});
      // An interface's stored energy, part of the stored energy.
      if (is_interface(p.law)) {
        row.reactions.push_back({"contact." + p.name + ".interface_energy", -1, p.interface_energy});
        row.stored_energy += p.interface_energy;
      }
    }
    for (const RigidMotion<D>& r : system.contact->rigid) {
      for (int d = 0; d < D; ++d) row.reactions.push_back({r.name, d, r.force[d]});
      row.reactions.push_back({"rigid." + r.name + ".work", -1, r.work});
    }
    row.reactions.push_back({"contact_work", -1, system.work.contact});
  }
  if (system.stress_state == StressState::axisymmetric) {
    // The forces above act on a one-radian wedge; each again over the full
    // turn, 2 pi times (N): "<column>.full_turn".
    const std::size_t per_radian = row.reactions.size();
    for (std::size_t i = 0; i < per_radian; ++i) {
      const Reaction r = row.reactions[i];  // a copy: the vector grows below
      const std::string column = r.column();
      if (r.axis >= 0 || column.ends_with(".normal") || column.ends_with(".tangential"))
        row.reactions.push_back({column + ".full_turn", -1, 2.0 * std::numbers::pi * r.value});
    }
  }
  for (std::size_t i = 0; i < body_count; ++i) {
    for (int k = 0; k < 6; ++k) {
      row.bodies[i].stress[k] /= body_volume[i];
      row.bodies[i].strain[k] /= body_volume[i];
    }
  }
  return row;
}

}  // namespace flowmpm
