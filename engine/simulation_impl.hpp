// The members of Simulation<D, Shape> (engine/simulation.hpp), which pull
// in every kernel: included only by the engine library's instantiations
// (engine/simulation_instances.cpp.in).
#pragma once
#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/errors.hpp"
#include "discretisation/build_system.hpp"
#include "discretisation/grid/particle_sort.hpp"
#include "engine/carried_state.hpp"
#include "engine/diagnostics.hpp"
#include "engine/energy_balance.hpp"
#include "engine/simulation.hpp"
#include "engine/take_snapshot.hpp"
#include "tasks/stage_table.hpp"

namespace flowmpm {

template <int D, class Shape>
Simulation<D, Shape>::Simulation(const SystemSpec& spec, const Wiring& wiring, double fixed_dt,
                                 std::function<void(Stage)> observer, TransportBranch branch)
    : shape_(spec.shape_function),
      fixed_dt_(fixed_dt),
      observer_(std::move(observer)),
      graph_(step_wiring(asks_nonlocal(spec) ? with_nonlocal_settle(wiring) : wiring, spec, branch),
             [this](int node) { run_node(node); }) {
  for (const StageGroup& group : graph_.wiring().nodes) passes_.push_back(stage_pass<D, Shape>(group));
  build_system(spec, system_);
  // Nodes too light for their stiffness are held only where the stress
  // update sees the updated grid velocity (tasks/grid_update.hpp held_node),
  // or APIC's affine velocity its gradient (tasks/g2p.hpp): where N_Ip
  // vanishes dN_Ip does not, and the affine velocity would take the light
  // node's whole f_I dt / m_I (a spinning square blew up in 60 steps, MUSL).
  if constexpr (Shape::gradient_jumps)
    if (wiring.stress_from_updated_grid() || spec.velocity_update == VelocityUpdate::apic)
      for (int k = 0; k < system_.field_count(); ++k) system_.field(k).stiffness.assign(system_.grid.node_count(), 0.0);
}

template <int D, class Shape>
void Simulation<D, Shape>::advance() {
  finish_step([this] { graph_.run(); });
}

template <int D, class Shape>
void Simulation<D, Shape>::advance_serial() {
  finish_step([this] { graph_.run_serial(); });
}

template <int D, class Shape>
SystemSize Simulation<D, Shape>::size() const {
  SystemSize s;
  s.particles = system_.particle_count();
  s.nodes = system_.grid.node_count();
  for (const auto& b : system_.batches)
    for (const double m : b.mass) s.total_mass += m;
  return s;
}

template <int D, class Shape>
void Simulation<D, Shape>::measure_speed() {
  system_.max_speed_sq = 0.0;
  system_.kinetic_energy = 0.0;
  for (const auto& b : system_.batches) {
    for (std::size_t p = 0; p < b.size(); ++p) {
      system_.max_speed_sq = std::max(system_.max_speed_sq, b.v[p].squaredNorm());
      system_.kinetic_energy += 0.5 * b.mass[p] * b.v[p].squaredNorm();
    }
  }
}

template <int D, class Shape>
Diagnostics Simulation<D, Shape>::diagnostics(std::size_t body_count) const {
  return flowmpm::diagnostics(system_, body_count);
}

template <int D, class Shape>
void Simulation<D, Shape>::snapshot_into(ParticleSnapshot& s, const std::vector<std::string>& names) const {
  take_snapshot(system_, names, s);
}

template <int D, class Shape>
std::string Simulation<D, Shape>::fastest_particle(const std::vector<std::string>& body_names) const {
  double best = -1.0;
  Vec<D> x = Vec<D>::Zero();
  int body = 0;
  for (const auto& b : system_.batches) {
    for (std::size_t p = 0; p < b.size(); ++p) {
      if (!(b.v[p].squaredNorm() <= best)) best = b.v[p].squaredNorm(), x = b.x[p], body = b.body;
    }
  }
  std::ostringstream s;
  s.precision(6);
  s << "a particle of body '" << body_names.at(body) << "' at " << position_text<D>(x) << " moves at "
    << std::sqrt(best) << " m/s";
  return s.str();
}

template <int D, class Shape>
void Simulation<D, Shape>::save_state(StateRecords& records) const {
  save_carried_state(system_, records);
}

template <int D, class Shape>
void Simulation<D, Shape>::restore_state(const StateRecords& records) {
  restore_carried_state(records, system_);
}

template <int D, class Shape>
void Simulation<D, Shape>::run_node(int node) {
  if (observer_)
    for (Stage s : graph_.wiring().nodes[node]) observer_(s);
  passes_[node](system_);
}

template <int D, class Shape>
template <class RunStep>
void Simulation<D, Shape>::finish_step(RunStep&& run_step) {
  if (system_.flags.resort_needed) sort_particles(system_);
  run_step();
  add_step_energy(system_);
  if (system_.flags.failed) {
    std::ostringstream s;
    s.precision(6);
    s << "step " << system_.step + 1 << " (t = " << system_.t << " s to " << system_.t + system_.dt
      << " s): " << system_.flags.problem;
    throw SimulationError(s.str());
  }
  ++system_.step;
  // A fixed step keeps t an exact multiple of dt; an automatic one adds up.
  system_.t = fixed_dt_ > 0.0 ? static_cast<double>(system_.step) * fixed_dt_ : system_.t + system_.dt;
}

}  // namespace flowmpm
