// The sections of a case file, each read by its own file (io/case/read_*.cpp)
// into the struct it fills; read_case (io/case/case_file.cpp) calls them in
// the file's order of dependence: analysis, grid, materials, bodies, node
// sets, surface fluxes, loads, damping, reference, output. Each fails
// through its TableReader, so that messages name the file, the line, the
// key and what was expected.
#pragma once
#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include <toml++/toml.h>

#include "core/vec.hpp"
#include "io/case/case_file.hpp"
#include "io/case/case_reader.hpp"

namespace flowmpm {

inline constexpr const char* axis_names[3] = {"x", "y", "z"};

// Applies one --set KEY=VALUE to the document (io/case/overrides.cpp).
// VALUE is TOML; a value that does not parse as TOML is taken as a bare
// string (--set analysis.scheme=usf). Returns the key as messages name it
// ("bodies[0].velocity").
std::string apply_override(toml::table& root, const std::string& assignment);

// An array of `dim` numbers; zeros when the key is absent.
Vec3 vector_of(TableReader& t, std::string_view key, int dim);
// A number or an array of `dim` numbers; a single number applies to every axis.
Vec3 per_axis(TableReader& t, std::string_view key, int dim);

// [analysis]: dimension, scheme, shape function, velocity update, the time
// step's choice (TimeControl), the blow-up guard, gravity.
void read_analysis(TableReader t, Case& c);
// [grid]: origin, cell size, cells.
void read_grid(TableReader t, SystemSpec& c);
// The grid's upper end along axis d.
double grid_max(const SystemSpec& c, int d);
// [materials.NAME]: each model reads its own keys; with transport, what
// every material must then give.
void read_materials(TableReader& root, const toml::table& document, SystemSpec& c);
// [[bodies]] k: its particles, material, velocity, axes, initial state; the
// names it wins over (resolved by resolve_wins_over once all are read).
void read_body(TableReader t, SystemSpec& c, std::size_t index, const std::filesystem::path& case_file,
               std::vector<std::string>& wins_over);
void resolve_wins_over(std::vector<TableReader>& tables, SystemSpec& c,
                       const std::vector<std::vector<std::string>>& names);
// [[contact_groups]] k: bodies that share one contact field.
void read_contact_group(TableReader t, SystemSpec& c);
// [[contacts]] k: two bodies (or groups) in contact and the law between them.
void read_contact(TableReader t, SystemSpec& c);
// Once the contacts are read: every rigid body is in one, and rigid bodies
// only where the scene supports them.
void check_rigid_bodies(TableReader& root, const SystemSpec& c);
// [[node_sets]] k: a plane or box of nodes and what it prescribes.
void read_node_set(TableReader t, SystemSpec& c, std::size_t index);
// Axisymmetric: the node set "axis" holding the radial velocity at 0 on
// r = 0, where the grid reaches the axis (`grid` names grid.origin when
// the axis falls between node lines; `node_sets`, the [[node_sets]] tables
// read into c.node_sets, name node_sets[k].name when the case's own set k
// is named "axis").
void add_axis_node_set(TableReader& grid, std::vector<TableReader>& node_sets, SystemSpec& c);
// [[surface_fluxes]] k: a heat or solvent flux through a body's face.
void read_surface_flux(TableReader t, SystemSpec& c, std::size_t index);
// [[loads]]: tractions, pressures, nodal and body forces (each its own type).
void read_load(TableReader t, SystemSpec& c);
// [damping]: local and viscous coefficients.
void read_damping(TableReader t, SystemSpec& c);
// The fields written when a case does not choose, with the transported ones.
std::vector<std::string> default_fields(const SystemSpec& c);
// [output]: directory, every, fields, checkpoint_every.
void read_output(TableReader t, Case& c);

}  // namespace flowmpm
