// [output]: where the results go, how often, and which fields.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "core/number_text.hpp"
#include "io/case/case_limits.hpp"
#include "io/case/case_reader.hpp"
#include "io/case/case_sections.hpp"
#include "engine/take_snapshot.hpp"

namespace flowmpm {

namespace {

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

}  // namespace

// The fields written when a case does not choose, with the transported ones.
std::vector<std::string> default_fields(const SystemSpec& c) {
  std::vector<std::string> names = default_output_fields();
  if (c.conducts_heat()) names.emplace_back("temperature");
  if (c.diffuses_solvent()) names.emplace_back("concentration");
  return names;
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

}  // namespace flowmpm
