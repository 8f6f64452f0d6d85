// [analysis]: the run's choices and the time step's, resolved when read.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "core/number_text.hpp"
#include "io/case/case_limits.hpp"
#include "io/case/case_reader.hpp"
#include "io/case/case_sections.hpp"
#include "discretisation/shapes/shape_functions.hpp"
#include "engine/schemes.hpp"
#include "engine/time_step.hpp"

namespace flowmpm {

void read_analysis(TableReader t, Case& c) {
  SystemSpec& s = c.system;
  const std::int64_t dimension = t.integer("dimension");
  t.require(dimension >= 1 && dimension <= 3, "dimension", "1, 2 or 3");
  s.dimension = static_cast<int>(dimension);
  c.scheme = &scheme_named(t.choice("scheme", scheme_names(), "usl"));
  s.shape_function = shape_function_named(t.choice("shape_function", shape_function_names(), "linear"));
  if (t.has("stress_state")) {
    t.require(s.dimension == 2, "stress_state", "no stress_state outside 2D (3D is full, 1D uniaxial stress)");
    const std::string state = t.choice("stress_state", {"plane_strain", "plane_stress", "axisymmetric"});
    s.plane_stress = state == "plane_stress";
    s.axisymmetric = state == "axisymmetric";
  }
  const std::string update = t.choice("velocity_update", {"flip", "pic", "blend", "apic", "xpic"}, "flip");
  for (VelocityUpdate u : {VelocityUpdate::flip, VelocityUpdate::pic, VelocityUpdate::blend, VelocityUpdate::apic,
                           VelocityUpdate::xpic})
    if (update == velocity_update_name(u)) s.velocity_update = u;
  if (s.velocity_update == VelocityUpdate::xpic) {
    if (t.has("xpic_order")) {
      const std::int64_t order = t.integer("xpic_order");
      t.require(order >= 1 && order <= 20, "xpic_order", "an XPIC order m from 1 (PIC) to 20");
      s.xpic_order = static_cast<int>(order);
    }
  } else if (t.has("xpic_order")) {
    t.fail("xpic_order", "no xpic_order unless velocity_update = \"xpic\"");
  }
  if (s.velocity_update == VelocityUpdate::blend) {
    s.flip_fraction = t.number("flip_fraction");
    t.require(s.flip_fraction >= 0.0 && s.flip_fraction <= 1.0, "flip_fraction",
              "a FLIP fraction in [0, 1]");
  } else {
    s.flip_fraction = s.velocity_update == VelocityUpdate::flip ? 1.0 : 0.0;
    if (t.has("flip_fraction")) t.fail("flip_fraction", "no flip_fraction unless velocity_update = \"blend\"");
  }
  TimeControl& time = c.time_control;
  if (t.has("dt") && t.node("dt")->is_string()) {
    t.require(t.string("dt") == "auto", "dt", "a time step in s, or \"auto\"");
    time.automatic = true;
    // Without cfl: 0.8 of the stable limit, at most 0.5 (engine/time_step.hpp).
    if (t.has("cfl")) {
      time.cfl = t.number("cfl");
      t.require(*time.cfl > 0.0, "cfl", "a positive CFL number");
    }
    time.end_time = t.number("end_time");
    t.require(time.end_time > 0.0, "end_time", "a positive end time in s");
    if (t.has("steps")) t.fail("steps", "no steps with dt = \"auto\" (give end_time)");
  } else {
    time.dt = t.number("dt");
    t.require(time.dt > 0.0, "dt", "a positive time step in s, or \"auto\"");
    if (t.has("cfl")) t.fail("cfl", "no cfl unless dt = \"auto\"");
    if (t.has("steps") == t.has("end_time")) {
      t.fail_table("give exactly one of analysis.steps and analysis.end_time");
    }
    if (t.has("steps")) {
      time.steps = t.integer("steps");
      t.require(time.steps >= 1 && time.steps <= max_steps, "steps",
                std::string("a positive number of steps, at most ") + max_steps_text);
    } else {
      const double end_time = t.number("end_time");
      t.require(end_time > 0.0, "end_time", "a positive end time in s");
      t.require(end_time / time.dt <= static_cast<double>(max_steps), "end_time",
                "at most " + std::string(max_steps_text) + " steps of dt (end_time / dt = " +
                    readable_text(end_time / time.dt) + ")");
      const double steps = std::round(end_time / time.dt);
      t.require(steps >= 1.0 && std::abs(steps * time.dt - end_time) <= 1e-9 * end_time, "end_time",
                "a whole number of time steps (end_time / dt = " + readable_text(end_time / time.dt) + ")");
      time.steps = static_cast<std::int64_t>(steps);
    }
    time.end_time = time.dt * static_cast<double>(time.steps);
  }
  c.guard_speed_factor = t.number_or("guard_speed_factor", 10.0);
  t.require(c.guard_speed_factor > 1.0, "guard_speed_factor", "a factor > 1 on the fastest wave speed");
  c.guard_energy_factor = t.number_or("guard_energy_factor", 2.0);
  t.require(c.guard_energy_factor > 1.0, "guard_energy_factor",
            "a factor > 1 on the initial energy plus the work done on the bodies");
  c.guard_every = t.integer_or("guard_every", 10);
  t.require(c.guard_every >= 0, "guard_every", "a number of steps >= 0 (0: keep no last good state)");
  s.gravity = vector_of(t, "gravity", s.dimension);
  t.reject_unknown_keys();
}

}  // namespace flowmpm
