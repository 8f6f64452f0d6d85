// The energy balance of a run (docs/theory/energy_balance.md):
//   kinetic + stored + dissipated - W_gravity - W_boundary - W_expansion - W_load
// stays at its initial value, where stored and dissipated are the
// materials' own (stored_energy, dissipated_energy) plus what damping took
// (tasks/grid_update.hpp), and the W are the work done on the bodies since
// t = 0: by gravity and body forces (the fall of the potential energy,
// sum m g_p . dx), by the velocity constraints' reactions (sum R V dt), by
// the expansion strains against the stress, and by the tractions,
// pressures and nodal forces (tasks/external_forces.hpp). What it does not keep
// is the scheme's error: PIC's and FLIP's mapping losses, the time
// integration, and a blow-up.
// The per-step sums come from the particles' blocks, added in block order:
// the same at any thread count.
#pragma once
#include <algorithm>
#include <cmath>

#include "discretisation/discrete_system.hpp"

namespace flowmpm {

// After a step: the kinetic energy and the work of the step from the block
// sums (which it clears for the next step) and the constraints.
template <int D, class Shape>
void add_step_energy(DiscreteSystem<D, Shape>& system) {
  double kinetic = 0.0;
  for (const std::uint32_t block : system.blocks.occupied) {
    BlockEnergy& e = system.block_energy[block];
    kinetic += e.kinetic;
    system.work.gravity += e.gravity_work;
    system.work.expansion += e.expansion_work;
    e = BlockEnergy{};
  }
  system.kinetic_energy = kinetic;
  system.work.boundary = 0.0;
  for (const NodeConstraint& c : system.constraints) system.work.boundary += c.work;
  for (const Wall<D>& w : system.walls) system.work.boundary += w.work;
  for (const SurfaceLoad<D>& load : system.loads.surface) {
    const ParticleBatch<D>& b = system.batches[load.batch];
    for (const LoadedFace<D>& f : load.faces) system.work.load += f.force.dot(b.x[f.particle] + f.offset - f.at);
  }
}

// The blow-up guard's budget: a run cannot have more kinetic energy than
// its initial energy plus what was done on it at some time (the largest so
// far: a column oscillating under gravity gives back gravity's work each
// period). `factor` times that, plus a floor for bodies at rest (all
// particles at 1e-6 of the fastest wave speed), is the most the guard lets
// pass.
class EnergyBudget {
 public:
  EnergyBudget(double initial, double floor, double factor)
      : initial_(initial), largest_(initial), floor_(floor), factor_(factor) {}

  // The most kinetic energy allowed after a step with the work `w` done so far.
  double limit(const WorkDone& w) {
    largest_ = std::max(largest_, initial_ + std::abs(w.gravity) + std::abs(w.boundary) + std::abs(w.expansion) +
                                      std::abs(w.load) + std::abs(w.contact));
    return factor_ * (largest_ + floor_);
  }
  double factor() const { return factor_; }
  // Calls f(name, value) for what a checkpoint carries (engine/carried_state.hpp).
  template <class F>
  void visit_state(F&& f) {
    f("energy.budget_initial", initial_);
    f("energy.budget_largest", largest_);
  }

 private:
  double initial_;  // kinetic + stored + dissipated at the start (J)
  double largest_;  // the largest initial energy plus work done so far (J)
  double floor_;    // J
  double factor_;
};

}  // namespace flowmpm
