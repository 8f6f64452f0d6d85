#include "io/case/case_file.hpp"

#include <fstream>
#include <map>
#include <memory>
#include <sstream>

#include "io/case/case_limits.hpp"
#include "io/case/case_reader.hpp"
#include "io/case/case_sections.hpp"
#include "io/case/digest.hpp"
#include "io/case/memory_estimate.hpp"

namespace flowmpm {

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

  read_materials(t, root, c.system);
  auto bodies = t.tables("bodies");
  if (bodies.empty()) t.fail("bodies", "at least one [[bodies]] table");
  std::vector<std::vector<std::string>> wins_over(bodies.size());
  for (std::size_t i = 0; i < bodies.size(); ++i) read_body(bodies[i], c.system, i, file, wins_over[i]);
  resolve_wins_over(bodies, c.system, wins_over);
  for (TableReader& group : t.tables("contact_groups")) read_contact_group(group, c.system);
  for (TableReader& contact : t.tables("contacts")) read_contact(contact, c.system);
  check_rigid_bodies(t, c.system);
  auto node_sets = t.tables("node_sets");
  for (std::size_t i = 0; i < node_sets.size(); ++i) read_node_set(node_sets[i], c.system, i);
  if (c.system.axisymmetric) {
    TableReader grid = t.table("grid");
    add_axis_node_set(grid, node_sets, c.system);
  }
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
