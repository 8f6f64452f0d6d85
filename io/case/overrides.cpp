// --set KEY=VALUE applied to a case document before it is read.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "core/number_text.hpp"
#include "io/case/case_limits.hpp"
#include "io/case/case_reader.hpp"
#include "io/case/case_sections.hpp"

namespace flowmpm {

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

}  // namespace flowmpm
