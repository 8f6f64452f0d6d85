// A case's simulation and the services of its time loop (the reference
// sampler, the energy balance, the blow-up guard, the results writer, the
// checkpointer and the progress reporter), built and checked before
// anything is written, and what a checkpoint carries of them.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "app/blow_up_guard.hpp"
#include "app/checkpointer.hpp"
#include "app/energy_monitor.hpp"
#include "app/progress_reporter.hpp"
#include "app/reference_sampler.hpp"
#include "app/results_writer.hpp"
#include "app/run_case.hpp"
#include "engine/simulation_base.hpp"

namespace flowmpm {

// The simulation a case builds (its dimension, shape function and scheme).
std::unique_ptr<SimulationBase> simulation_of(const Case& c);

struct RunServices {
  RunServices(const Case& c, const RunOptions& options);

  const Case& c;
  std::unique_ptr<SimulationBase> sim;
  std::vector<std::string> body_names;
  ReferenceSampler reference;  // initialised first: it may set initial conditions
  Diagnostics initial;         // after the reference's initial conditions
  EnergyMonitor energy;
  BlowUpGuard guard;
  ResultsWriter results;
  Checkpointer checkpointer;
  ProgressReporter progress;
  RunSummary summary;  // what ran; its timings carry over a restart

  // An output step (results, energy balance and the errors so far).
  void write_output() { results.write(*sim, energy, reference, summary.output_seconds); }
  void write_checkpoint() {
    checkpointer.write(*sim, [&](StateWriter& write) { visit_state(write); }, summary.output_seconds);
  }
  // Restores the simulation and the services from a checkpoint's records;
  // throws std::runtime_error naming a record that does not fit.
  void restore(const StateRecords& records);

  // What a checkpoint carries of the services (the simulation saves its own).
  template <class F>
  void visit_state(F&& f) {
    results.visit_state(f);
    energy.visit_state(f);
    f("run.step_loop_seconds", summary.step_loop_seconds);
    f("run.output_seconds", summary.output_seconds);
    f("run.reference_seconds", summary.reference_seconds);
    reference.visit_state(f);
    guard.visit_state(f, *sim);
  }
};

}  // namespace flowmpm
