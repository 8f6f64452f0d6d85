#include "app/run_case.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include <spdlog/sinks/basic_file_sink.h>
#include <spdlog/sinks/dist_sink.h>
#include <spdlog/spdlog.h>

#include "app/interrupt.hpp"
#include "core/errors.hpp"
#include "core/number_text.hpp"
#include "discretisation/shape_functions.hpp"
#include "engine/schemes.hpp"
#include "engine/simulation.hpp"
#include "engine/stable_time_step.hpp"
#include "io/memory_estimate.hpp"
#include "io/output_lock.hpp"
#include "io/results_h5.hpp"
#include "io/timeseries_csv.hpp"
#include "io/xdmf.hpp"

#include "flowmpm_build_info.hpp"

namespace flowmpm {
namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

std::string stored_fields(int dimension) {
  const std::string vec = dimension == 1 ? "scalar" : std::to_string(dimension) + "-vector";
  return "x, v (" + vec + "), mass, volume, stress, strain (6 Voigt)";
}

// The run's logger: with `console`, the program's console output at the
// level the default logger has (through a sink of its own that filters at
// that level), and with `file`, every info line in that file (run.log).
std::shared_ptr<spdlog::logger> run_logger(const std::optional<std::filesystem::path>& file, bool console) {
  const auto& program = spdlog::default_logger();
  std::vector<spdlog::sink_ptr> sinks;
  if (console) {
    sinks.push_back(std::make_shared<spdlog::sinks::dist_sink_mt>(program->sinks()));
    sinks.back()->set_level(program->level());
  }
  if (file) {
    try {
      sinks.push_back(std::make_shared<spdlog::sinks::basic_file_sink_mt>(file->string(), true));
    } catch (const spdlog::spdlog_ex& e) {
      throw std::runtime_error("cannot write " + file->string() + ": " + e.what());
    }
    sinks.back()->set_level(spdlog::level::info);
  }
  auto log = std::make_shared<spdlog::logger>("run", sinks.begin(), sinks.end());
  log->set_level(std::min(program->level(), spdlog::level::info));
  log->set_pattern("[%H:%M:%S.%e] %^%l%$ %v");
  log->flush_on(spdlog::level::info);
  return log;
}

template <int D, class Shape>
void log_system(spdlog::logger& log, const Case& c, const DiscreteSystem<D, Shape>& system, const Scheme& scheme) {
  log.info("model: {}D ({}), scheme {} [{}], shape function {}, velocity update {}{}", D,
               stress_state_name(system.stress_state), scheme.label, scheme.wiring.describe(), Shape::name,
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
  log.info("particle fields stored: {}", stored_fields(D));
  for (const auto& k : system.constraints) {
    log.info("node set '{}': {} nodes, velocity prescribed along {}", k.name, k.nodes.size(),
                 "xyz"[k.axis]);
  }
  if (system.gravity.norm() > 0.0) log.info("gravity: {} m/s^2", system.gravity.norm());
  const MemoryEstimate estimate = estimate_memory(c);
  log.info("{}", estimate_text(estimate));
  if (estimate.steps > long_run_steps) {
    log.warn("a long run: {:.3g} steps (more than {:.0e})", estimate.steps, long_run_steps);
  }
  const StableStep stable = stable_time_step(c.system, scheme);
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
}

template <int D, class Shape>
RunSummary run(const Case& c, const RunOptions& options) {
  const auto setup_start = Clock::now();
  const Scheme& scheme = scheme_named(c.scheme);
  Simulation<D, Shape> sim(c.system, scheme.wiring, c.dt_auto ? 0.0 : c.dt);
  auto& system = sim.system();
  std::optional<Reference> reference = c.reference;
  if (reference) reference->initialise(system);  // with its own checks, before anything is written
  // From here the output directory is this run's (io/output_lock.hpp), and
  // an interrupt lets the run finish its step.
  const auto& dir = c.output.directory;
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
  summary.setup_seconds = options.setup_seconds + seconds_since(setup_start);
  if (options.write_results) {
    summary.status = "running";
    start_output(dir, summary);
    summary.status = "completed";
  }
  const auto log = run_logger(options.write_results ? std::optional(dir / "run.log") : std::nullopt,
                              options.log_to_console);
  log->info("case '{}' from {}, {} thread{}, output in {}", c.name, c.file.string(), options.threads,
            options.threads == 1 ? "" : "s", options.write_results ? dir.string() : "(none)");
  log_system(*log, c, system, scheme);

  // Without output.every: about 20 output steps over the run.
  const std::int64_t planned_steps =
      c.dt_auto ? static_cast<std::int64_t>(std::ceil(c.end_time / c.dt)) : c.steps;
  const std::int64_t every = c.output.every > 0 ? c.output.every : std::max<std::int64_t>(1, planned_steps / 20);
  std::int64_t sample_every = 1;
  auto sample_reference = [&] {
    const auto t0 = Clock::now();
    reference->sample(system);
    summary.reference_seconds += seconds_since(t0);
  };
  if (reference) {
    if (reference->samples() > 0) sample_every = std::max<std::int64_t>(1, planned_steps / reference->samples());
    sample_reference();
    log->info("reference: {} (errors sampled every {} step{})", reference->type(), sample_every,
                 sample_every == 1 ? "" : "s");
  }

  const std::size_t body_count = c.system.bodies.size();
  std::vector<std::string> body_names;
  for (const auto& b : c.system.bodies) body_names.push_back(b.name);
  std::optional<ResultsH5> h5;
  std::optional<XdmfIndex> xdmf;
  std::optional<TimeseriesCsv> csv;
  if (options.write_results) {
    ResultsMetadata metadata{FLOWMPM_VERSION, FLOWMPM_COMMIT, c.name, c.file.string(), D,
                             stress_state_name(system.stress_state), scheme.label, Shape::name, {}};
    for (const NamedMaterial& m : c.system.materials) metadata.materials.push_back(m.name);
    h5.emplace(dir / "results.h5", metadata);
    xdmf.emplace(dir / "results.xdmf", "results.h5");
    std::vector<std::string> error_names;
    if (reference)
      for (const auto& [name, value] : reference->errors()) error_names.push_back(name);
    csv.emplace(dir / "timeseries.csv", body_names, reaction_names(sim.diagnostics(body_count)), error_names);
  }
  auto write_output = [&] {
    const auto t0 = Clock::now();
    if (options.write_results) {
      h5->write(sim.snapshot(c.output.fields));
      xdmf->update(*h5);
      // The error norms so far: over the particles and the samples up to now.
      std::vector<double> errors;
      if (reference)
        for (const auto& [name, value] : reference->errors()) errors.push_back(value);
      csv->write(sim.diagnostics(body_count), errors);
    }
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
    summary.bodies.clear();
    for (std::size_t i = 0; i < body_count; ++i) {
      summary.bodies.push_back(
          {c.system.bodies[i].name, final_state.bodies[i].stress, final_state.bodies[i].strain});
    }
    if (reference) summary.errors = reference->errors();
    summary.energy_final = final_state.kinetic_energy + final_state.strain_energy;
    if (options.write_results) {
      xdmf->finish(*h5);
      write_summary(dir / "summary.json", summary);
    }
  };

  // Blow-up guard: the state is kept every guard_every steps so that the
  // last one that passed can be written when the run breaks down.
  ParticleSnapshot last_good;
  std::int64_t last_written = -1;
  const StableStep stable = stable_time_step(c.system, scheme);
  const double c_max = system.grid.h.minCoeff() / stable.crossing;  // fastest wave speed
  const double speed_limit = c.guard_speed_factor * c_max;
  auto check_guard = [&] {
    if (system.max_speed_sq <= speed_limit * speed_limit) return;
    throw SimulationError(fmt::format("blow-up at step {} (t = {:.6g} s): {}, more than {:g} times the fastest "
                                      "wave speed, {:.4g} m/s (analysis.guard_speed_factor)",
                                      system.step, system.t, sim.fastest_particle(), c.guard_speed_factor, c_max));
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
  auto done = [&] { return c.dt_auto ? system.t >= c.end_time * (1.0 - 1e-12) : system.step >= c.steps; };
  auto next_dt = [&] {
    if (!c.dt_auto) return c.dt;
    // CFL condition with the particles' own speed added to the wave speed.
    const double dt = c.cfl * system.grid.h.minCoeff() / (c_max + std::sqrt(system.max_speed_sq));
    return std::min(dt, c.end_time - system.t);
  };
  const Diagnostics initial = sim.diagnostics(body_count);
  summary.energy_initial = initial.kinetic_energy + initial.strain_energy;
  sim.measure_speed();

  auto last_progress = Clock::now();
  const auto loop_start = Clock::now();
  try {
    write_output();
    last_written = system.step;
    while (!done()) {
      if (options.interrupt && options.interrupt->load()) {
        if (system.step != last_written) write_output();
        finish("interrupted at step " + std::to_string(system.step));
        throw SimulationError("interrupted at step " + std::to_string(system.step) + " (t = " +
                              std::to_string(system.t) + " s); results up to this step are written");
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
      if (seconds_since(last_progress) >= options.progress_seconds) {
        last_progress = Clock::now();
        const double rate = static_cast<double>(summary.particles) * static_cast<double>(system.step) /
                            summary.step_loop_seconds;
        const double fraction = system.t / c.end_time;
        const double eta = seconds_since(loop_start) * (1.0 - fraction) / fraction;
        log->info("step {} ({:.0f}%), t = {:.6g} s, dt = {:.3g} s, {:.3g} particle-steps/s, ETA {:.0f} s",
                     system.step, 100.0 * fraction, system.t, system.dt, rate, eta);
      }
    }
  } catch (const SimulationError& e) {
    if (summary.status == "completed") {
      const std::string message = e.what() + write_last_good();
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
  log->info("done: {} steps, {} particles, {:.3f} s in the step loop, {:.4g} particle-steps/s (set-up {:.3f} s, "
            "output {:.3f} s)",
            summary.steps, summary.particles, summary.step_loop_seconds, summary.particle_steps_per_second,
            summary.setup_seconds, summary.output_seconds);
  for (const auto& b : summary.bodies) {
    log->info("body '{}' at t = {:.6g} s: mean stress xx {:.6g} yy {:.6g} zz {:.6g} Pa, mean strain xx {:.6g} "
              "yy {:.6g} zz {:.6g}",
              b.name, system.t, b.mean_stress[0], b.mean_stress[1], b.mean_stress[2], b.mean_strain[0],
              b.mean_strain[1], b.mean_strain[2]);
  }
  if (summary.energy_initial > 0.0) {
    log->info("energy (kinetic + strain): {:.6g} J at the start, {:.6g} J at the end, drift {:+.3g} %",
              summary.energy_initial, summary.energy_final, 100.0 * summary.energy_drift());
  }
  for (const auto& [name, value] : summary.errors) {
    log->info("error against the {} reference: {} = {:.4g}", reference->type(), name, value);
  }
  return summary;
}

}  // namespace

std::string failure_text(const std::exception& e) {
  if (dynamic_cast<const std::bad_alloc*>(&e)) return "out of memory (std::bad_alloc)";
  return e.what();
}

RunSummary run_case(const Case& c, const RunOptions& options) {
  return with_dimension_and_shape(c.system.dimension, c.system.shape_function,
                                  [&]<int D, class Shape>() { return run<D, Shape>(c, options); });
}

void describe_case(const Case& c) {
  with_dimension_and_shape(c.system.dimension, c.system.shape_function, [&]<int D, class Shape>() {
    const Scheme& scheme = scheme_named(c.scheme);
    Simulation<D, Shape> sim(c.system, scheme.wiring, c.dt_auto ? 0.0 : c.dt);
    if (c.reference) c.reference->initialise(sim.system());
    log_system(*spdlog::default_logger(), c, sim.system(), scheme);
  });
}

}  // namespace flowmpm
