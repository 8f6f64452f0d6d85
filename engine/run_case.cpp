#include "engine/run_case.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include <spdlog/spdlog.h>

#include "engine/reference/reference.hpp"
#include "engine/shape_bspline.hpp"
#include "engine/shape_gimp.hpp"
#include "engine/shape_linear.hpp"
#include "engine/simulation.hpp"
#include "io/case_reader.hpp"
#include "io/results_h5.hpp"
#include "io/xdmf.hpp"

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

template <int D, class Shape>
void log_model(const Case& c, const Model<D, Shape>& model, const Wiring& wiring) {
  spdlog::info("model: {}D ({}), scheme {} [{}], shape function {}, velocity update {}{}", D,
               stress_state_name(model.stress_state), scheme_name(c.scheme),
               wiring.describe(), Shape::name, c.velocity_update,
               c.velocity_update == "blend" ? " (FLIP fraction " + std::to_string(c.flip_fraction) + ")" : "");
  std::string cells;
  for (int d = 0; d < D; ++d) cells += (d ? " x " : "") + std::to_string(model.grid.cells[d]);
  spdlog::info("grid: {} cells, {} nodes, {} blocks of {}^{} cells ({} occupied)", cells,
               model.grid.node_count(), model.blocks.block_count, BlockLayout<D, Shape>::block_cells, D,
               model.blocks.occupied.size());
  for (const auto& b : model.batches) {
    const auto& m = c.materials[b.material];
    spdlog::info("body '{}': {} particles, material '{}' ({}, density {} kg/m^3, wave speed {:.4g} m/s)",
                 c.bodies[b.body].name, b.size(), m.name, type_name(m.model), density(m.model),
                 wave_speed(m.model));
  }
  spdlog::info("particle fields stored: {}", stored_fields(D));
  for (const auto& k : model.constraints) {
    spdlog::info("node set '{}': {} nodes, velocity prescribed along {}", k.name, k.nodes.size(),
                 "xyz"[k.axis]);
  }
  if (model.gravity.norm() > 0.0) spdlog::info("gravity: {} m/s^2", model.gravity.norm());
  const StableStep stable = stable_time_step(c);
  if (c.dt_auto) {
    spdlog::info("time: dt automatic, CFL {} (first step {:.4g} s; the stable limit at rest is {:.4g} s), to t = {} s",
                 c.cfl, c.dt, stable.dt, c.end_time);
  } else {
    spdlog::info("time: dt = {} s ({:.3g} of the stable limit {:.4g} s), {} steps to t = {} s", c.dt,
                 c.dt / stable.dt, stable.dt, c.steps, c.end_time);
  }
}

template <int D, class Shape>
RunSummary run(const Case& c, const RunOptions& options) {
  const auto setup_start = Clock::now();
  Simulation<D, Shape> sim(c);
  auto& model = sim.model();
  log_model(c, model, sim.graph().wiring());

  RunSummary summary;
  summary.case_name = c.name;
  summary.case_file = c.file.string();
  summary.scheme = scheme_name(c.scheme);
  summary.shape_function = Shape::name;
  summary.velocity_update = c.velocity_update;
  summary.dimension = D;
  summary.threads = options.threads;
  summary.particles = model.particle_count();
  summary.nodes = model.grid.node_count();
  summary.dt = c.dt_auto ? 0.0 : c.dt;
  summary.end_time = c.end_time;
  summary.setup_seconds = options.setup_seconds + seconds_since(setup_start);

  // Without output.every: about 20 output steps over the run.
  const std::int64_t planned_steps =
      c.dt_auto ? static_cast<std::int64_t>(std::ceil(c.end_time / c.dt)) : c.steps;
  const std::int64_t every = c.output.every > 0 ? c.output.every : std::max<std::int64_t>(1, planned_steps / 20);
  std::optional<Reference> reference;
  std::int64_t sample_every = 1;
  auto sample_reference = [&] {
    const auto t0 = Clock::now();
    reference->sample(model);
    summary.reference_seconds += seconds_since(t0);
  };
  if (!c.reference.type.empty()) {
    reference.emplace(c.reference);
    reference->initialise(model, c.end_time);
    if (c.reference.samples > 0) sample_every = std::max<std::int64_t>(1, planned_steps / c.reference.samples);
    sample_reference();
    spdlog::info("reference: {} (errors sampled every {} step{})", c.reference.type, sample_every,
                 sample_every == 1 ? "" : "s");
  }

  const auto& dir = c.output.directory;
  std::vector<std::string> body_names;
  for (const auto& b : c.bodies) body_names.push_back(b.name);
  std::optional<ResultsH5> h5;
  std::optional<TimeseriesCsv> csv;
  if (options.write_results) {
    std::error_code error;
    std::filesystem::create_directories(dir, error);
    if (error) {
      throw CaseError("output directory " + dir.string() + ": cannot create it (" + error.message() +
                      "); set output.directory or --output");
    }
    h5.emplace(dir / "results.h5", c.output.fields);
    std::vector<std::string> error_names;
    if (reference)
      for (const auto& [name, value] : reference->errors()) error_names.push_back(name);
    csv.emplace(dir / "timeseries.csv", body_names, error_names);
  }
  auto write_output = [&] {
    const auto t0 = Clock::now();
    if (options.write_results) {
      h5->write(sim.snapshot());
      write_xdmf(dir / "results.xdmf", "results.h5", *h5);
      TimeseriesRow row = sim.diagnostics(c.bodies.size());
      // The error norms so far: over the particles and the samples up to now.
      if (reference)
        for (const auto& [name, value] : reference->errors()) row.errors.push_back(value);
      csv->write(row);
    }
    summary.output_seconds += seconds_since(t0);
  };
  auto finish = [&](const std::string& status) {
    summary.status = status;
    summary.steps = model.step;
    summary.particle_steps_per_second =
        summary.step_loop_seconds > 0.0
            ? static_cast<double>(summary.particles) * static_cast<double>(model.step) / summary.step_loop_seconds
            : 0.0;
    const TimeseriesRow final_state = sim.diagnostics(c.bodies.size());
    summary.bodies.clear();
    for (std::size_t i = 0; i < c.bodies.size(); ++i) {
      summary.bodies.push_back({c.bodies[i].name, final_state.bodies[i].stress, final_state.bodies[i].strain});
    }
    if (reference) summary.errors = reference->errors();
    summary.energy_final = final_state.kinetic_energy + final_state.strain_energy;
    if (options.write_results) write_summary(dir / "summary.json", summary);
  };

  // Blow-up guard: the state is kept every guard_every steps so that the
  // last one that passed can be written when the run breaks down.
  ParticleSnapshot last_good;
  std::int64_t last_written = -1;
  const StableStep stable = stable_time_step(c);
  const double c_max = model.grid.h.minCoeff() / stable.dt;  // fastest wave speed
  const double speed_limit = c.guard_speed_factor * c_max;
  auto check_guard = [&] {
    if (model.max_speed_sq <= speed_limit * speed_limit) return;
    throw SimulationError(fmt::format("blow-up at step {} (t = {:.6g} s): {}, more than {:g} times the fastest "
                                      "wave speed, {:.4g} m/s (analysis.guard_speed_factor)",
                                      model.step, model.t, sim.fastest_particle(), c.guard_speed_factor, c_max));
  };
  auto write_last_good = [&] {
    if (!options.write_results) return std::string();
    if (last_good.count == 0 || last_good.step <= last_written) {
      return fmt::format("; the last good state written is step {} in results.h5", last_written);
    }
    h5->write(last_good);
    write_xdmf(dir / "results.xdmf", "results.h5", *h5);
    return fmt::format("; the last good state (step {}, t = {:.6g} s) is the last step in results.h5",
                       last_good.step, last_good.time);
  };
  auto done = [&] { return c.dt_auto ? model.t >= c.end_time * (1.0 - 1e-12) : model.step >= c.steps; };
  auto next_dt = [&] {
    if (!c.dt_auto) return c.dt;
    // CFL condition with the particles' own speed added to the wave speed.
    const double dt = c.cfl * model.grid.h.minCoeff() / (c_max + std::sqrt(model.max_speed_sq));
    return std::min(dt, c.end_time - model.t);
  };
  const TimeseriesRow initial = sim.diagnostics(c.bodies.size());
  summary.energy_initial = initial.kinetic_energy + initial.strain_energy;
  sim.measure_speed();

  write_output();
  last_written = model.step;
  auto last_progress = Clock::now();
  const auto loop_start = Clock::now();
  try {
    while (!done()) {
      if (options.interrupt && options.interrupt->load()) {
        if (model.step != last_written) write_output();
        finish("interrupted at step " + std::to_string(model.step));
        throw SimulationError("interrupted at step " + std::to_string(model.step) + " (t = " +
                              std::to_string(model.t) + " s); results up to this step are written");
      }
      if (c.guard_every > 0 && model.step % c.guard_every == 0) sim.snapshot_into(last_good);
      model.dt = next_dt();
      const auto t0 = Clock::now();
      try {
        sim.advance();
      } catch (const SimulationError&) {
        throw;
      } catch (const std::exception& e) {
        // A stage threw (e.g. a material's return mapping did not converge).
        throw SimulationError(fmt::format("step {} (t = {:.6g} s): {}", model.step + 1, model.t, e.what()));
      }
      summary.step_loop_seconds += seconds_since(t0);
      check_guard();
      const bool last = done();
      if (reference && (model.step % sample_every == 0 || last)) sample_reference();
      if (model.step % every == 0 || last) {
        write_output();
        last_written = model.step;
      }
      if (seconds_since(last_progress) >= options.progress_seconds) {
        last_progress = Clock::now();
        const double rate = static_cast<double>(summary.particles) * static_cast<double>(model.step) /
                            summary.step_loop_seconds;
        const double fraction = model.t / c.end_time;
        const double eta = seconds_since(loop_start) * (1.0 - fraction) / fraction;
        spdlog::info("step {} ({:.0f}%), t = {:.6g} s, dt = {:.3g} s, {:.3g} particle-steps/s, ETA {:.0f} s",
                     model.step, 100.0 * fraction, model.t, model.dt, rate, eta);
      }
    }
  } catch (const SimulationError& e) {
    if (summary.status == "completed") {
      const std::string message = e.what() + write_last_good();
      finish("failed: " + message);
      throw SimulationError(message);
    }
    throw;
  }
  finish("completed");
  return summary;
}

// Calls f.template operator()<D, Shape>() for the case's dimension and
// shape function: the one dispatch from run-time choices to compiled code.
template <class F>
auto dispatch(const Case& c, F&& f) {
  auto by_shape = [&]<int D>() {
    if (c.shape_function == "gimp") return f.template operator()<D, GimpShape>();
    if (c.shape_function == "bspline2") return f.template operator()<D, QuadraticBSpline>();
    if (c.shape_function == "bspline3") return f.template operator()<D, CubicBSpline>();
    return f.template operator()<D, LinearShape>();
  };
  switch (c.dimension) {
    case 1: return by_shape.template operator()<1>();
    case 2: return by_shape.template operator()<2>();
    default: return by_shape.template operator()<3>();
  }
}

}  // namespace

RunSummary run_case(const Case& c, const RunOptions& options) {
  return dispatch(c, [&]<int D, class Shape>() { return run<D, Shape>(c, options); });
}

void describe_case(const Case& c) {
  dispatch(c, [&]<int D, class Shape>() {
    Simulation<D, Shape> sim(c);
    log_model(c, sim.model(), sim.graph().wiring());
  });
}

}  // namespace flowmpm
