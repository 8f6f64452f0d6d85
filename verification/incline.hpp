// A body on a plane (2D or 3D), gravity tilted by theta from the plane's
// normal (y) towards x, in contact with the plane by the law of its [[contacts]]
// entry, or else of the case's first wall node set (Coulomb coefficient
// mu; 0 frictionless). From rest, its centre of
// mass moves along x by (rigid-body dynamics, [Meriam 2012]):
//   slide (a block):          s = g (sin theta - mu cos theta) t^2 / 2 when mu < tan theta, else 0;
//   roll (a disk, plane strain, a solid cylinder):
//                             s = g sin theta t^2 / 3 when mu >= tan(theta) / 3 (no slip),
//                             else the sliding s.
// Error, at the last sample: displacement = |s_h - s| / max(s, h), s_h the
// body's mass-weighted mean displacement along x since the first sample,
// h the cell size along x (for a body that should stick, the drift in
// cells). Measures: displacement (s_h, m) and expected (s, m).
#pragma once
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <string>

#include "verification/reference_context.hpp"

namespace flowmpm {

struct Incline {
  static constexpr const char* type_name = "incline";
  int body = 0;
  bool rolls = false;
  double friction = 0.0;  // mu; infinite for a body that sticks
  double g_along = 0.0, g_normal = 0.0;  // gravity's x and -y components (m/s^2)
  double cell = 1.0;                     // h along x (m)
  double x0 = std::numeric_limits<double>::quiet_NaN(), t0 = 0.0;
  double displacement = 0.0, time = 0.0;

  static Incline read(ParameterTable& t, const ReferenceContext& context) {
    const SystemSpec& s = context.system;
    Incline r;
    std::vector<std::string> names;
    for (const BodySpec& b : s.bodies) names.push_back(b.name);
    const std::string name = t.choice("body", names);
    r.body = static_cast<int>(std::ranges::find(names, name) - names.begin());
    r.rolls = t.choice("motion", {"slide", "roll"}, "slide") == "roll";
    t.require(s.dimension >= 2 && s.gravity[1] < 0.0 && s.gravity[0] != 0.0 && s.gravity[2] == 0.0, "type",
              "a 2D or 3D case with gravity tilted from -y towards x (no z component) for incline");
    r.g_along = s.gravity[0];
    r.g_normal = -s.gravity[1];
    r.cell = s.grid.cell_size[0];
    const auto contact = std::ranges::find_if(s.contacts, [&](const ContactSpec& c) {
      return c.first == r.body || c.second == r.body;
    });
    const auto wall = std::ranges::find_if(s.node_sets, [](const NodeSetSpec& n) { return n.wall.has_value(); });
    t.require(contact != s.contacts.end() || wall != s.node_sets.end(), "body",
              "a body in a [[contacts]] pair with the plane, or a case with a wall node set");
    r.friction = std::visit(
        [](const auto& law) {
          using Law = std::decay_t<decltype(law)>;
          if constexpr (std::is_same_v<Law, CoulombLaw>) return law.friction;
          if constexpr (std::is_same_v<Law, FrictionlessLaw>) return 0.0;
          return std::numeric_limits<double>::infinity();
        },
        contact != s.contacts.end() ? contact->law : *wall->wall);
    return r;
  }

  template <int D, class Shape>
  void initialise(DiscreteSystem<D, Shape>&) const {}

  // The expected displacement along x after t seconds from rest.
  double expected(double t) const {
    const double g = std::hypot(g_along, g_normal), sin = std::abs(g_along) / g, cos = g_normal / g;
    const double sign = g_along > 0.0 ? 1.0 : -1.0;
    if (rolls && friction >= sin / cos / 3.0) return sign * g * sin * t * t / 3.0;
    if (friction >= sin / cos) return 0.0;
    return sign * g * (sin - friction * cos) * t * t / 2.0;
  }

  template <int D, class Shape>
  void sample(const DiscreteSystem<D, Shape>& system) {
    double mx = 0.0, m = 0.0;
    for (const auto& b : system.batches) {
      if (b.body != body) continue;
      for (std::size_t p = 0; p < b.size(); ++p) {
        mx += b.mass[p] * b.x[p][0];
        m += b.mass[p];
      }
    }
    if (std::isnan(x0)) x0 = mx / m, t0 = system.t;
    displacement = mx / m - x0;
    time = system.t - t0;
  }

  template <class F>
  void visit_state(F&& f) {
    f("x0", x0);
    f("t0", t0);
    f("displacement", displacement);
    f("time", time);
  }

  std::map<std::string, double> errors() const {
    const double s = expected(time);
    return {{"displacement", std::abs(displacement - s) / std::max(std::abs(s), cell)}};
  }
  std::map<std::string, double> measures() const {
    return {{"displacement", displacement}, {"expected", expected(time)}};
  }
};

}  // namespace flowmpm
