// A running simulation: the DiscreteSystem, the step graph wired for a
// scheme (with nonlocal_settle after g2p_stress where a model asks for
// nonlocal averages, and the transport branch where the scene conducts
// heat or diffuses solvent) with each node's pass resolved once
// (tasks/stage_table.hpp), and
// what the time loop and the writers read off it.
#pragma once
#include <algorithm>
#include <cmath>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include "core/errors.hpp"
#include "discretisation/build_system.hpp"
#include "engine/diagnostics.hpp"
#include "engine/energy_balance.hpp"
#include "engine/schemes.hpp"
#include "engine/take_snapshot.hpp"
#include "engine/step_graph.hpp"
#include "tasks/stage_table.hpp"

namespace flowmpm {

template <int D, class Shape>
class Simulation {
 public:
  // `wiring`: the scheme's; the transport branch is added when the scene
  // needs it (step_wiring), beside the momentum stages unless `branch`
  // says otherwise. `observer`, if given, is called as each stage starts
  // (from any thread; for the stages of one node, in their order, as the
  // node starts). `fixed_dt`: the time step when it stays fixed, 0 when the
  // caller sets system().dt before every step.
  Simulation(const SystemSpec& spec, const Wiring& wiring, double fixed_dt,
             std::function<void(Stage)> observer = {}, TransportBranch branch = TransportBranch::beside)
      : fixed_dt_(fixed_dt),
        observer_(std::move(observer)),
        graph_(step_wiring(asks_nonlocal(spec) ? with_nonlocal_settle(wiring) : wiring, spec, branch),
               [this](int node) { run_node(node); }) {
    for (const StageGroup& group : graph_.wiring().nodes) passes_.push_back(stage_pass<D, Shape>(group));
    build_system(spec, system_);
    // Nodes too light for their stiffness are held only where the stress
    // update sees the updated grid velocity (tasks/grid_update.hpp held_node).
    if constexpr (Shape::gradient_jumps)
      if (wiring.stress_from_updated_grid()) system_.grid.stiffness.assign(system_.grid.node_count(), 0.0);
  }

  // One step through the flow graph (or serially, as the reference).
  void advance() { finish_step([this] { graph_.run(); }); }
  void advance_serial() { finish_step([this] { graph_.run_serial(); }); }

  DiscreteSystem<D, Shape>& system() { return system_; }
  const DiscreteSystem<D, Shape>& system() const { return system_; }
  const StepGraph& graph() const { return graph_; }

  // The fields named in `names` (engine/take_snapshot.hpp).
  ParticleSnapshot snapshot(const std::vector<std::string>& names) const {
    ParticleSnapshot s;
    take_snapshot(system_, names, s);
    return s;
  }
  // The same into `s`, reusing its storage.
  void snapshot_into(ParticleSnapshot& s, const std::vector<std::string>& names) const {
    take_snapshot(system_, names, s);
  }

  // Sets the system's largest particle speed and kinetic energy (they are
  // measured during each step; this measures them outside one, e.g. at the
  // start).
  void measure_speed() {
    system_.max_speed_sq = 0.0;
    system_.kinetic_energy = 0.0;
    for (const auto& b : system_.batches) {
      for (std::size_t p = 0; p < b.size(); ++p) {
        system_.max_speed_sq = std::max(system_.max_speed_sq, b.v[p].squaredNorm());
        system_.kinetic_energy += 0.5 * b.mass[p] * b.v[p].squaredNorm();
      }
    }
  }

  // Where the fastest particle is, of which body, and how fast it moves,
  // for messages.
  std::string fastest_particle(const std::vector<std::string>& body_names) const {
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

  // Energies and volume-weighted mean stress and strain per body.
  Diagnostics diagnostics(std::size_t body_count) const { return flowmpm::diagnostics(system_, body_count); }

 private:
  void run_node(int node) {
    if (observer_)
      for (Stage s : graph_.wiring().nodes[node]) observer_(s);
    passes_[node](system_);
  }

  template <class RunStep>
  void finish_step(RunStep&& run_step) {
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

  DiscreteSystem<D, Shape> system_;
  double fixed_dt_;
  std::function<void(Stage)> observer_;
  std::vector<StagePass<D, Shape>> passes_;
  StepGraph graph_;
};

}  // namespace flowmpm
