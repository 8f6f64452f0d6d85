// [[bodies]]: where the particles are, their material and initial state.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "core/number_text.hpp"
#include "io/case/case_limits.hpp"
#include "io/case/case_reader.hpp"
#include "io/case/case_sections.hpp"
#include "discretisation/bodies/body_shape.hpp"
#include "discretisation/loads/load_context.hpp"
#include "io/case/particle_file.hpp"

namespace flowmpm {

namespace {

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

// A rigid body (contact): its particles and its velocity, nothing else.
void read_rigid_body(TableReader& t, SystemSpec& c, BodySpec& b, const std::filesystem::path& case_file) {
  b.material = -1;
  b.rigid_velocity.emplace();
  t.read_table("rigid", [&](ParameterTable& r) {
    if (!r.has("velocity")) return;
    *b.rigid_velocity = read_axis_functions(r, "velocity", c.dimension, "a velocity in m/s");
  });
  for (const char* key : {"material", "velocity", "angular_velocity", "material_axes", "material_axes_center", "temperature",
                          "concentration", "initial_stress"}) {
    if (t.has(key)) t.fail(key, "nothing: a rigid body has no material and no state; it moves with rigid.velocity");
  }
  if (c.conducts_heat() || c.diffuses_solvent())
    t.fail("rigid", "no rigid body in a scene that conducts heat or diffuses solvent (not supported yet)");
  read_body_particles(t, c, b, case_file);
  if (t.has("wins_over")) t.fail("wins_over", "nothing: a rigid body may not overlap another body");
  t.reject_unknown_keys();
  c.bodies.push_back(std::move(b));
}

}  // namespace

void read_body(TableReader t, SystemSpec& c, std::size_t index, const std::filesystem::path& case_file,
               std::vector<std::string>& wins_over) {
  BodySpec b;
  b.name = t.string_or("name", "body" + std::to_string(index));
  b.where = t.where("");
  if (t.has("rigid")) {
    read_rigid_body(t, c, b, case_file);
    return;
  }
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
  if (t.has("angular_velocity")) {
    t.require(c.dimension > 1, "angular_velocity", "no angular_velocity in 1D");
    t.require(!c.axisymmetric, "angular_velocity",
              "no angular_velocity in axisymmetric (a turn in the (r, z) section breaks the symmetry)");
    // 2D: the rate about z, a number; 3D: a vector (rad/s).
    if (c.dimension == 2) {
      b.angular_velocity[2] = t.number("angular_velocity");
    } else {
      b.angular_velocity = vector_of(t, "angular_velocity", 3);
    }
  }
  const bool file_axes = b.particles && !b.particles->material_axes.empty();
  if (t.has("material_axes")) {
    t.require(c.dimension > 1, "material_axes", "no material axes in 1D");
    t.require(!file_axes, "material_axes", "no material_axes where the particle file gives them per particle");
    // 2D: one angle about z; 3D: angles about z, y and x (R = Rz Ry Rx).
    // Axisymmetric: about the hoop direction theta only; a turn about r or
    // z would couple theta with the section (shear r-theta, z-theta), which
    // a body of revolution cannot carry.
    if (c.axisymmetric) {
      const toml::node* angles = t.node("material_axes");
      const toml::array* list = angles ? angles->as_array() : nullptr;
      t.require(!list || list->size() == 1, "material_axes",
                "one angle in degrees, the turn of the material axes in the (r, z) section about the hoop "
                "direction theta (axisymmetric: a turn out of the section would need r-theta and z-theta shear, "
                "which a body of revolution cannot carry)");
    }
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

}  // namespace flowmpm
