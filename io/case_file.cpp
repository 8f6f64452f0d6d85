#include "io/case_file.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <memory>
#include <sstream>

#include "core/number_text.hpp"
#include "core/registry.hpp"
#include "discretisation/shape_functions.hpp"
#include "engine/schemes.hpp"
#include "engine/stable_time_step.hpp"
#include "engine/take_snapshot.hpp"
#include "io/case_limits.hpp"
#include "io/case_reader.hpp"
#include "io/memory_estimate.hpp"

namespace flowmpm {
namespace {

constexpr const char* axis_names[3] = {"x", "y", "z"};

// Applies one --set KEY=VALUE to the document. VALUE is TOML; a value that
// does not parse as TOML is taken as a bare string (--set analysis.scheme=usf).
// Returns the key as messages name it ("bodies[0].velocity").
std::string apply_override(toml::table& root, const std::string& assignment) {
  const auto eq = assignment.find('=');
  if (eq == std::string::npos || eq == 0) {
    throw CaseError("--set " + assignment + ": expected KEY=VALUE, e.g. --set analysis.dt=0.001");
  }
  const std::string key = assignment.substr(0, eq);
  const std::string text = assignment.substr(eq + 1);
  const std::string source = "--set " + assignment;
  toml::table parsed;
  try {
    parsed = toml::parse("value = " + text, source);
  } catch (const toml::parse_error&) {
    parsed = toml::parse("value = \"\"", source);
    parsed.insert_or_assign("value", text);
  }

  std::vector<std::string> parts;
  std::stringstream ss(key);
  // "bodies[0].velocity" (as messages name keys) is "bodies.0.velocity".
  for (std::string part; std::getline(ss, part, '.');) {
    while (!part.empty() && part.back() == ']' && part.find('[') != std::string::npos) {
      const std::size_t open = part.rfind('[');
      parts.push_back(part.substr(0, open));
      part = part.substr(open + 1, part.size() - open - 2);
    }
    parts.push_back(part);
  }
  toml::node* node = &root;
  for (std::size_t i = 0; i + 1 < parts.size(); ++i) {
    if (toml::table* t = node->as_table()) {
      if (!t->contains(parts[i])) t->insert(parts[i], toml::table{});
      node = t->get(parts[i]);
    } else if (toml::array* a = node->as_array()) {
      std::size_t index = 0;
      try {
        index = std::stoul(parts[i]);
      } catch (const std::exception&) {
        throw CaseError(source + ": '" + parts[i] + "' must be an index into an array");
      }
      if (index >= a->size()) throw CaseError(source + ": index " + parts[i] + " is out of range");
      node = a->get(index);
    } else {
      throw CaseError(source + ": '" + parts[i] + "' is not a table");
    }
  }
  toml::table* target = node->as_table();
  if (!target) throw CaseError(source + ": the key's parent is not a table");
  target->insert_or_assign(parts.back(), *parsed.get("value"));
  std::string dotted;
  for (const std::string& part : parts) {
    const bool index = !part.empty() && part.find_first_not_of("0123456789") == std::string::npos;
    dotted += index ? "[" + part + "]" : (dotted.empty() ? "" : ".") + part;
  }
  return dotted;
}

// An array of `dim` numbers; zeros when the key is absent.
Vec3 vector_of(TableReader& t, std::string_view key, int dim) {
  if (!t.has(key)) return {};
  const std::vector<double> values = t.numbers(key, static_cast<std::size_t>(dim));
  Vec3 v{};
  for (int d = 0; d < dim; ++d) v[d] = values[d];
  return v;
}

// A number or an array of `dim` numbers; a single number applies to every axis.
Vec3 per_axis(TableReader& t, std::string_view key, int dim) {
  const toml::node* n = t.node(key);
  Vec3 v{};
  if (n && n->is_number()) {
    const double value = t.number(key);
    for (int d = 0; d < dim; ++d) v[d] = value;
    return v;
  }
  return vector_of(t, key, dim);
}

void read_analysis(TableReader t, Case& c) {
  SystemSpec& s = c.system;
  const std::int64_t dimension = t.integer("dimension");
  t.require(dimension >= 1 && dimension <= 3, "dimension", "1, 2 or 3");
  s.dimension = static_cast<int>(dimension);
  c.scheme = t.choice("scheme", scheme_names(), "usl");
  s.shape_function = t.choice("shape_function", shape_function_names(), "linear");
  if (t.has("stress_state")) {
    t.require(s.dimension == 2, "stress_state", "no stress_state outside 2D (3D is full, 1D uniaxial stress)");
    s.plane_stress = t.choice("stress_state", {"plane_strain", "plane_stress"}) == "plane_stress";
  }
  c.velocity_update = t.choice("velocity_update", {"flip", "pic", "blend"}, "flip");
  if (c.velocity_update == "blend") {
    s.flip_fraction = t.number("flip_fraction");
    t.require(s.flip_fraction >= 0.0 && s.flip_fraction <= 1.0, "flip_fraction",
              "a FLIP fraction in [0, 1]");
  } else {
    s.flip_fraction = c.velocity_update == "flip" ? 1.0 : 0.0;
    if (t.has("flip_fraction")) t.fail("flip_fraction", "no flip_fraction unless velocity_update = \"blend\"");
  }
  if (t.has("dt") && t.node("dt")->is_string()) {
    t.require(t.string("dt") == "auto", "dt", "a time step in s, or \"auto\"");
    c.dt_auto = true;
    // Without cfl: 0.8 of the stable limit, at most 0.5 (set with the bodies).
    c.cfl = t.number_or("cfl", 0.5);
    t.require(c.cfl > 0.0, "cfl", "a positive CFL number");
    c.end_time = t.number("end_time");
    t.require(c.end_time > 0.0, "end_time", "a positive end time in s");
    if (t.has("steps")) t.fail("steps", "no steps with dt = \"auto\" (give end_time)");
  } else {
    c.dt = t.number("dt");
    t.require(c.dt > 0.0, "dt", "a positive time step in s, or \"auto\"");
    if (t.has("cfl")) t.fail("cfl", "no cfl unless dt = \"auto\"");
    if (t.has("steps") == t.has("end_time")) {
      t.fail_table("give exactly one of analysis.steps and analysis.end_time");
    }
    if (t.has("steps")) {
      c.steps = t.integer("steps");
      t.require(c.steps >= 1 && c.steps <= max_steps, "steps",
                std::string("a positive number of steps, at most ") + max_steps_text);
    } else {
      const double end_time = t.number("end_time");
      t.require(end_time > 0.0, "end_time", "a positive end time in s");
      t.require(end_time / c.dt <= static_cast<double>(max_steps), "end_time",
                "at most " + std::string(max_steps_text) + " steps of dt (end_time / dt = " +
                    readable_text(end_time / c.dt) + ")");
      const double steps = std::round(end_time / c.dt);
      t.require(steps >= 1.0 && std::abs(steps * c.dt - end_time) <= 1e-9 * end_time, "end_time",
                "a whole number of time steps (end_time / dt = " + readable_text(end_time / c.dt) + ")");
      c.steps = static_cast<std::int64_t>(steps);
    }
    c.end_time = c.dt * static_cast<double>(c.steps);
  }
  c.guard_speed_factor = t.number_or("guard_speed_factor", 10.0);
  t.require(c.guard_speed_factor > 1.0, "guard_speed_factor", "a factor > 1 on the fastest wave speed");
  c.guard_every = t.integer_or("guard_every", 10);
  t.require(c.guard_every >= 0, "guard_every", "a number of steps >= 0 (0: keep no last good state)");
  s.gravity = vector_of(t, "gravity", s.dimension);
  t.reject_unknown_keys();
}

void read_grid(TableReader t, SystemSpec& c) {
  c.grid.origin = vector_of(t, "origin", c.dimension);
  c.grid.cell_size = per_axis(t, "cell_size", c.dimension);
  if (!t.has("cell_size")) t.fail("cell_size", "the cell size in m (a number, or one per axis)");
  for (int d = 0; d < c.dimension; ++d) {
    t.require(c.grid.cell_size[d] > 0.0, "cell_size", "positive cell sizes in m");
  }
  const std::vector<double> cells = t.numbers("cells", static_cast<std::size_t>(c.dimension));
  c.grid.cells = {1, 1, 1};
  for (int d = 0; d < c.dimension; ++d) {
    t.require(cells[d] >= 1.0 && cells[d] == std::floor(cells[d]) && cells[d] < 1e6, "cells",
              "a whole number of cells (1 to 10^6) per axis");
    c.grid.cells[d] = static_cast<int>(cells[d]);
  }
  t.reject_unknown_keys();
}

double grid_max(const SystemSpec& c, int d) {
  return c.grid.origin[d] + c.grid.cell_size[d] * c.grid.cells[d];
}

void read_body(TableReader t, SystemSpec& c, std::size_t index) {
  BodySpec b;
  b.name = t.string_or("name", "body" + std::to_string(index));
  const std::string material = t.string("material");
  b.material = -1;
  std::string known;
  for (std::size_t m = 0; m < c.materials.size(); ++m) {
    if (c.materials[m].name == material) b.material = static_cast<int>(m);
    known += (known.empty() ? "\"" : ", \"") + c.materials[m].name + "\"";
  }
  if (b.material < 0) t.fail("material", "the name of a material in [materials]: " + known);
  b.box_min = vector_of(t, "min", c.dimension);
  b.box_max = vector_of(t, "max", c.dimension);
  if (!t.has("min")) t.fail("min", "the lower corner of the body's box in m");
  if (!t.has("max")) t.fail("max", "the upper corner of the body's box in m");
  for (int d = 0; d < c.dimension; ++d) {
    t.require(b.box_min[d] < b.box_max[d], "max", "a corner above min along every axis");
    const double tol = 1e-9 * c.grid.cell_size[d];
    t.require(b.box_min[d] >= c.grid.origin[d] - tol, "min",
              "a box inside the grid: " + std::string(axis_names[d]) + " >= " + readable_text(c.grid.origin[d]));
    t.require(b.box_max[d] <= grid_max(c, d) + tol, "max",
              "a box inside the grid: " + std::string(axis_names[d]) + " <= " + readable_text(grid_max(c, d)));
  }
  if (t.has("particles_per_cell") == t.has("spacing")) {
    t.fail_table("give exactly one of particles_per_cell (per axis) and spacing (m)");
  }
  if (t.has("particles_per_cell")) {
    const std::int64_t n = t.integer("particles_per_cell");
    t.require(n >= 1 && n <= 16, "particles_per_cell", "1 to 16 particles per cell per axis");
    for (int d = 0; d < c.dimension; ++d) {
      b.spacing[d] = c.grid.cell_size[d] / static_cast<double>(n);
      t.require(b.spacing[d] <= (b.box_max[d] - b.box_min[d]) * (1.0 + 1e-9), "max",
                "a box at least one particle spacing (cell_size / particles_per_cell = " +
                    readable_text(b.spacing[d]) + " m) thick along " + axis_names[d]);
    }
  } else {
    b.spacing = per_axis(t, "spacing", c.dimension);
    for (int d = 0; d < c.dimension; ++d) {
      t.require(b.spacing[d] > 0.0 && b.spacing[d] <= b.box_max[d] - b.box_min[d], "spacing",
                "a positive particle spacing no larger than the box, in m");
    }
  }
  b.velocity = vector_of(t, "velocity", c.dimension);
  if (t.has("material_axes")) {
    t.require(c.dimension > 1, "material_axes", "no material axes in 1D");
    // 2D: one angle about z; 3D: angles about z, y and x (R = Rz Ry Rx).
    b.material_axes = vector_of(t, "material_axes", c.dimension == 2 ? 1 : 3);
  }
  if (t.has("material_axes_center")) {
    t.require(c.dimension > 1, "material_axes_center", "no material axes in 1D");
    const std::vector<double> center = t.numbers("material_axes_center", 2);
    b.material_axes_center = std::array<double, 2>{center[0], center[1]};
  }
  t.reject_unknown_keys();
  c.bodies.push_back(b);
}

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
  TableReader v = t.table("velocity");
  for (int d = 0; d < c.dimension; ++d) {
    if (v.has(axis_names[d])) s.velocity[d] = v.time_function(axis_names[d], "a velocity in m/s");
  }
  v.reject_unknown_keys();
  if (std::ranges::none_of(s.velocity, [](const auto& f) { return f.has_value(); })) {
    t.fail("velocity", "a velocity for at least one axis, e.g. { y = 0.0 }");
  }
  t.reject_unknown_keys();
  c.node_sets.push_back(s);
}

void read_output(TableReader t, Case& c) {
  c.output.directory = t.string_or("directory", "results/" + c.name);
  t.require(is_clean_path(c.output.directory.string()), "directory", "a path without control characters");
  c.output.every = t.integer_or("every", 0);
  t.require(c.output.every >= 1 || !t.has("every"), "every",
            "a number of steps >= 1 (leave it out for about 20 output steps over the run)");
  if (t.has("fields")) {
    // The built-in fields and the state variables of the case's models.
    std::vector<Material> materials;
    for (const NamedMaterial& m : c.system.materials) materials.push_back(m.model);
    std::vector<std::string> known;
    for (const OutputField& f : output_fields_of(materials)) known.emplace_back(f.name);
    c.output.fields = t.strings("fields");
    for (const std::string& name : c.output.fields) {
      if (std::ranges::find(known, name) == known.end()) {
        t.fail("fields", "field names among " + quoted_list(known) + " (\"" + name + "\" is none of them)");
      }
    }
    // The XDMF geometry needs the positions.
    if (std::ranges::find(c.output.fields, "position") == c.output.fields.end()) c.output.fields.push_back("position");
  }
  t.reject_unknown_keys();
}

}  // namespace

Case read_case(const std::filesystem::path& file, const std::vector<std::string>& overrides) {
  toml::table root;
  try {
    root = toml::parse_file(file.string());
  } catch (const toml::parse_error& e) {
    // The parser reports where it noticed the error, which can be the line
    // after the mistake (an unclosed array): quote both lines.
    const auto line = static_cast<std::size_t>(e.source().begin.line);
    std::ifstream in(file);
    std::vector<std::string> lines;
    for (std::string text; std::getline(in, text);) lines.push_back(text);
    std::string context;
    if (line >= 1 && line <= lines.size()) context = " (line " + std::to_string(line) + ": '" + lines[line - 1] + "'";
    if (line >= 2 && line <= lines.size()) context += ", after line " + std::to_string(line - 1) + ": '" + lines[line - 2] + "'";
    if (!context.empty()) context += ")";
    throw CaseError(file.string() + ":" + std::to_string(line) + ": not valid TOML: " +
                    std::string(e.description()) + context);
  }
  auto sources = std::make_shared<std::map<std::string, std::string>>();
  for (const std::string& assignment : overrides) {
    (*sources)[apply_override(root, assignment)] = "--set " + assignment;
  }

  Case c;
  c.file = file;
  TableReader t(root, "", file.string(), sources);
  c.system.source = file.string();
  c.name = t.string_or("name", file.stem().string());
  if (t.has("name")) {
    t.require(is_plain_name(c.name), "name",
              "a name that can be a directory's (no / or \\, not . or .., no control character)");
  }
  read_analysis(t.table("analysis"), c);
  read_grid(t.table("grid"), c.system);

  // Each key of [materials] names a material with its own table.
  TableReader materials = t.table("materials");
  for (auto&& [key, value] : *root.get("materials")->as_table()) {
    TableReader m = materials.table(key.str());
    c.system.materials.push_back({std::string(key.str()), read_material(m)});
    m.reject_unknown_keys();
  }
  if (c.system.materials.empty()) materials.fail_table("define at least one material, e.g. [materials.steel]");

  const auto bodies = t.tables("bodies");
  if (bodies.empty()) t.fail("bodies", "at least one [[bodies]] table");
  for (std::size_t i = 0; i < bodies.size(); ++i) read_body(bodies[i], c.system, i);
  const auto node_sets = t.tables("node_sets");
  for (std::size_t i = 0; i < node_sets.size(); ++i) read_node_set(node_sets[i], c.system, i);
  if (t.has("reference")) {
    TableReader r = t.table("reference");
    c.reference = Reference::read(r, {c.system, c.end_time});
    r.reject_unknown_keys();
    c.system.keep_initial_positions = true;
  }
  c.output.directory = "results/" + c.name;
  c.output.fields = default_output_fields();
  if (t.has("output")) read_output(t.table("output"), c);
  for (const char* needs_x0 : {"displacement", "initial_position"}) {
    if (std::ranges::find(c.output.fields, needs_x0) != c.output.fields.end()) c.system.keep_initial_positions = true;
  }
  t.reject_unknown_keys();

  check_memory(c, t);

  // The explicit step is stable only below a fraction of the time a P wave
  // takes to cross the smallest cell (engine/stable_time_step.hpp).
  const Scheme& scheme = scheme_named(c.scheme);
  const StableStep stable = stable_time_step(c.system, scheme);
  const std::string limit = readable_text(stable.factor) + " h/c = " + readable_text(stable.dt()) + " s for " +
                            scheme.label + " with " + c.system.shape_function + " shape functions at " +
                            readable_text(stable.particles_per_cell) + " particles per cell (h/c = " +
                            readable_text(stable.crossing) +
                            " s: smallest cell over the P-wave speed of material \"" + stable.material + "\")";
  TableReader analysis = t.table("analysis");
  if (c.dt_auto) {
    if (!analysis.has("cfl")) c.cfl = std::min(0.5, 0.8 * stable.factor);
    analysis.require(c.cfl <= stable.factor, "cfl", "a CFL number no larger than the stable limit " + limit);
    c.dt = c.cfl * stable.crossing;  // the first step's, particles at rest
  }
  c.system.dt = c.dt;
  if (c.dt > stable.dt()) analysis.fail("dt", "a time step no larger than the stable limit " + limit);
  if (c.dt_auto && c.end_time / c.dt > static_cast<double>(max_steps)) {
    analysis.fail("end_time", "at most " + std::string(max_steps_text) + " steps (end_time over the first dt, " +
                                  readable_text(c.dt) + " s, is " + readable_text(c.end_time / c.dt) + ")");
  }
  return c;
}

}  // namespace flowmpm
