// The blow-up guard (docs/STABILITY.md): after every step, a kinetic energy
// above guard_energy_factor times the initial energy plus the most work
// done on the bodies (engine/energy_balance.hpp EnergyBudget), or a
// particle faster than guard_speed_factor times the fastest wave speed,
// stops the run with a SimulationError that says where and what may run
// the case. The state is kept every guard_every steps so that the last one
// that passed can be written.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "engine/energy_balance.hpp"
#include "engine/simulation_base.hpp"
#include "engine/time_step.hpp"
#include "io/case/case_file.hpp"

namespace flowmpm {

class BlowUpGuard {
 public:
  // `initial`: the diagnostics at the start, the budget's initial energy.
  BlowUpGuard(const Case& c, const TimeStep& time_step, const SimulationBase& sim, const Diagnostics& initial);

  // Keeps the state every guard_every steps.
  void before_step(const SimulationBase& sim);
  // Throws SimulationError if the step blew up.
  void after_step(const SimulationBase& sim, const std::vector<std::string>& body_names);

  // The last state kept (count 0 when none).
  const ParticleSnapshot& last_good() const { return last_good_; }
  // What may run a case that broke down, appended to the message.
  const std::string& remedy() const { return remedy_; }

  // What a checkpoint carries: the budget and, unless the next step keeps
  // the state anyway, the last good state.
  template <class F>
  void visit_state(F&& f, const SimulationBase& sim) {
    budget_.visit_state(f);
    // At a step the guard keeps anyway (a multiple of guard_every), the
    // loop keeps it again before the next step: nothing to save.
    const bool kept_next = every_ > 0 && sim.scalars().step % every_ == 0;
    std::size_t rows = kept_next ? 0 : last_good_.count;
    f("guard.count", rows);
    if (rows == 0) return;
    if (last_good_.count == 0) sim.snapshot_into(last_good_, fields_);  // restoring: the fields' layout
    f("guard.step", last_good_.step);
    f("guard.time", last_good_.time);
    for (SnapshotField& field : last_good_.fields) {
      f("guard." + std::string(field.field.name), field.real);
      f("guard." + std::string(field.field.name) + ".integer", field.integer);
    }
  }

 private:
  EnergyBudget budget_;
  double wave_speed_, speed_factor_;
  std::int64_t every_;
  const std::vector<std::string>& fields_;
  ParticleSnapshot last_good_;
  std::string remedy_;
};

}  // namespace flowmpm
