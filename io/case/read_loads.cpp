// [[loads]] and [damping]: what acts on the bodies besides gravity.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "core/number_text.hpp"
#include "io/case/case_limits.hpp"
#include "io/case/case_reader.hpp"
#include "io/case/case_sections.hpp"

namespace flowmpm {

void read_load(TableReader t, SystemSpec& c) {
  LoadReadContext context{c.dimension, {}, {}, {}};
  for (const BodySpec& b : c.bodies) {
    context.body_names.push_back(b.name);
    context.body_has_shape.push_back(!b.particles);
  }
  for (const NodeSetSpec& s : c.node_sets) context.node_set_names.push_back(s.name);
  c.loads.push_back(Loads::read(t, "type", context));
  std::visit(
      [&](const auto& load) {
        if constexpr (requires { load.body; }) {
          t.require(!c.bodies[load.body].rigid(), "body", "a body that is not rigid (a rigid body moves as it is told)");
        }
      },
      c.loads.back());
  t.reject_unknown_keys();
}

// Each coefficient a number or [[t, value], ...]; at least one of them.
void read_damping(TableReader t, SystemSpec& c) {
  Damping damping;
  if (!t.has("local") && !t.has("viscous")) t.fail_table("give local (alpha, -) and/or viscous (c, 1/s) damping");
  if (t.has("local")) {
    damping.local = t.time_function("local", "a local damping coefficient alpha in [0, 1)");
    for (const auto& [time, alpha] : damping.local.points)
      t.require(alpha >= 0.0 && alpha < 1.0, "local", "local damping coefficients alpha in [0, 1)");
  }
  if (t.has("viscous")) {
    damping.viscous = t.time_function("viscous", "a viscous damping coefficient c in 1/s");
    for (const auto& [time, coefficient] : damping.viscous.points)
      t.require(coefficient >= 0.0, "viscous", "viscous damping coefficients c >= 0 in 1/s");
  }
  t.reject_unknown_keys();
  c.damping = std::move(damping);
}

}  // namespace flowmpm
