#include "app/blow_up_guard.hpp"

#include <spdlog/fmt/fmt.h>

#include "core/errors.hpp"
#include "discretisation/shapes/shape_functions.hpp"

namespace flowmpm {

namespace {
// The budget's floor for bodies at rest: every particle at 1e-6 of the
// fastest wave speed.
double rest_floor(double total_mass, double wave_speed) {
  return 0.5 * total_mass * (1e-6 * wave_speed) * (1e-6 * wave_speed);
}
}  // namespace

BlowUpGuard::BlowUpGuard(const Case& c, const TimeStep& time_step, const SimulationBase& sim,
                         const Diagnostics& initial)
    : budget_(initial.kinetic_energy + initial.stored_energy + initial.dissipated_energy,
              rest_floor(sim.size().total_mass, time_step.fastest_wave_speed()), c.guard_energy_factor),
      wave_speed_(time_step.fastest_wave_speed()),
      speed_factor_(c.guard_speed_factor),
      every_(c.guard_every),
      fields_(c.output.fields),
      remedy_("; a smaller time step may run it (analysis.dt, or analysis.cfl with dt = \"auto\")") {
  const bool gradient_jumps =
      with_shape_function(c.system.shape_function, []<class Shape>() { return Shape::gradient_jumps; });
  if (gradient_jumps && c.scheme->wiring.stress_from_updated_grid())
    remedy_ += ", or scheme = \"musl\", or shape_function = \"gimp\" or \"bspline2\": linear shape functions "
               "with USL are the least stable pair where the material's edge moves (docs/STABILITY.md)";
}

void BlowUpGuard::before_step(const SimulationBase& sim) {
  if (every_ > 0 && sim.scalars().step % every_ == 0) sim.snapshot_into(last_good_, fields_);
}

void BlowUpGuard::after_step(const SimulationBase& sim, const std::vector<std::string>& body_names) {
  const SystemScalars& s = sim.scalars();
  const double limit = budget_.limit(s.work);
  if (s.kinetic_energy > limit) {
    throw SimulationError(fmt::format(
        "blow-up at step {} (t = {:.6g} s): the kinetic energy, {:.4g} J, is more than {:g} times the initial "
        "energy plus the most work done on the bodies, {:.4g} J (analysis.guard_energy_factor); the fastest: {}",
        s.step, s.t, s.kinetic_energy, budget_.factor(), limit / budget_.factor(), sim.fastest_particle(body_names)));
  }
  const double speed_limit = speed_factor_ * wave_speed_;
  if (s.max_speed_sq <= speed_limit * speed_limit) return;
  throw SimulationError(fmt::format("blow-up at step {} (t = {:.6g} s): {}, more than {:g} times the fastest "
                                    "wave speed, {:.4g} m/s (analysis.guard_speed_factor)",
                                    s.step, s.t, sim.fastest_particle(body_names), speed_factor_, wave_speed_));
}

}  // namespace flowmpm
