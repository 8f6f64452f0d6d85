// What a system carries from one step to the next, for checkpoints: the
// clock (step, time, the last dt and the largest particle speed, which
// dt = "auto" reads), the particles in their memory order with every
// column (the order of the sort decides the order of every nodal sum, so
// a continuation in another order would differ in the last bits), the
// block lists and active node box of the last sort, the sort counter,
// whether a re-sort is due, and the constraints' reactions over the last
// step (which the diagnostics report), the kinetic energy after the last
// step and the work done on the bodies since t = 0 (the energy balance's),
// and in a contact scene the contact forces of the last step, the
// interfaces' stored energy and the contact's work.
// The grid's nodal values do not carry. Each step clears the nodes of the
// active box before mapping to them and computes there every value it
// reads. A node leaves the active box at a re-sort only when no particle
// reached it in the step before (the box reaches drift_limit >= 2 cells
// beyond the blocks, and a particle moves at most one cell per step:
// discretisation/grid/blocks.hpp), so what it keeps is zero mass, momentum and
// force, and on a massless node velocities, which count for nothing (the
// reactions weigh them by its zero mass).
#pragma once
#include <string>
#include <type_traits>

#include "discretisation/discrete_system.hpp"
#include "engine/state_records.hpp"

namespace flowmpm {

// Calls f(name, value) for every piece of carried state of `s` (a
// DiscreteSystem, const when saving).
template <class System, class F>
void visit_carried_state(System& s, F&& f) {
  f("clock.step", s.step);
  f("clock.t", s.t);
  f("clock.dt", s.dt);
  f("clock.max_speed_sq", s.max_speed_sq);
  f("clock.sorts", s.sorts);
  bool resort_needed = s.flags.resort_needed;
  f("clock.resort_needed", resort_needed);
  if constexpr (!std::is_const_v<System>) s.flags.resort_needed = resort_needed;
  f("grid.active_lo", s.grid.active_lo);
  f("grid.active_hi", s.grid.active_hi);
  f("blocks.occupied", s.blocks.occupied);
  for (std::size_t c = 0; c < s.blocks.occupied_by_colour.size(); ++c)
    f("blocks.occupied_by_colour." + std::to_string(c), s.blocks.occupied_by_colour[c]);
  for (std::size_t i = 0; i < s.batches.size(); ++i) {
    auto& batch = s.batches[i];
    const std::string prefix = "batch." + std::to_string(i) + ".";
    batch.for_each_column([&](const char* name, auto& column) { f(prefix + name, column); });
    f(prefix + "block_begin", batch.block_begin);
  }
  for (std::size_t k = 0; k < s.constraints.size(); ++k) {
    f("constraint." + std::to_string(k) + ".reaction", s.constraints[k].reaction);
    f("constraint." + std::to_string(k) + ".work", s.constraints[k].work);
  }
  for (std::size_t k = 0; k < s.walls.size(); ++k) {
    f("wall." + std::to_string(k) + ".force", s.walls[k].force);
    f("wall." + std::to_string(k) + ".work", s.walls[k].work);
  }
  f("energy.kinetic", s.kinetic_energy);
  f("work.gravity", s.work.gravity);
  f("work.boundary", s.work.boundary);
  f("work.expansion", s.work.expansion);
  f("work.load", s.work.load);
  f("damping.dissipated", s.damping_dissipated);
  if (s.nonlocal) f("nonlocal.unsettled_steps", s.nonlocal->unsettled_steps);
  if (s.contact) {
    f("work.contact", s.work.contact);
    for (std::size_t k = 0; k < s.contact->pairs.size(); ++k) {
      f("contact." + std::to_string(k) + ".normal_force", s.contact->pairs[k].normal_force);
      f("contact." + std::to_string(k) + ".tangential_force", s.contact->pairs[k].tangential_force);
      if (is_interface(s.contact->pairs[k].law))
        f("contact." + std::to_string(k) + ".interface_energy", s.contact->pairs[k].interface_energy);
    }
    for (std::size_t r = 0; r < s.contact->rigid.size(); ++r) {
      f("rigid." + std::to_string(r) + ".force", s.contact->rigid[r].force);
      f("rigid." + std::to_string(r) + ".work", s.contact->rigid[r].work);
    }
  }
}

template <int D, class Shape>
void save_carried_state(const DiscreteSystem<D, Shape>& system, StateRecords& records) {
  visit_carried_state(system, StateWriter(records));
}

// Restores the state saved from a system built from the same spec; throws
// std::runtime_error when the records do not fit it (written by another
// build of the program, or for another case): every particle column must
// keep the length the build gave it.
template <int D, class Shape>
void restore_carried_state(const StateRecords& records, DiscreteSystem<D, Shape>& system) {
  const auto column_lengths = [&] {
    std::vector<std::size_t> lengths;
    for (const auto& b : system.batches) {
      b.for_each_column([&](const char*, const auto& column) { lengths.push_back(column.size()); });
      lengths.push_back(b.block_begin.size());
    }
    return lengths;
  };
  const std::vector<std::size_t> built = column_lengths();
  visit_carried_state(system, StateReader(records));
  if (column_lengths() != built) throw std::runtime_error("its particles do not fit those the case builds");
}

}  // namespace flowmpm
