// What a load (loads.hpp) reads besides its own table, and what it attaches
// to when the system is built.
#pragma once
#include <algorithm>
#include <optional>
#include <string>
#include <vector>

#include "core/number_text.hpp"
#include "discretisation/discrete_system.hpp"
#include "discretisation/bodies/lattice.hpp"
#include "discretisation/grid/stencil.hpp"

namespace flowmpm {

struct LoadReadContext {
  int dimension = 3;
  std::vector<std::string> body_names;
  std::vector<bool> body_has_shape;  // filled from a shape (not particles from a file)
  std::vector<std::string> node_set_names;
};

// A body filled from a shape, whose surface faces are found on its lattice.
struct BodyGeometry {
  const BodyShape* shape = nullptr;  // null for particles from a file
  std::optional<Lattice> lattice;
};

template <int D, class Shape>
struct LoadSite {
  DiscreteSystem<D, Shape>& system;
  const std::vector<BodyGeometry>& bodies;                 // per body (= batch)
  const std::vector<std::vector<std::size_t>>& node_sets;  // the nodes of each node set
  const std::vector<std::string>& body_names;
  const std::vector<std::string>& node_set_names;
};

// The index of the body named by `key`; with `needs_shape`, one filled
// from a shape.
inline int read_body_name(ParameterTable& t, std::string_view key, const LoadReadContext& c, bool needs_shape) {
  const std::string name = t.choice(key, c.body_names);
  const int body = static_cast<int>(std::ranges::find(c.body_names, name) - c.body_names.begin());
  if (needs_shape && !c.body_has_shape[body]) {
    t.fail(key, "a body filled from a shape (the surface of particles from a file is not known)");
  }
  return body;
}

// Per axis ({ x = ..., y = ... }), each a number or [[t, value], ...]; at
// least one axis.
inline AxisFunctions read_axis_functions(ParameterTable& t, std::string_view key, int dimension,
                                         std::string_view what) {
  AxisFunctions f;
  int given = 0;
  t.read_table(key, [&](ParameterTable& axes) {
    for (int d = 0; d < dimension; ++d) {
      const std::string axis(1, "xyz"[d]);
      if (axes.has(axis)) f[d] = axes.time_function(axis, what), ++given;
    }
  });
  t.require(given > 0, key, std::string("a table of ") + std::string(what) + " per axis, e.g. { x = 1.0 }");
  return f;
}

// "x = 1 Pa, y = [[0, 0], [1, 2]]"-like text for the log.
inline std::string axis_functions_text(const AxisFunctions& f, std::string_view unit) {
  std::string text;
  for (int d = 0; d < 3; ++d) {
    if (!f[d]) continue;
    const auto& points = f[d]->points;
    std::string value;
    if (points.size() == 1) {
      value = readable_text(points[0].second);
    } else {
      for (const auto& [time, v] : points) value += (value.empty() ? "" : ", ") + readable_text(time) + " s: " + readable_text(v);
      value = "(" + value + ")";
    }
    text += (text.empty() ? "" : ", ") + std::string(1, "xyz"[d]) + " " + value + " " + std::string(unit);
  }
  return text;
}

}  // namespace flowmpm
