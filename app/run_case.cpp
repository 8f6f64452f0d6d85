// The time loop of a run: start or resume, step, the after-step services,
// finish. The services (app/run_services.hpp) each own one job: the
// reference sampler, the energy balance, the blow-up guard, the results
// writer, the checkpointer and the progress reporter.
#include "app/run_case.hpp"

#include <filesystem>
#include <memory>
#include <new>
#include <optional>

#include <spdlog/spdlog.h>

#include "app/interrupt.hpp"
#include "app/run_case_internal.hpp"
#include "app/run_services.hpp"
#include "app/stopwatch.hpp"
#include "core/errors.hpp"
#include "io/results/output_lock.hpp"

namespace flowmpm {

using namespace run_internal;

namespace {

// Restores the run from the checkpoint in its output directory when the
// options ask for it (`asked`: read already). A case that may restart (a
// sweep's) starts afresh, rebuilt, when its checkpoint does not fit, and
// `fresh_because` says why. Returns whether the run resumes.
bool resume(std::unique_ptr<RunServices>& run, const Case& c, const RunOptions& options,
            std::optional<StateRecords>& asked, std::string& fresh_because) {
  const auto& path = run->checkpointer.path();
  const bool wanted = options.write_results && (options.restart == Restart::from_checkpoint ||
                                                (options.restart == Restart::if_checkpoint &&
                                                 std::filesystem::exists(path)));
  if (!wanted) return false;
  try {
    const StateRecords records = asked ? std::move(*asked) : checkpoint_of(c);
    try {
      run->restore(records);
    } catch (const std::runtime_error& e) {
      throw CaseError(path.string() + ": does not fit this case: " + e.what());
    }
    try {
      run->results.check_continuation(*run->sim);
    } catch (const std::runtime_error& e) {
      throw CaseError(e.what());
    }
    return true;
  } catch (const CaseError& e) {
    if (options.restart == Restart::from_checkpoint) throw;
    fresh_because = e.what();
    run = std::make_unique<RunServices>(c, options);  // the restore may have changed it
    return false;
  }
}

// The summary at the end of a run (or where it stopped), written with the
// index of the results.
void finish(RunServices& run, const RunOptions& options, RunStatus status, const std::string& failure = {}) {
  RunSummary& summary = run.summary;
  const SystemScalars& s = run.sim->scalars();
  summary.status = status;
  summary.failure = failure;
  summary.steps = s.step;
  summary.particle_steps_per_second =
      summary.step_loop_seconds > 0.0
          ? static_cast<double>(summary.particles) * static_cast<double>(s.step) / summary.step_loop_seconds
          : 0.0;
  const Diagnostics final_state = run.sim->diagnostics(run.body_names.size());
  run.energy.error(final_state);
  summary.bodies.clear();
  for (std::size_t i = 0; i < run.body_names.size(); ++i) {
    summary.bodies.push_back({run.body_names[i], final_state.bodies[i].stress, final_state.bodies[i].strain});
  }
  if (run.reference.present()) {
    summary.errors = run.reference.reference().errors();
    summary.measures = run.reference.reference().measures();
  }
  if (run.sim->damped()) summary.damping_dissipated = s.damping_dissipated;
  summary.kinetic_energy = final_state.kinetic_energy;
  summary.stored_energy = final_state.stored_energy;
  summary.dissipated_energy = final_state.dissipated_energy;
  summary.gravity_work = final_state.work.gravity;
  summary.boundary_work = final_state.work.boundary;
  summary.expansion_work = final_state.work.expansion;
  summary.load_work = final_state.work.load;
  if (run.sim->in_contact()) summary.contact_work = final_state.work.contact;
  summary.energy_error = run.energy.relative_error();
  if (summary.energy_error > RunSummary::energy_warning_threshold) {
    // An explicit step loses (or, unstable, gains) energy the balance does
    // not book: USL's own dissipation where bodies vibrate or meet
    // (docs/theory/energy_balance.md), coarse cells at an impact or a
    // contact, a time step near the stable limit.
    summary.energy_warning = fmt::format(
        "the energy balance ends {:.3g} off (more than {:.2g} of the largest energy present): the scheme {} loses "
        "or gains energy it does not book, most often where bodies vibrate, meet or slide on coarse cells; to "
        "trust energies, run with {}a finer grid or a smaller time step (analysis.cfl or analysis.dt)",
        summary.energy_error, RunSummary::energy_warning_threshold, summary.scheme,
        summary.scheme == "MUSL" ? "" : "scheme = \"musl\", ");
  }
  if (options.write_results) {
    run.results.finish();
    write_summary(run.c.output.directory / "summary.json", summary);
  }
}

// One step; a stage's exception (a return mapping that did not converge)
// becomes a SimulationError naming the step.
void step(SimulationBase& sim, double& seconds) {
  TimeInto timer(seconds);
  try {
    sim.advance();
  } catch (const SimulationError&) {
    throw;
  } catch (const std::exception& e) {
    const SystemScalars& s = sim.scalars();
    throw SimulationError(fmt::format("step {} (t = {:.6g} s): {}", s.step + 1, s.t, e.what()));
  }
}

// Stops the run after an interrupt: a checkpoint, the last output step and
// the summary, then a SimulationError that says how to continue.
[[noreturn]] void stop_interrupted(RunServices& run, const RunOptions& options) {
  const SystemScalars& s = run.sim->scalars();
  std::string checkpoint;
  if (options.write_results) {
    run.write_checkpoint();
    checkpoint = "; continue it with " + restart_command(run.c);
  }
  if (s.step != run.results.last_written()) run.write_output();
  finish(run, options, RunStatus::interrupted);
  throw SimulationError("interrupted at step " + std::to_string(s.step) + " (t = " + std::to_string(s.t) +
                        " s); results up to this step are written" + checkpoint);
}

// The steps from where the run starts or resumes to the end.
void time_loop(RunServices& run, const RunOptions& options, spdlog::logger& log, bool restart) {
  SimulationBase& sim = *run.sim;
  SystemScalars& s = sim.scalars();
  const TimeStep& time = run.c.time_step;
  if (!restart) sim.measure_speed();
  run.progress.start(sim);
  bool interrupted = false;
  try {
    if (!restart) run.write_output();
    while (!time.done(s.step, s.t)) {
      if (options.interrupt && options.interrupt->load()) {
        interrupted = true;
        stop_interrupted(run, options);
      }
      run.guard.before_step(sim);
      s.dt = time.next_dt(s.t, s.max_speed_sq);
      step(sim, run.summary.step_loop_seconds);
      run.guard.after_step(sim, run.body_names);
      const bool last = time.done(s.step, s.t);
      run.reference.after_step(sim, last, run.summary.reference_seconds);
      if (run.results.due(s.step, last)) run.write_output();
      if (run.checkpointer.due(s.step, last)) run.write_checkpoint();
      run.progress.after_step(log, sim, run.summary.particles, run.summary.step_loop_seconds);
    }
  } catch (const SimulationError& e) {
    if (interrupted) {
      log.error("{}", e.what());
      throw;
    }
    const std::string message = e.what() + run.results.write_last_good(run.guard.last_good()) + run.guard.remedy();
    finish(run, options, RunStatus::failed, message);
    log.error("{}", message);
    throw SimulationError(message);
  } catch (const std::exception& e) {
    // An output file could not be written (a full disk) or memory ran out:
    // one line naming what failed; the summary says so if it can still be
    // written, and what was written before stays readable.
    const std::string message = fmt::format("step {} (t = {:.6g} s): {}", s.step, s.t, failure_text(e));
    log.error("{}", message);
    try {
      finish(run, options, RunStatus::failed, message);
    } catch (const std::exception&) {
      // The disk that failed the output may fail the summary too.
    }
    throw SimulationError(message);
  }
  finish(run, options, RunStatus::completed);
}

// The end of a completed run in the log: rate, means, energy, errors.
void log_end(spdlog::logger& log, const RunServices& run) {
  const RunSummary& summary = run.summary;
  const double t = run.sim->scalars().t;
  if (run.sim->unsettled_steps() > 0) {
    log.warn("the nonlocal averages did not settle in {} of {} steps (tasks/nonlocal_settle.hpp): a softening band "
             "as wide as its model allows; refine the grid", run.sim->unsettled_steps(), summary.steps);
  }
  log.info("done: {} steps, {} particles, {:.3f} s in the step loop, {:.4g} particle-steps/s (set-up {:.3f} s, "
           "output {:.3f} s), particles sorted {} times",
           summary.steps, summary.particles, summary.step_loop_seconds, summary.particle_steps_per_second,
           summary.setup_seconds, summary.output_seconds, run.sim->scalars().sorts);
  for (const auto& b : summary.bodies) {
    const TensorComponentNames& n = tensor_component_names(summary.axisymmetric);
    log.info("body '{}' at t = {:.6g} s: mean stress {} {:.6g} {} {:.6g} {} {:.6g} Pa, mean strain {} {:.6g} "
             "{} {:.6g} {} {:.6g}",
             b.name, t, n[0], b.mean_stress[0], n[1], b.mean_stress[1], n[2], b.mean_stress[2], n[0],
             b.mean_strain[0], n[1], b.mean_strain[1], n[2], b.mean_strain[2]);
  }
  log.info("energy at the end: kinetic {:.6g} J, stored {:.6g} J, dissipated {:.6g} J; work done by gravity "
           "and body forces {:.6g} J, by the constraints {:.6g} J, by the expansion strains {:.6g} J, by the loads "
           "{:.6g} J{}; balance error {:.3g} of the largest energy present",
           summary.kinetic_energy, summary.stored_energy, summary.dissipated_energy, summary.gravity_work,
           summary.boundary_work, summary.expansion_work, summary.load_work,
           summary.contact_work ? fmt::format(", by contact {:.6g} J", *summary.contact_work) : "",
           summary.energy_error);
  if (summary.energy_warning) log.warn("{}", *summary.energy_warning);
  const char* type = run.reference.present() ? run.reference.reference().type() : "";
  for (const auto& [name, value] : summary.errors) {
    log.info("error against the {} reference: {} = {:.4g}", type, name, value);
  }
  for (const auto& [name, value] : summary.measures) {
    log.info("measured by the {} reference: {} = {:.6g}", type, name, value);
  }
  if (summary.damping_dissipated) log.info("energy dissipated by damping: {:.6g} J", *summary.damping_dissipated);
}

}  // namespace

RunSummary run_case(const Case& c, const RunOptions& options) {
  const auto setup_start = WallClock::now();
  auto run = std::make_unique<RunServices>(c, options);  // built and checked: nothing written yet
  // A restart that cannot be made says why before anything is touched.
  std::optional<StateRecords> asked;
  if (options.write_results && options.restart == Restart::from_checkpoint) asked = checkpoint_of(c);
  // From here the output directory is this run's (io/results/output_lock.hpp), and
  // an interrupt lets the run finish its step.
  const auto& dir = c.output.directory;
  std::optional<OutputLock> lock;
  std::optional<FinishBeforeExit> finish_before_exit;
  if (options.write_results) {
    lock.emplace(dir, "case " + c.file.string());
    finish_before_exit.emplace();
  }
  std::string fresh_because;
  const bool restart = resume(run, c, options, asked, fresh_because);

  // The directory marked as this run's (summary.json "running"); a fresh
  // run removes the earlier run's results, a restart continues them.
  if (options.write_results) {
    run->summary.status = RunStatus::running;
    if (restart) {
      remove_stale_temporaries(dir);
      write_summary(dir / "summary.json", run->summary);
    } else {
      start_output(dir, run->summary);
    }
    run->summary.status = RunStatus::completed;
  }
  const auto log = run_logger(options.write_results ? std::optional(dir / "run.log") : std::nullopt,
                              options.log_to_console, !restart);
  log->info("case '{}' from {}, {} thread{}, output in {}", c.name, c.file.string(), options.threads,
            options.threads == 1 ? "" : "s", options.write_results ? dir.string() : "(none)");
  log_model(*log, c, *run->sim);
  const SystemScalars& s = run->sim->scalars();
  if (restart) {
    log->info("restart from the checkpoint at step {} (t = {:.6g} s), {}; results.h5, results.xdmf and "
              "timeseries.csv continue after its output step {}",
              s.step, s.t, run->checkpointer.path().string(), run->results.last_written());
  } else if (options.write_results && std::filesystem::exists(run->checkpointer.path())) {
    log->warn("{}: a checkpoint of an earlier run in the output directory{}; this run starts afresh and replaces it",
              run->checkpointer.path().string(), fresh_because.empty() ? "" : " (" + fresh_because + ")");
    std::filesystem::remove(run->checkpointer.path());
  }
  run->summary.setup_seconds = options.setup_seconds + seconds_since(setup_start);
  if (run->reference.present()) {
    if (!restart) run->reference.sample(*run->sim, run->summary.reference_seconds);
    log->info("reference: {} (errors sampled every {} step{})", run->reference.reference().type(),
              run->reference.every(), run->reference.every() == 1 ? "" : "s");
  }
  run->results.open(*run->sim, restart);

  time_loop(*run, options, *log, restart);
  log_end(*log, *run);
  return run->summary;
}

void describe_case(const Case& c) {
  const auto sim = simulation_of(c);
  if (c.reference) c.reference->initialise(*sim);
  log_model(*spdlog::default_logger(), c, *sim);
}

std::string failure_text(const std::exception& e) {
  if (dynamic_cast<const std::bad_alloc*>(&e)) return "out of memory (std::bad_alloc)";
  return e.what();
}

}  // namespace flowmpm
