#include "app/run_services.hpp"

#include "discretisation/shapes/shape_functions.hpp"

namespace flowmpm {

std::unique_ptr<SimulationBase> simulation_of(const Case& c) {
  return make_simulation(c.system, c.scheme->wiring, c.time_step.fixed_dt());
}

RunServices::RunServices(const Case& c, const RunOptions& options)
    : c(c),
      sim(simulation_of(c)),
      body_names([&] {
        std::vector<std::string> names;
        for (const auto& b : c.system.bodies) names.push_back(b.name);
        return names;
      }()),
      reference(c.reference, *sim, c.time_step.planned_steps()),
      initial(sim->diagnostics(c.system.bodies.size())),
      energy(initial),
      guard(c, c.time_step, *sim, initial),
      results(c, options, *sim, c.time_step.planned_steps(), reference.error_names()),
      checkpointer(c, options),
      progress(options.progress_seconds, c.time_step.end_time()) {
  summary.case_name = c.name;
  summary.case_file = c.file.string();
  summary.scheme = c.scheme->label;
  summary.shape_function = sim->shape_function();
  summary.velocity_update = velocity_update_name(c.system.velocity_update);
  summary.dimension = sim->dimension();
  summary.axisymmetric = sim->stress_state() == StressState::axisymmetric;
  summary.threads = options.threads;
  const SystemSize size = sim->size();
  summary.particles = size.particles;
  summary.nodes = size.nodes;
  summary.dt = c.time_step.fixed_dt();
  summary.end_time = c.time_step.end_time();
}

void RunServices::restore(const StateRecords& records) {
  sim->restore_state(records);
  visit_state(StateReader(records));
}

}  // namespace flowmpm
