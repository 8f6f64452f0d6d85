#include "engine/time_step.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/number_text.hpp"

namespace flowmpm {

TimeStep::TimeStep(const SystemSpec& spec, const Scheme& scheme, const TimeControl& control)
    : control_(control), limits_(time_step_limit(spec, scheme)) {
  const StableStep& stable = limits_.wave;
  h_min_ = std::numeric_limits<double>::infinity();
  for (int d = 0; d < spec.dimension; ++d) h_min_ = std::min(h_min_, spec.grid.cell_size[d]);
  c_max_ = h_min_ / stable.crossing;
  wave_limit_text_ = readable_text(stable.factor) + " h/c = " + readable_text(stable.dt()) + " s for " +
                     scheme.label + " with " + shape_function_name(spec.shape_function) + " shape functions at " +
                     readable_text(stable.particles_per_cell) + " particles per cell" +
                     (spec.axisymmetric ? ", axisymmetric" : "") + " (h/c = " +
                     readable_text(stable.crossing) + " s: smallest cell over the P-wave speed of material \"" +
                     stable.material + "\")";
  auto fail = [&](std::string key, std::string expected) {
    if (!problem_) problem_ = TimeStepProblem{std::move(key), std::move(expected)};
  };
  first_dt_ = control.dt;
  if (control.automatic) {
    cfl_ = control.cfl ? *control.cfl : std::min(0.5, 0.8 * stable.factor);
    if (cfl_ > stable.factor) fail("cfl", "a CFL number no larger than the stable limit " + wave_limit_text_);
    first_dt_ = cfl_ * stable.crossing;  // the particles at rest
    // The same fraction of the interface and diffusion limits as of the wave limit.
    if (limits_.interface) {
      interface_dt_ = cfl_ / stable.factor * limits_.interface->dt;
      first_dt_ = joined_dt(first_dt_, interface_dt_);
    }
    if (limits_.diffusion) {
      diffusion_dt_ = cfl_ / stable.factor * limits_.diffusion->dt;
      first_dt_ = std::min(first_dt_, diffusion_dt_);
    }
  }
  if (!limits_.diffusion && !limits_.interface) {
    if (first_dt_ > stable.dt()) fail("dt", "a time step no larger than the stable limit " + wave_limit_text_);
  } else if (first_dt_ > limits_.dt()) {
    std::string mechanical = "the wave limit " + wave_limit_text_;
    if (limits_.interface) {
      const InterfaceStep& i = *limits_.interface;
      mechanical = "1 / sqrt(1 / dt_w^2 + 1 / dt_i^2) = " + readable_text(limits_.mechanical_dt()) + " s with " +
                   mechanical + " and the interface limit of contact \"" + i.contact + "\" " +
                   readable_text(stability_margin) + " sqrt(h / (D (1 / rho_a + 1 / rho_b))) = " +
                   readable_text(i.dt) + " s (D " + readable_text(i.stiffness) + " Pa/m, rho " +
                   readable_text(i.density_a) + " and " + readable_text(i.density_b) + " kg/m^3)";
    }
    if (!limits_.diffusion) {
      fail("dt", "a time step no larger than the stable limit " + mechanical);
    } else {
      const DiffusionStep& diffusion = *limits_.diffusion;
      const std::string diffusion_limit = "the " + diffusion.field + " diffusion limit 1 / (2 kappa sum_d 1/h_d^2) = " +
                                          readable_text(diffusion.dt) + " s (" + diffusion.field + " diffusivity " +
                                          readable_text(diffusion.diffusivity) + " m^2/s of material \"" +
                                          diffusion.material + "\")";
      fail("dt", "a time step no larger than the stable limit " + readable_text(limits_.dt()) + " s: " +
                     (limits_.diffusion_governs() ? diffusion_limit + " governs; " + mechanical
                                                  : mechanical + " governs; " + diffusion_limit));
    }
  }
  if (control.automatic && control.end_time / first_dt_ > static_cast<double>(max_steps)) {
    fail("end_time", "at most " + std::string(max_steps_text) + " steps (end_time over the first dt, " + readable_text(first_dt_) + " s, is " +
                         readable_text(control.end_time / first_dt_) + ")");
  }
}

std::int64_t TimeStep::planned_steps() const {
  return control_.automatic ? static_cast<std::int64_t>(std::ceil(control_.end_time / first_dt_)) : control_.steps;
}

double TimeStep::next_dt(double t, double max_speed_sq) const {
  if (!control_.automatic) return control_.dt;
  double dt = cfl_ * h_min_ / (c_max_ + std::sqrt(max_speed_sq));
  if (limits_.interface) dt = joined_dt(dt, interface_dt_);
  if (limits_.diffusion) dt = std::min(dt, diffusion_dt_);
  return std::min(dt, control_.end_time - t);
}

bool TimeStep::done(std::int64_t step, double t) const {
  return control_.automatic ? t >= control_.end_time * (1.0 - 1e-12) : step >= control_.steps;
}

}  // namespace flowmpm
