// [[node_sets]]: nodes that prescribe a velocity, a temperature or a
// concentration, or a plane that is a wall (it holds only in compression).
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "core/number_text.hpp"
#include "core/registry.hpp"
#include "io/case/case_limits.hpp"
#include "io/case/case_reader.hpp"
#include "io/case/case_sections.hpp"

namespace flowmpm {

namespace {

// A prescribed temperature (K, > 0) or concentration (in [0, 1]) as a
// function of time, allowed only when the scene carries that field.
std::optional<TimeFunction> transport_condition(TableReader& t, const char* key, bool carried) {
  if (!t.has(key)) return std::nullopt;
  const bool heat = std::string_view(key) == "temperature";
  if (!carried) {
    t.fail(key, heat ? "no prescribed temperature: no material of the scene conducts heat (conductivity)"
                     : "no prescribed concentration: no material of the scene diffuses solvent (diffusivity)");
  }
  const char* what = heat ? "a temperature in K" : "a solvent concentration (weight fraction)";
  TimeFunction f = t.time_function(key, what);
  for (const auto& [time, value] : f.points) {
    t.require(heat ? value > 0.0 : value >= 0.0 && value <= 1.0, key,
              heat ? "temperatures in K (> 0)" : "concentrations (weight fractions) in [0, 1]");
  }
  return f;
}

}  // namespace

void read_node_set(TableReader t, SystemSpec& c, std::size_t index) {
  NodeSetSpec s;
  s.name = t.string_or("name", "node_set" + std::to_string(index));
  if (t.has("plane") == (t.has("min") || t.has("max"))) {
    t.fail_table("select nodes either by plane = \"x\"|\"y\"|\"z\" with at = coordinate, or by a box min, max");
  }
  if (t.has("plane")) {
    s.is_plane = true;
    s.axis = read_axis(t, "plane", c.dimension);
    s.at = t.number("at");
    const double h = c.grid.cell_size[s.axis];
    const double cell = (s.at - c.grid.origin[s.axis]) / h;
    t.require(std::abs(cell - std::round(cell)) <= 1e-6 && std::round(cell) >= 0 &&
                  std::round(cell) <= c.grid.cells[s.axis],
              "at", "the coordinate of a plane of grid nodes (origin + k * cell_size, k = 0.." +
                        std::to_string(c.grid.cells[s.axis]) + ")");
  } else {
    s.is_plane = false;
    s.box_min = vector_of(t, "min", c.dimension);
    s.box_max = vector_of(t, "max", c.dimension);
    if (!t.has("min") || !t.has("max")) t.fail_table("a box needs both min and max");
    for (int d = 0; d < c.dimension; ++d) t.require(s.box_min[d] <= s.box_max[d], "max", "max >= min");
  }
  if (t.has("wall")) {
    t.require(s.is_plane, "wall", "a wall on a plane of nodes (plane = \"x\"|\"y\"|\"z\", at)");
    t.read_table("wall", [&](ParameterTable& w) {
      s.wall = ContactLaws::read(w, "law");
      w.require(!is_interface(*s.wall), "law", "\"stick\", \"frictionless\" or \"coulomb\" (a wall bonds to nothing)");
    });
  }
  s.temperature = transport_condition(t, "temperature", c.conducts_heat());
  s.concentration = transport_condition(t, "concentration", c.diffuses_solvent());
  if (t.has("velocity")) {
    TableReader v = t.table("velocity");
    for (int d = 0; d < c.dimension; ++d) {
      if (v.has(axis_names[d])) s.velocity[d] = v.time_function(axis_names[d], "a velocity in m/s");
    }
    v.reject_unknown_keys();
    if (std::ranges::none_of(s.velocity, [](const auto& f) { return f.has_value(); })) {
      t.fail("velocity", "a velocity for at least one axis, e.g. { y = 0.0 }");
    }
  }
  t.reject_unknown_keys();
  c.node_sets.push_back(s);
}

void add_axis_node_set(TableReader& grid, std::vector<TableReader>& node_sets, SystemSpec& c) {
  const double origin = c.grid.origin[0], h = c.grid.cell_size[0];
  if (origin > 0.0) return;  // the grid does not reach the axis (a hollow body)
  const double cell = -origin / h;
  grid.require(std::abs(cell - std::round(cell)) <= 1e-6, "origin",
               "the axis r = 0 on a plane of grid nodes in axisymmetric (origin x = -k * cell_size, k >= 0)");
  // A set the case names "axis" (as other codes name it) is taken for the
  // automatic one when it holds exactly what that holds: the plane x = 0,
  // the radial velocity 0 and nothing else.
  for (std::size_t i = 0; i < c.node_sets.size(); ++i) {
    const NodeSetSpec& s = c.node_sets[i];
    if (s.name != "axis") continue;
    const auto zero = [](const std::optional<TimeFunction>& f) {
      return f && std::ranges::all_of(f->points, [](const auto& p) { return p.second == 0.0; });
    };
    const bool is_the_axis = s.is_plane && s.axis == 0 && s.at == 0.0 && zero(s.velocity[0]) && !s.velocity[1] &&
                             !s.velocity[2] && !s.wall && !s.temperature && !s.concentration;
    if (!is_the_axis) {
      node_sets.at(i).fail("name", "a name other than \"axis\" where the grid reaches r = 0 in axisymmetric, or "
                                   "the axis itself (plane = \"x\", at = 0.0, velocity = { x = 0.0 } and nothing "
                                   "else): the axis holds the radial velocity at 0");
    }
    return;  // the case's own axis
  }
  // Symmetry about the axis: v_r = 0 on it; the shape functions that reach
  // past it fold onto their mirror nodes as at any held plane (MirrorPlane).
  NodeSetSpec axis;
  axis.name = "axis";
  axis.is_plane = true;
  axis.axis = 0;
  axis.at = 0.0;
  axis.velocity[0] = TimeFunction{{{0.0, 0.0}}};
  c.node_sets.push_back(std::move(axis));
}

}  // namespace flowmpm
