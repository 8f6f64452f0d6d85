// The time loop of a run (app/run_case.hpp): the system built, the output
// directory taken, the steps, output steps and checkpoints, the blow-up
// guard and the summary, for one dimension and shape function. Included
// only by the per-dimension translation units (app/run_case_dimension.cpp.in).
#pragma once
#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include <spdlog/spdlog.h>

#include "app/interrupt.hpp"
#include "app/run_case_internal.hpp"
#include "core/errors.hpp"
#include "core/number_text.hpp"
#include "discretisation/shape_functions.hpp"
#include "engine/carried_state.hpp"
#include "engine/energy_balance.hpp"
#include "engine/schemes.hpp"
#include "engine/simulation.hpp"
#include "engine/stable_time_step.hpp"
#include "io/checkpoint_file.hpp"
#include "io/memory_estimate.hpp"
#include "io/output_lock.hpp"
#include "io/results_h5.hpp"
#include "io/timeseries_csv.hpp"
#include "io/results_index.hpp"

namespace flowmpm::run_internal {

using Clock = std::chrono::steady_clock;
inline double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

template <int D, class Shape>
void log_system(spdlog::logger& log, const Case& c, const Simulation<D, Shape>& sim, const Scheme& scheme) {
  const DiscreteSystem<D, Shape>& system = sim.system();
  log.info("model: {}D ({}), scheme {} [{}], shape function {}, velocity update {}{}", D,
           stress_state_name(system.stress_state), scheme.label, sim.graph().wiring().describe(), Shape::name,
               c.velocity_update,
               c.velocity_update == "blend" ? " (FLIP fraction " + std::to_string(system.flip_fraction) + ")" : "");
  std::string cells;
  for (int d = 0; d < D; ++d) cells += (d ? " x " : "") + std::to_string(system.grid.cells[d]);
  log.info("grid: {} cells, {} nodes, {} blocks of {}^{} cells ({} occupied)", cells,
               system.grid.node_count(), system.blocks.block_count, BlockLayout<D, Shape>::block_cells, D,
               system.blocks.occupied.size());
  for (const auto& b : system.batches) {
    const auto& m = c.system.materials[b.material];
    log.info("body '{}': {} particles, material '{}' ({}, density {} kg/m^3, wave speed {:.4g} m/s)",
                 c.system.bodies[b.body].name, b.size(), m.name, type_name(m.model), density(m.model),
                 wave_speed(m.model));
  }
  log.info("particle fields stored: {}", stored_fields(D, system.heat.carried, system.solvent.carried));
  if (system.nonlocal.active) {
    log.info("nonlocal averages: over the initial positions (x0 stored), settled with the step's end by "
             "nonlocal_settle");
  }
  for (const auto& k : system.constraints) {
    log.info("node set '{}': {} nodes, velocity prescribed along {}", k.name, k.nodes.size(),
                 "xyz"[k.axis]);
  }
  if (system.heat.carried || system.solvent.carried) {
    log.info("transport: {}{}{} on the grid, a branch of the step graph beside the momentum stages",
             system.heat.carried ? "heat conduction" : "", system.heat.carried && system.solvent.carried ? " and " : "",
             system.solvent.carried ? "solvent diffusion" : "");
  }
  for (const auto* field : {&system.heat, &system.solvent}) {
    for (const auto& k : field->prescribed) {
      log.info("node set '{}': {} nodes, {} prescribed", k.name, k.nodes.size(),
               field == &system.heat ? "temperature" : "concentration");
    }
  }
  for (const auto& f : system.surface_fluxes) {
    log.info("surface flux '{}': {}{}", f.name, f.heat ? "heat" : "", f.solvent ? (f.heat ? " and solvent" : "solvent") : "");
  }
  if (system.gravity.norm() > 0.0) log.info("gravity: {} m/s^2", system.gravity.norm());
  for (const auto& load : system.loads.surface) log.info("load: {}", load.description);
  for (const auto& load : system.loads.nodal) log.info("load: {}", load.description);
  for (const auto& load : system.loads.body) log.info("load: {}", load.description);
  if (system.damping) {
    log.info("damping: local alpha {}, viscous c {} 1/s (at t = 0; README \"Damping\")", system.damping->local(0.0),
             system.damping->viscous(0.0));
  }
  for (const auto& body : c.system.bodies) {
    if (body.initial_stress) {
      log.info("body '{}': initial stress {}", body.name, InitialStresses::name_of(*body.initial_stress));
    } else if (body.particles && !body.particles->stress.empty()) {
      log.info("body '{}': initial stress per particle from {}", body.name, body.particles->source);
    }
  }
  const MemoryEstimate estimate = estimate_memory(c);
  log.info("{}", estimate_text(estimate));
  if (estimate.steps > long_run_steps) {
    log.warn("a long run: {:.3g} steps (more than {:.0e})", estimate.steps, long_run_steps);
  }
  const TimeStepLimit limits = time_step_limit(c.system, scheme);
  const StableStep& stable = limits.wave;
  if (c.dt_auto) {
    log.info("time: dt automatic, CFL {} of h/c = {:.4g} s (the stable limit is {:.3g} h/c for {} with {} at {:.3g} "
             "particles per cell), to t = {:.6g} s",
             c.cfl, stable.crossing, stable.factor, scheme.label, Shape::name, stable.particles_per_cell, c.end_time);
  } else {
    log.info("time: dt = {:.6g} s = {:.3g} h/c ({:.3g} of the stable limit {:.3g} h/c for {} with {} at {:.3g} "
             "particles per cell), {} steps to t = {:.6g} s",
             c.dt, c.dt / stable.crossing, c.dt / stable.dt(), stable.factor, scheme.label, Shape::name,
             stable.particles_per_cell, c.steps, c.end_time);
  }
  if (limits.diffusion) log.info("time-step limits: {}", time_step_limits(limits));
}

template <int D, class Shape>
RunSummary run(const Case& c, const RunOptions& options, const std::string& fresh_because = {}) {
  const auto setup_start = Clock::now();
  const Scheme& scheme = scheme_named(c.scheme);
  Simulation<D, Shape> sim(c.system, scheme.wiring, c.dt_auto ? 0.0 : c.dt);
  auto& system = sim.system();
  std::optional<Reference> reference = c.reference;
  if (reference) reference->initialise(system);  // with its own checks, before anything is written
  // From here the output directory is this run's (io/output_lock.hpp), and
  // an interrupt lets the run finish its step.
  const auto& dir = c.output.directory;
  const auto checkpoint_path = dir / checkpoint_file_name;
  // A restart that cannot be made says why before anything is touched.
  std::optional<StateRecords> asked_checkpoint;
  if (options.write_results && options.restart == Restart::from_checkpoint) asked_checkpoint = checkpoint_of(c);
  std::optional<OutputLock> lock;
  std::optional<FinishBeforeExit> finish_before_exit;
  if (options.write_results) {
    lock.emplace(dir, "case " + c.file.string());
    finish_before_exit.emplace();
  }

  RunSummary summary;
  summary.case_name = c.name;
  summary.case_file = c.file.string();
  summary.scheme = scheme.label;
  summary.shape_function = Shape::name;
  summary.velocity_update = c.velocity_update;
  summary.dimension = D;
  summary.threads = options.threads;
  summary.particles = system.particle_count();
  summary.nodes = system.grid.node_count();
  summary.dt = c.dt_auto ? 0.0 : c.dt;
  summary.end_time = c.end_time;

  // Without output.every: about 20 output steps over the run.
  const std::int64_t planned_steps =
      c.dt_auto ? static_cast<std::int64_t>(std::ceil(c.end_time / c.dt)) : c.steps;
  const std::int64_t every = c.output.every > 0 ? c.output.every : std::max<std::int64_t>(1, planned_steps / 20);
  std::int64_t sample_every = 1;
  if (reference && reference->samples() > 0)
    sample_every = std::max<std::int64_t>(1, planned_steps / reference->samples());
  const std::size_t body_count = c.system.bodies.size();
  std::vector<std::string> body_names;
  for (const auto& b : c.system.bodies) body_names.push_back(b.name);
  const std::vector<std::string> reactions = reaction_names(sim.diagnostics(body_count));
  std::vector<std::string> error_names;
  if (reference)
    for (const auto& [name, value] : reference->errors()) error_names.push_back(name);

  // The energy balance (engine/energy_balance.hpp): its change since the
  // start at each recorded step, and the largest energy present so far.
  const Diagnostics initial = sim.diagnostics(body_count);
  double balance_at_start = initial.energy_balance();
  double energy_scale = 0.0, worst_balance_error = 0.0;
  // The guard's energy budget, with a floor for bodies at rest.
  const StableStep stable = stable_time_step(c.system, scheme);
  const double c_max = system.grid.h.minCoeff() / stable.crossing;  // fastest wave speed
  double total_mass = 0.0;
  for (const auto& b : system.batches)
    for (const double m : b.mass) total_mass += m;
  EnergyBudget budget(initial.kinetic_energy + initial.stored_energy + initial.dissipated_energy,
                      0.5 * total_mass * (1e-6 * c_max) * (1e-6 * c_max), c.guard_energy_factor);

  // What the time loop carries from step to step besides the system: the
  // output steps written (results.h5 groups and timeseries.csv rows; the
  // step of the last), the reference's sums, the blow-up guard's last good
  // state and energy budget, the energy balance at the start and its worst
  // error so far, and the time spent so far.
  std::int64_t output_steps = 0, last_written = -1;
  ParticleSnapshot last_good;
  auto visit_loop_state = [&](auto&& f) {
    f("run.output_steps", output_steps);
    f("run.last_written", last_written);
    f("energy.balance_at_start", balance_at_start);
    f("energy.scale", energy_scale);
    f("energy.worst_balance_error", worst_balance_error);
    budget.visit_state(f);
    f("run.step_loop_seconds", summary.step_loop_seconds);
    f("run.output_seconds", summary.output_seconds);
    f("run.reference_seconds", summary.reference_seconds);
    if (reference) reference->visit_state([&](const std::string& name, auto& value) { f("reference." + name, value); });
    // At a step the guard keeps anyway (a multiple of guard_every), the
    // loop keeps it again before the next step: nothing to save.
    const bool kept_next = c.guard_every > 0 && system.step % c.guard_every == 0;
    std::size_t guard_rows = kept_next ? 0 : last_good.count;
    f("guard.count", guard_rows);
    if (guard_rows > 0) {
      if (last_good.count == 0) sim.snapshot_into(last_good, c.output.fields);  // restoring: the fields' layout
      f("guard.step", last_good.step);
      f("guard.time", last_good.time);
      for (SnapshotField& field : last_good.fields) {
        f("guard." + std::string(field.field.name), field.real);
        f("guard." + std::string(field.field.name) + ".integer", field.integer);
      }
    }
  };
  auto output_continuation = [&] {
    ResultsH5::Continuation h5_from{static_cast<std::size_t>(output_steps), last_written, {}};
    for (const SnapshotField& f : sim.snapshot(c.output.fields).fields) h5_from.fields.push_back(f.field);
    return std::pair(h5_from, TimeseriesCsv::Continuation{static_cast<std::size_t>(output_steps), last_written});
  };

  // A restart: the checkpoint restored and the output files checked before
  // anything is written. A case that may restart (a sweep's) starts afresh
  // when its checkpoint does not fit.
  const bool restart = options.write_results && (options.restart == Restart::from_checkpoint ||
                                                 (options.restart == Restart::if_checkpoint &&
                                                  std::filesystem::exists(checkpoint_path)));
  if (restart) {
    try {
      const StateRecords records = asked_checkpoint ? std::move(*asked_checkpoint) : checkpoint_of(c);
      try {
        restore_carried_state(records, system);
        visit_loop_state(StateReader(records));
      } catch (const std::runtime_error& e) {
        throw CaseError(checkpoint_path.string() + ": does not fit this case: " + e.what());
      }
      const auto [h5_from, csv_from] = output_continuation();
      try {
        ResultsH5::check_continuation(dir / "results.h5", h5_from);
        TimeseriesCsv::kept_text(dir / "timeseries.csv", body_names, reactions, error_names, csv_from);
      } catch (const std::runtime_error& e) {
        throw CaseError(e.what());
      }
    } catch (const CaseError& e) {
      if (options.restart == Restart::from_checkpoint) throw;
      RunOptions fresh = options;
      fresh.restart = Restart::no;
      finish_before_exit.reset();
      lock.reset();  // the fresh run takes it again
      return run<D, Shape>(c, fresh, e.what());
    }
  }

  // The directory marked as this run's (summary.json "running"); a fresh
  // run removes the earlier run's results, a restart continues them.
  if (options.write_results) {
    summary.status = "running";
    if (restart) {
      remove_stale_temporaries(dir);
      write_summary(dir / "summary.json", summary);
    } else {
      start_output(dir, summary);
    }
    summary.status = "completed";
  }
  const auto log = run_logger(options.write_results ? std::optional(dir / "run.log") : std::nullopt,
                              options.log_to_console, !restart);
  log->info("case '{}' from {}, {} thread{}, output in {}", c.name, c.file.string(), options.threads,
            options.threads == 1 ? "" : "s", options.write_results ? dir.string() : "(none)");
  log_system(*log, c, sim, scheme);
  if (restart) {
    log->info("restart from the checkpoint at step {} (t = {:.6g} s), {}; results.h5, results.xdmf and "
              "timeseries.csv continue after its output step {}",
              system.step, system.t, checkpoint_path.string(), last_written);
  } else if (options.write_results && std::filesystem::exists(checkpoint_path)) {
    log->warn("{}: a checkpoint of an earlier run in the output directory{}; this run starts afresh and replaces it",
              checkpoint_path.string(), fresh_because.empty() ? "" : " (" + fresh_because + ")");
    std::filesystem::remove(checkpoint_path);
  }
  summary.setup_seconds = options.setup_seconds + seconds_since(setup_start);

  auto sample_reference = [&] {
    const auto t0 = Clock::now();
    reference->sample(system);
    summary.reference_seconds += seconds_since(t0);
  };
  if (reference) {
    if (!restart) sample_reference();
    log->info("reference: {} (errors sampled every {} step{})", reference->type(), sample_every,
                 sample_every == 1 ? "" : "s");
  }

  std::optional<ResultsH5> h5;
  std::optional<ResultsIndex> index;
  std::optional<TimeseriesCsv> csv;
  if (options.write_results) {
    ResultsMetadata metadata{FLOWMPM_VERSION, source_commit(), c.name, c.file.string(), D,
                             stress_state_name(system.stress_state), scheme.label, Shape::name, {}};
    for (const NamedMaterial& m : c.system.materials) metadata.materials.push_back(m.name);
    if (restart) {
      const auto [h5_from, csv_from] = output_continuation();
      h5.emplace(dir / "results.h5", metadata, h5_from);
      csv.emplace(dir / "timeseries.csv", body_names, reactions, error_names, csv_from);
    } else {
      h5.emplace(dir / "results.h5", metadata);
      csv.emplace(dir / "timeseries.csv", body_names, reactions, error_names);
    }
    index.emplace(dir / "results.xdmf");
    if (restart) index->finish(*h5);  // without the steps written after the checkpoint
  }
  auto balance_error = [&](const Diagnostics& d) {
    const double error = d.energy_balance() - balance_at_start;
    energy_scale = std::max({energy_scale, d.kinetic_energy + d.stored_energy + d.dissipated_energy,
                             std::abs(d.work.gravity), std::abs(d.work.boundary), std::abs(d.work.expansion),
                             std::abs(d.work.load)});
    worst_balance_error = std::max(worst_balance_error, std::abs(error));
    return error;
  };
  auto write_output = [&] {
    const auto t0 = Clock::now();
    const Diagnostics row = sim.diagnostics(body_count);
    const double error = balance_error(row);
    if (options.write_results) {
      h5->write(sim.snapshot(c.output.fields));
      index->update(*h5);
      // The error norms so far: over the particles and the samples up to now.
      std::vector<double> errors;
      if (reference)
        for (const auto& [name, value] : reference->errors()) errors.push_back(value);
      csv->write(row, error, errors);
    }
    ++output_steps;
    summary.output_seconds += seconds_since(t0);
  };
  auto write_checkpoint_now = [&] {
    const auto t0 = Clock::now();
    StateRecords records;
    StateWriter write(records);
    write("case.digest", c.digest);
    write("case.name", c.name);
    write("case.file", c.file.string());
    write("case.overrides", overrides_text(c));
    save_carried_state(system, records);
    visit_loop_state(write);
    write_checkpoint(checkpoint_path, records);
    summary.output_seconds += seconds_since(t0);
  };
  auto finish = [&](const std::string& status) {
    summary.status = status;
    summary.steps = system.step;
    summary.particle_steps_per_second =
        summary.step_loop_seconds > 0.0
            ? static_cast<double>(summary.particles) * static_cast<double>(system.step) / summary.step_loop_seconds
            : 0.0;
    const Diagnostics final_state = sim.diagnostics(body_count);
    balance_error(final_state);
    summary.bodies.clear();
    for (std::size_t i = 0; i < body_count; ++i) {
      summary.bodies.push_back(
          {c.system.bodies[i].name, final_state.bodies[i].stress, final_state.bodies[i].strain});
    }
    if (reference) {
      summary.errors = reference->errors();
      summary.measures = reference->measures();
    }
    if (system.damping) summary.damping_dissipated = system.damping_dissipated;
    summary.kinetic_energy = final_state.kinetic_energy;
    summary.stored_energy = final_state.stored_energy;
    summary.dissipated_energy = final_state.dissipated_energy;
    summary.gravity_work = final_state.work.gravity;
    summary.boundary_work = final_state.work.boundary;
    summary.expansion_work = final_state.work.expansion;
    summary.load_work = final_state.work.load;
    summary.energy_error = energy_scale > 0.0 ? worst_balance_error / energy_scale
                                              : std::numeric_limits<double>::quiet_NaN();
    if (options.write_results) {
      index->finish(*h5);
      write_summary(dir / "summary.json", summary);
    }
  };

  // Blow-up guard: the state is kept every guard_every steps so that the
  // last one that passed can be written when the run breaks down.
  const double speed_limit = c.guard_speed_factor * c_max;
  auto check_guard = [&] {
    const double limit = budget.limit(system.work);
    if (system.kinetic_energy > limit) {
      throw SimulationError(fmt::format(
          "blow-up at step {} (t = {:.6g} s): the kinetic energy, {:.4g} J, is more than {:g} times the initial "
          "energy plus the most work done on the bodies, {:.4g} J (analysis.guard_energy_factor); the fastest: {}",
          system.step, system.t, system.kinetic_energy, budget.factor(), limit / budget.factor(),
          sim.fastest_particle(body_names)));
    }
    if (system.max_speed_sq <= speed_limit * speed_limit) return;
    throw SimulationError(fmt::format("blow-up at step {} (t = {:.6g} s): {}, more than {:g} times the fastest "
                                      "wave speed, {:.4g} m/s (analysis.guard_speed_factor)",
                                      system.step, system.t, sim.fastest_particle(body_names),
                                      c.guard_speed_factor, c_max));
  };
  auto write_last_good = [&] {
    if (!options.write_results) return std::string();
    if (last_good.count == 0 || last_good.step <= last_written) {
      return fmt::format("; the last good state written is step {} in results.h5", last_written);
    }
    h5->write(last_good);
    return fmt::format("; the last good state (step {}, t = {:.6g} s) is the last step in results.h5",
                       last_good.step, last_good.time);
  };
  // What may run a case that broke down (docs/STABILITY.md).
  std::string remedy = "; a smaller time step may run it (analysis.dt, or analysis.cfl with dt = \"auto\")";
  if (Shape::gradient_jumps && scheme.wiring.stress_from_updated_grid())
    remedy += ", or scheme = \"musl\", or shape_function = \"gimp\" or \"bspline2\": linear shape functions "
              "with USL are the least stable pair where the material's edge moves (docs/STABILITY.md)";
  auto done = [&] { return c.dt_auto ? system.t >= c.end_time * (1.0 - 1e-12) : system.step >= c.steps; };
  const std::optional<DiffusionStep> diffusion = diffusion_time_step(c.system);
  const double diffusion_dt = diffusion ? c.cfl / stable.factor * diffusion->dt : 0.0;
  auto next_dt = [&] {
    if (!c.dt_auto) return c.dt;
    // CFL condition with the particles' own speed added to the wave speed,
    // and the explicit diffusion limit (the same fraction of it as the CFL
    // number is of the wave limit).
    double dt = c.cfl * system.grid.h.minCoeff() / (c_max + std::sqrt(system.max_speed_sq));
    if (diffusion) dt = std::min(dt, diffusion_dt);
    return std::min(dt, c.end_time - system.t);
  };
  if (!restart) sim.measure_speed();
  auto last_progress = Clock::now();
  const auto loop_start = Clock::now();
  const double loop_start_time = system.t;
  try {
    if (!restart) {
      write_output();
      last_written = system.step;
    }
    while (!done()) {
      if (options.interrupt && options.interrupt->load()) {
        std::string checkpoint;
        if (options.write_results) {
          write_checkpoint_now();
          checkpoint = "; continue it with " + restart_command(c);
        }
        if (system.step != last_written) write_output();
        finish("interrupted at step " + std::to_string(system.step));
        throw SimulationError("interrupted at step " + std::to_string(system.step) + " (t = " +
                              std::to_string(system.t) + " s); results up to this step are written" + checkpoint);
      }
      if (c.guard_every > 0 && system.step % c.guard_every == 0) sim.snapshot_into(last_good, c.output.fields);
      system.dt = next_dt();
      const auto t0 = Clock::now();
      try {
        sim.advance();
      } catch (const SimulationError&) {
        throw;
      } catch (const std::exception& e) {
        // A stage threw (e.g. a material's return mapping did not converge).
        throw SimulationError(fmt::format("step {} (t = {:.6g} s): {}", system.step + 1, system.t, e.what()));
      }
      summary.step_loop_seconds += seconds_since(t0);
      check_guard();
      const bool last = done();
      if (reference && (system.step % sample_every == 0 || last)) sample_reference();
      if (system.step % every == 0 || last) {
        write_output();
        last_written = system.step;
      }
      if (options.write_results && c.output.checkpoint_every > 0 && system.step % c.output.checkpoint_every == 0 &&
          !last) {
        write_checkpoint_now();
      }
      if (seconds_since(last_progress) >= options.progress_seconds) {
        last_progress = Clock::now();
        const double rate = static_cast<double>(summary.particles) * static_cast<double>(system.step) /
                            summary.step_loop_seconds;
        const double fraction = system.t / c.end_time;
        // The ETA from this session's pace (a restart begins part way).
        const double eta = seconds_since(loop_start) * (c.end_time - system.t) / (system.t - loop_start_time);
        log->info("step {} ({:.0f}%), t = {:.6g} s, dt = {:.3g} s, {:.3g} particle-steps/s, ETA {:.0f} s",
                     system.step, 100.0 * fraction, system.t, system.dt, rate, eta);
      }
    }
  } catch (const SimulationError& e) {
    if (summary.status == "completed") {
      const std::string message = e.what() + write_last_good() + remedy;
      finish("failed: " + message);
      log->error("{}", message);
      throw SimulationError(message);
    }
    log->error("{}", e.what());
    throw;
  } catch (const std::exception& e) {
    // An output file could not be written (a full disk) or memory ran out:
    // one line naming what failed; the summary says so if it can still be
    // written, and what was written before stays readable.
    const std::string message =
        fmt::format("step {} (t = {:.6g} s): {}", system.step, system.t, failure_text(e));
    log->error("{}", message);
    try {
      finish("failed: " + message);
    } catch (const std::exception&) {
      // The disk that failed the output may fail the summary too.
    }
    throw SimulationError(message);
  }
  finish("completed");
  if (system.nonlocal.unsettled_steps > 0) {
    log->warn("the nonlocal averages did not settle in {} of {} steps (tasks/nonlocal_settle.hpp): a softening band "
              "as wide as its model allows; refine the grid", system.nonlocal.unsettled_steps, system.step);
  }
  log->info("done: {} steps, {} particles, {:.3f} s in the step loop, {:.4g} particle-steps/s (set-up {:.3f} s, "
            "output {:.3f} s), particles sorted {} times",
            summary.steps, summary.particles, summary.step_loop_seconds, summary.particle_steps_per_second,
            summary.setup_seconds, summary.output_seconds, system.sorts);
  for (const auto& b : summary.bodies) {
    log->info("body '{}' at t = {:.6g} s: mean stress xx {:.6g} yy {:.6g} zz {:.6g} Pa, mean strain xx {:.6g} "
              "yy {:.6g} zz {:.6g}",
              b.name, system.t, b.mean_stress[0], b.mean_stress[1], b.mean_stress[2], b.mean_strain[0],
              b.mean_strain[1], b.mean_strain[2]);
  }
  log->info("energy at the end: kinetic {:.6g} J, stored {:.6g} J, dissipated {:.6g} J; work done by gravity "
            "and body forces {:.6g} J, by the constraints {:.6g} J, by the expansion strains {:.6g} J, by the loads "
            "{:.6g} J; balance error {:.3g} of the largest energy present",
            summary.kinetic_energy, summary.stored_energy, summary.dissipated_energy, summary.gravity_work,
            summary.boundary_work, summary.expansion_work, summary.load_work, summary.energy_error);
  for (const auto& [name, value] : summary.errors) {
    log->info("error against the {} reference: {} = {:.4g}", reference->type(), name, value);
  }
  for (const auto& [name, value] : summary.measures) {
    log->info("measured by the {} reference: {} = {:.6g}", reference->type(), name, value);
  }
  if (summary.damping_dissipated) log->info("energy dissipated by damping: {:.6g} J", *summary.damping_dissipated);
  return summary;
}

template <int D>
RunSummary run_case_in(const Case& c, const RunOptions& options) {
  return with_shape_function(c.system.shape_function, [&]<class Shape>() { return run<D, Shape>(c, options); });
}

template <int D>
void describe_case_in(const Case& c) {
  with_shape_function(c.system.shape_function, [&]<class Shape>() {
    const Scheme& scheme = scheme_named(c.scheme);
    Simulation<D, Shape> sim(c.system, scheme.wiring, c.dt_auto ? 0.0 : c.dt);
    if (c.reference) c.reference->initialise(sim.system());
    log_system(*spdlog::default_logger(), c, sim, scheme);
  });
}

}  // namespace flowmpm::run_internal
