#include "io/case/case_file.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <memory>
#include <sstream>

#include "core/number_text.hpp"
#include "core/registry.hpp"
#include "discretisation/shapes/shape_functions.hpp"
#include "engine/schemes.hpp"
#include "engine/stable_time_step.hpp"
#include "engine/take_snapshot.hpp"
#include "io/case/case_limits.hpp"
#include "io/case/case_reader.hpp"
#include "io/case/digest.hpp"
#include "io/case/memory_estimate.hpp"
#include "io/case/particle_file.hpp"

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

// The output fields a case may ask for: the built-in ones and the state
// variables of its models, the transported fields only when carried.
std::vector<std::string> offered_fields(const SystemSpec& c) {
  std::vector<Material> materials;
  for (const NamedMaterial& m : c.materials) materials.push_back(m.model);
  std::vector<std::string> names;
  for (const OutputField& f : output_fields_of(materials)) names.emplace_back(f.name);
  if (!c.conducts_heat()) std::erase(names, "temperature");
  if (!c.diffuses_solvent()) std::erase(names, "concentration");
  return names;
}

// The fields written when a case does not choose, with the transported ones.
std::vector<std::string> default_fields(const SystemSpec& c) {
  std::vector<std::string> names = default_output_fields();
  if (c.conducts_heat()) names.emplace_back("temperature");
  if (c.diffuses_solvent()) names.emplace_back("concentration");
  return names;
}

void read_analysis(TableReader t, Case& c) {
  SystemSpec& s = c.system;
  const std::int64_t dimension = t.integer("dimension");
  t.require(dimension >= 1 && dimension <= 3, "dimension", "1, 2 or 3");
  s.dimension = static_cast<int>(dimension);
  c.scheme = &scheme_named(t.choice("scheme", scheme_names(), "usl"));
  s.shape_function = shape_function_named(t.choice("shape_function", shape_function_names(), "linear"));
  if (t.has("stress_state")) {
    t.require(s.dimension == 2, "stress_state", "no stress_state outside 2D (3D is full, 1D uniaxial stress)");
    s.plane_stress = t.choice("stress_state", {"plane_strain", "plane_stress"}) == "plane_stress";
  }
  const std::string update = t.choice("velocity_update", {"flip", "pic", "blend"}, "flip");
  s.velocity_update = update == "blend" ? VelocityUpdate::blend
                      : update == "pic" ? VelocityUpdate::pic
                                        : VelocityUpdate::flip;
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

// The spacing of a body filled on a lattice: particles_per_cell (per axis)
// or spacing (m, one or one per axis).
Vec3 read_spacing(TableReader& t, const SystemSpec& c, const BoxShape& bounds) {
  if (t.has("particles_per_cell") == t.has("spacing")) {
    t.fail_table("give exactly one of particles_per_cell (per axis) and spacing (m)");
  }
  Vec3 spacing{};
  if (t.has("particles_per_cell")) {
    const std::int64_t n = t.integer("particles_per_cell");
    t.require(n >= 1 && n <= 16, "particles_per_cell", "1 to 16 particles per cell per axis");
    for (int d = 0; d < c.dimension; ++d) {
      spacing[d] = c.grid.cell_size[d] / static_cast<double>(n);
      // A box thinner than a spacing would hold no lattice point.
      if (t.has("max") && spacing[d] > (bounds.max[d] - bounds.min[d]) * (1.0 + 1e-9)) {
        t.fail("max", "a box at least one particle spacing (cell_size / particles_per_cell = " +
                          readable_text(spacing[d]) + " m) thick along " + axis_names[d]);
      }
    }
  } else {
    spacing = per_axis(t, "spacing", c.dimension);
    for (int d = 0; d < c.dimension; ++d) {
      t.require(spacing[d] > 0.0 && spacing[d] <= bounds.max[d] - bounds.min[d], "spacing",
                "a positive particle spacing no larger than the body, in m");
    }
  }
  return spacing;
}

// A body's particles: a box (min, max), a shape table, or a particle file.
void read_body_particles(TableReader& t, SystemSpec& c, BodySpec& b, const std::filesystem::path& case_file) {
  const int sources = (t.has("min") || t.has("max") ? 1 : 0) + (t.has("shape") ? 1 : 0) + (t.has("particles") ? 1 : 0);
  if (sources != 1) {
    t.fail_table("give the body's particles by exactly one of a box (min, max), a shape table (shape) or a particle "
                 "file (particles)");
  }
  if (t.has("particles")) {
    std::filesystem::path file = t.string("particles");
    if (file.is_relative()) file = case_file.parent_path() / file;
    try {
      b.particles = read_particle_file(file, c.dimension);
    } catch (const CaseError& e) {
      throw CaseError(t.where("particles") + ": " + e.what());
    }
    for (const char* key : {"particles_per_cell", "spacing"}) {
      if (t.has(key)) t.fail(key, "no lattice spacing for particles from a file (each has its volume)");
    }
    return;
  }
  if (t.has("shape")) {
    t.read_table("shape", [&](ParameterTable& shape) { b.shape = BodyShape::read(shape, {c.dimension}); });
    const BoxShape bounds = b.shape.bounds();
    for (int d = 0; d < c.dimension; ++d) {
      const double tol = 1e-9 * c.grid.cell_size[d];
      t.require(bounds.min[d] >= c.grid.origin[d] - tol && bounds.max[d] <= grid_max(c, d) + tol, "shape",
                "a shape inside the grid: " + readable_text(c.grid.origin[d]) + " <= " + axis_names[d] +
                    " <= " + readable_text(grid_max(c, d)) + " (its bounds reach " + readable_text(bounds.min[d]) +
                    " to " + readable_text(bounds.max[d]) + ")");
    }
  } else {
    BoxShape box{vector_of(t, "min", c.dimension), vector_of(t, "max", c.dimension)};
    if (!t.has("min")) t.fail("min", "the lower corner of the body's box in m");
    if (!t.has("max")) t.fail("max", "the upper corner of the body's box in m");
    for (int d = 0; d < c.dimension; ++d) {
      t.require(box.min[d] < box.max[d], "max", "a corner above min along every axis");
      const double tol = 1e-9 * c.grid.cell_size[d];
      t.require(box.min[d] >= c.grid.origin[d] - tol, "min",
                "a box inside the grid: " + std::string(axis_names[d]) + " >= " + readable_text(c.grid.origin[d]));
      t.require(box.max[d] <= grid_max(c, d) + tol, "max",
                "a box inside the grid: " + std::string(axis_names[d]) + " <= " + readable_text(grid_max(c, d)));
    }
    b.shape = BodyShape{box};
  }
  b.spacing = read_spacing(t, c, b.shape.bounds());
}

void read_body(TableReader t, SystemSpec& c, std::size_t index, const std::filesystem::path& case_file,
               std::vector<std::string>& wins_over) {
  BodySpec b;
  b.name = t.string_or("name", "body" + std::to_string(index));
  b.where = t.where("");
  const std::string material = t.string("material");
  b.material = -1;
  std::string known;
  for (std::size_t m = 0; m < c.materials.size(); ++m) {
    if (c.materials[m].name == material) b.material = static_cast<int>(m);
    known += (known.empty() ? "\"" : ", \"") + c.materials[m].name + "\"";
  }
  if (b.material < 0) t.fail("material", "the name of a material in [materials]: " + known);
  read_body_particles(t, c, b, case_file);
  b.velocity = vector_of(t, "velocity", c.dimension);
  const bool file_axes = b.particles && !b.particles->material_axes.empty();
  if (t.has("material_axes")) {
    t.require(c.dimension > 1, "material_axes", "no material axes in 1D");
    t.require(!file_axes, "material_axes", "no material_axes where the particle file gives them per particle");
    // 2D: one angle about z; 3D: angles about z, y and x (R = Rz Ry Rx).
    b.material_axes = vector_of(t, "material_axes", c.dimension == 2 ? 1 : 3);
  }
  if (t.has("material_axes_center")) {
    t.require(c.dimension > 1, "material_axes_center", "no material axes in 1D");
    const std::vector<double> center = t.numbers("material_axes_center", 2);
    b.material_axes_center = std::array<double, 2>{center[0], center[1]};
  }
  // The initial temperature and concentration, when the scene carries them.
  const TransportProperties& properties = transport(c.materials[b.material].model);
  if (c.conducts_heat()) {
    if (t.has("temperature")) {
      b.temperature = t.positive("temperature", "the initial temperature in K (> 0)");
    } else if (properties.reference_temperature) {
      b.temperature = *properties.reference_temperature;
    } else {
      t.fail("temperature", "the initial temperature in K (the scene conducts heat, and material \"" +
                                material + "\" has no reference_temperature to start from)");
    }
  } else if (t.has("temperature")) {
    t.fail("temperature", "no initial temperature: no material of the scene conducts heat (conductivity)");
  }
  if (t.has("concentration")) {
    t.require(c.diffuses_solvent(), "concentration",
              "no initial concentration: no material of the scene diffuses solvent (diffusivity)");
    b.concentration = t.number("concentration");
    t.require(b.concentration >= 0.0 && b.concentration <= 1.0, "concentration",
              "an initial solvent concentration (weight fraction) in [0, 1]");
  }
  if (t.has("initial_stress")) {
    t.require(!(b.particles && !b.particles->stress.empty()), "initial_stress",
              "no initial_stress where the particle file gives the stress per particle");
    t.read_table("initial_stress", [&](ParameterTable& s) {
      b.initial_stress = InitialStresses::read(s, "type", InitialStressContext{c.dimension, c.plane_stress, c.gravity});
    });
  }
  if (t.has("wins_over")) wins_over = t.strings("wins_over");
  t.reject_unknown_keys();
  c.bodies.push_back(std::move(b));
}

// Resolves each body's wins_over names once every body is known.
void resolve_wins_over(std::vector<TableReader>& tables, SystemSpec& c,
                       const std::vector<std::vector<std::string>>& names) {
  std::string known;
  for (const BodySpec& b : c.bodies) known += (known.empty() ? "\"" : ", \"") + b.name + "\"";
  for (std::size_t i = 0; i < c.bodies.size(); ++i) {
    for (const std::string& name : names[i]) {
      const auto it = std::ranges::find_if(c.bodies, [&](const BodySpec& b) { return b.name == name; });
      const int other = static_cast<int>(it - c.bodies.begin());
      if (it == c.bodies.end() || other == static_cast<int>(i)) {
        tables[i].fail("wins_over", "names of other bodies among " + known);
      }
      if (std::ranges::find(c.bodies[other].wins_over, static_cast<int>(i)) != c.bodies[other].wins_over.end()) {
        tables[i].fail("wins_over", "one winner per pair of bodies, but \"" + name + "\" wins over \"" +
                                        c.bodies[i].name + "\" too");
      }
      c.bodies[i].wins_over.push_back(other);
    }
  }
}

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

void read_surface_flux(TableReader t, SystemSpec& c, std::size_t index) {
  SurfaceFluxSpec f;
  f.name = t.string_or("name", "surface_flux" + std::to_string(index));
  const std::string body = t.string("body");
  f.body = -1;
  std::string known;
  for (std::size_t b = 0; b < c.bodies.size(); ++b) {
    if (c.bodies[b].name == body) f.body = static_cast<int>(b);
    known += (known.empty() ? "\"" : ", \"") + c.bodies[b].name + "\"";
  }
  if (f.body < 0) t.fail("body", "the name of a body: " + known);
  std::vector<std::string> faces;
  for (int d = 0; d < c.dimension; ++d)
    for (const char* side : {"-", "+"}) faces.push_back(axis_names[d] + std::string(side));
  const std::string face = t.choice("face", faces);
  f.axis = face[0] - 'x';
  f.side = face[1] == '+' ? 1 : -1;
  if (t.has("heat_flux")) {
    t.require(c.conducts_heat(), "heat_flux", "no heat flux: no material of the scene conducts heat (conductivity)");
    f.heat = t.time_function("heat_flux", "a heat flux into the body in W/m^2");
  }
  if (t.has("solvent_flux")) {
    t.require(c.diffuses_solvent(), "solvent_flux",
              "no solvent flux: no material of the scene diffuses solvent (diffusivity)");
    f.solvent = t.time_function("solvent_flux", "a solvent flux into the body in kg/(m^2 s)");
  }
  if (!f.heat && !f.solvent) t.fail_table("give heat_flux (W/m^2) or solvent_flux (kg/(m^2 s)), or both");
  t.reject_unknown_keys();
  c.surface_fluxes.push_back(f);
}

// What a scene that conducts heat or diffuses solvent asks of every
// material (each has read its own keys already): a heat capacity, and no
// uniform temperature change or concentration (the transported field
// drives the expansion).
void check_transport(std::vector<TableReader>& materials, const SystemSpec& c) {
  for (const char* field : {"heat", "solvent"}) {
    const bool heat = std::string_view(field) == "heat";
    if (heat ? !c.conducts_heat() : !c.diffuses_solvent()) continue;
    std::string carrier;
    for (const auto& m : c.materials) {
      const TransportProperties& p = transport(m.model);
      if (carrier.empty() && (heat ? p.conducts() : p.diffuses())) carrier = m.name;
    }
    const std::string why = heat ? "the scene conducts heat (material \"" + carrier + "\" has a conductivity)"
                                 : "the scene diffuses solvent (material \"" + carrier + "\" has a diffusivity)";
    for (std::size_t i = 0; i < materials.size(); ++i) {
      TableReader& m = materials[i];
      if (heat && transport(c.materials[i].model).heat_capacity == 0.0) {
        m.fail("heat_capacity", "the specific heat capacity in J/(kg K): " + why);
      }
      const char* uniform = heat ? "temperature_change" : "concentration";
      if (m.has(uniform)) {
        m.fail(uniform, std::string("no uniform ") + uniform + ": " + why + ", so each particle's own " +
                            (heat ? "temperature" : "concentration") + " drives the expansion");
      }
    }
  }
}

void read_load(TableReader t, SystemSpec& c) {
  LoadReadContext context{c.dimension, {}, {}, {}};
  for (const BodySpec& b : c.bodies) {
    context.body_names.push_back(b.name);
    context.body_has_shape.push_back(!b.particles);
  }
  for (const NodeSetSpec& s : c.node_sets) context.node_set_names.push_back(s.name);
  c.loads.push_back(Loads::read(t, "type", context));
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

void read_output(TableReader t, Case& c) {
  c.output.directory = t.string_or("directory", "results/" + c.name);
  t.require(is_clean_path(c.output.directory.string()), "directory", "a path without control characters");
  c.output.every = t.integer_or("every", 0);
  t.require(c.output.every >= 1 || !t.has("every"), "every",
            "a number of steps >= 1 (leave it out for about 20 output steps over the run)");
  c.output.checkpoint_every = t.integer_or("checkpoint_every", 0);
  t.require(c.output.checkpoint_every >= 0, "checkpoint_every",
            "a number of steps >= 0 between checkpoints (0: a checkpoint only when interrupted)");
  if (t.has("fields")) {
    const std::vector<std::string> known = offered_fields(c.system);
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
  c.overrides = overrides;
  {
    std::ifstream in(file, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    std::uint64_t h = fnv1a(text.str());
    for (const std::string& assignment : overrides) h = fnv1a("\n--set " + assignment, h);
    c.digest = hex_digest(h);
  }
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
  std::vector<TableReader> material_tables;
  for (auto&& [key, value] : *root.get("materials")->as_table()) {
    TableReader m = materials.table(key.str());
    c.system.materials.push_back({std::string(key.str()), read_material(m)});
    m.reject_unknown_keys();
    material_tables.push_back(std::move(m));
  }
  if (c.system.materials.empty()) materials.fail_table("define at least one material, e.g. [materials.steel]");
  check_transport(material_tables, c.system);

  auto bodies = t.tables("bodies");
  if (bodies.empty()) t.fail("bodies", "at least one [[bodies]] table");
  std::vector<std::vector<std::string>> wins_over(bodies.size());
  for (std::size_t i = 0; i < bodies.size(); ++i) read_body(bodies[i], c.system, i, file, wins_over[i]);
  resolve_wins_over(bodies, c.system, wins_over);
  const auto node_sets = t.tables("node_sets");
  for (std::size_t i = 0; i < node_sets.size(); ++i) read_node_set(node_sets[i], c.system, i);
  const auto fluxes = t.tables("surface_fluxes");
  for (std::size_t i = 0; i < fluxes.size(); ++i) read_surface_flux(fluxes[i], c.system, i);
  for (TableReader& load : t.tables("loads")) read_load(load, c.system);
  if (t.has("damping")) read_damping(t.table("damping"), c.system);
  if (t.has("reference")) {
    TableReader r = t.table("reference");
    c.reference = Reference::read(r, {c.system, c.time_control.end_time});
    r.reject_unknown_keys();
    c.system.keep_initial_positions = true;
  }
  c.output.directory = "results/" + c.name;
  c.output.fields = default_fields(c.system);
  if (t.has("output")) read_output(t.table("output"), c);
  for (const char* needs_x0 : {"displacement", "initial_position"}) {
    if (std::ranges::find(c.output.fields, needs_x0) != c.output.fields.end()) c.system.keep_initial_positions = true;
  }
  t.reject_unknown_keys();

  // The time step's owner checks the choice against the scene's limits
  // (the wave limit and, with transport, the diffusion limit).
  c.time_step = TimeStep(c.system, *c.scheme, c.time_control);
  c.system.dt = c.time_step.first_dt();
  check_memory(c, t);
  if (const auto& problem = c.time_step.problem()) t.table("analysis").fail(problem->key, problem->expected);
  // The viscous damping's share of the update, v (1 - c dt), must not
  // reverse the velocity.
  if (c.system.damping) {
    for (const auto& [time, coefficient] : c.system.damping->viscous.points) {
      const double dt = c.time_step.first_dt();
      if (coefficient * dt > 1.0) {
        TableReader damping = t.table("damping");
        damping.fail("viscous", "a viscous damping coefficient c with c dt <= 1 (c <= " + readable_text(1.0 / dt) +
                                    " 1/s at dt = " + readable_text(dt) + " s)");
      }
    }
  }
  return c;
}

void set_time_control(Case& c, TimeControl control) {
  if (!control.automatic) control.end_time = control.dt * static_cast<double>(control.steps);
  c.time_control = control;
  c.time_step = TimeStep(c.system, *c.scheme, control);
  c.system.dt = c.time_step.first_dt();
}

}  // namespace flowmpm
