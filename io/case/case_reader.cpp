#include "io/case/case_reader.hpp"

#include "core/registry.hpp"
#include "io/case/key_registry.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>

namespace flowmpm {
namespace {

std::string describe(const toml::node& node) {
  switch (node.type()) {
    case toml::node_type::table: return "a table";
    case toml::node_type::array: {
      const std::size_t n = node.as_array()->size();
      return "an array of " + std::to_string(n) + (n == 1 ? " item" : " items");
    }
    case toml::node_type::string: return "the string \"" + std::string(*node.value<std::string>()) + "\"";
    case toml::node_type::integer: return "the integer " + std::to_string(*node.value<std::int64_t>());
    case toml::node_type::floating_point: {
      std::ostringstream s;
      s << "the number " << *node.value_exact<double>();
      return s.str();
    }
    case toml::node_type::boolean: return *node.value<bool>() ? "true" : "false";
    default: return "a date or time";
  }
}

// Levenshtein distance: insertions, deletions and substitutions.
std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

// Numbers the engine can compute with. Integers beyond 2^53 have no
// exact double. Magnitudes outside [1e-100, 1e100] (other than 0) would
// under- or overflow what the engine makes of them (a modulus over a
// density, squared, times dt squared): doubles span about 1e-308 to 1e308,
// and the cube of a number inside the bounds stays inside that range.
constexpr std::int64_t largest_exact_integer = std::int64_t{1} << 53;
constexpr double largest_number = 1e100, smallest_number = 1e-100;
constexpr const char* number_bounds =
    "a finite number of magnitude 0 or between 1e-100 and 1e100 (an integer up to 2^53 = 9007199254740992)";

std::optional<double> usable_number(const toml::node& node) {
  if (const auto* i = node.as_integer()) {
    // Compared as integers: 2^53 + 1 rounds to 2^53 as a double.
    const std::int64_t value = i->get();
    if (value > largest_exact_integer || value < -largest_exact_integer) return std::nullopt;
    return static_cast<double>(value);
  }
  const auto* f = node.as_floating_point();
  if (!f) return std::nullopt;
  const double value = f->get();
  const double size = std::abs(value);
  if (!std::isfinite(value) || size > largest_number || (size != 0.0 && size < smallest_number)) return std::nullopt;
  return value;
}

}  // namespace

std::string source_of(const toml::node& node, const std::string& fallback_file) {
  const auto& src = node.source();
  std::string file = src.path ? *src.path : fallback_file;
  if (src.begin.line == 0) return file;
  return file + ":" + std::to_string(src.begin.line);
}

TableReader::TableReader(const toml::table& table, std::string path, std::string file,
                         std::shared_ptr<const std::map<std::string, std::string>> overrides)
    : table_(&table), path_(std::move(path)), file_(std::move(file)), overrides_(std::move(overrides)) {}

std::string TableReader::dotted(std::string_view key) const {
  return path_.empty() ? std::string(key) : path_ + "." + std::string(key);
}

void TableReader::ask(std::string_view key) const {
  known_.emplace(key);
  record_asked_key(path_, key);
}

bool TableReader::has(std::string_view key) const {
  ask(key);
  return table_->contains(key);
}

std::string TableReader::location(const toml::node& node, std::string_view key) const {
  if (overrides_) {
    // A key set by --set, or inside a table set by --set.
    const std::string full = dotted(key);
    for (const auto& [set_key, assignment] : *overrides_) {
      if (full == set_key || full.starts_with(set_key + ".") || full.starts_with(set_key + "[")) return assignment;
    }
  }
  return source_of(node, file_);
}

std::string TableReader::failure_at(const toml::node& node, std::string_view key, std::string_view expected) const {
  return location(node, key) + ": " + dotted(key) + ": expected " + std::string(expected) + ", got " + describe(node);
}

void TableReader::fail_at(const toml::node& node, std::string_view key, std::string_view expected) const {
  throw CaseError(failure_at(node, key, expected));
}

std::string TableReader::failure(std::string_view key, std::string_view expected) const {
  if (const toml::node* n = table_->get(key)) return failure_at(*n, key, expected);
  return source_of(*table_, file_) + ": " + dotted(key) + ": missing; expected " + std::string(expected);
}

std::string TableReader::table_failure(std::string_view message) const {
  return source_of(*table_, file_) + ": " + (path_.empty() ? "case" : path_) + ": " + std::string(message);
}

const toml::node& TableReader::required(std::string_view key) {
  const toml::node* n = table_->get(key);
  if (!n) {
    throw CaseError(source_of(*table_, file_) + ": " + dotted(key) + ": missing required key");
  }
  used_.emplace(key);
  ask(key);
  return *n;
}

const toml::node* TableReader::node(std::string_view key) {
  const toml::node* n = table_->get(key);
  ask(key);
  if (n) used_.emplace(key);
  return n;
}

double TableReader::number(std::string_view key) {
  const toml::node& n = required(key);
  if (!n.is_number()) fail_at(n, key, "a number");
  const std::optional<double> value = usable_number(n);
  if (!value) fail_at(n, key, number_bounds);
  return *value;
}

std::int64_t TableReader::integer(std::string_view key) {
  const toml::node& n = required(key);
  if (!n.is_integer()) fail_at(n, key, "an integer");
  return *n.value<std::int64_t>();
}

std::string TableReader::string(std::string_view key) {
  const toml::node& n = required(key);
  if (!n.is_string()) fail_at(n, key, "a string");
  return std::string(*n.value<std::string>());
}

std::string TableReader::choice(std::string_view key, const std::vector<std::string>& allowed,
                                std::string_view fallback) {
  if (!has(key) && !fallback.empty()) return std::string(fallback);
  const toml::node& n = required(key);
  if (n.is_string()) {
    const std::string value(*n.value<std::string>());
    for (const std::string& a : allowed)
      if (value == a) return value;
  }
  fail_at(n, key, "one of " + quoted_list(allowed));
}

std::vector<double> TableReader::numbers(std::string_view key, std::size_t count) {
  const toml::node& n = required(key);
  const toml::array* array = n.as_array();
  const std::string expected = "an array of " + std::to_string(count) + " numbers";
  if (!array || array->size() != count) fail_at(n, key, expected);
  std::vector<double> values;
  for (const toml::node& item : *array) {
    const std::optional<double> value = usable_number(item);
    if (!value) fail_at(n, key, expected + ", each " + number_bounds);
    values.push_back(*value);
  }
  return values;
}

std::vector<std::string> TableReader::strings(std::string_view key) {
  const toml::node& n = required(key);
  const toml::array* array = n.as_array();
  if (!array) fail_at(n, key, "an array of strings");
  std::vector<std::string> values;
  for (const toml::node& item : *array) {
    if (!item.is_string()) fail_at(n, key, "an array of strings");
    values.emplace_back(*item.value<std::string>());
  }
  return values;
}

TimeFunction TableReader::time_function(std::string_view key, std::string_view what) {
  const toml::node& n = required(key);
  if (n.is_number()) return TimeFunction{{{0.0, number(key)}}};
  const std::string expected =
      std::string(what) + ", or an array of [time in s, value] pairs with increasing times";
  const toml::array* points = n.as_array();
  if (!points || points->empty()) fail_at(n, key, expected);
  TimeFunction f;
  for (const toml::node& p : *points) {
    const toml::array* pair = p.as_array();
    if (!pair || pair->size() != 2) fail_at(n, key, expected);
    const std::optional<double> time = usable_number(*pair->get(0)), value = usable_number(*pair->get(1));
    if (!time || !value) fail_at(n, key, expected + ", each " + number_bounds);
    if (!f.points.empty() && *time <= f.points.back().first) fail_at(n, key, expected);
    f.points.emplace_back(*time, *value);
  }
  return f;
}

void TableReader::read_table(std::string_view key, const std::function<void(ParameterTable&)>& read) {
  TableReader sub = table(key);
  read(sub);
  sub.reject_unknown_keys();
}

void TableReader::read_tables(std::string_view key, const std::function<void(ParameterTable&)>& read) {
  for (TableReader& sub : tables(key)) {
    read(sub);
    sub.reject_unknown_keys();
  }
}

std::string TableReader::where(std::string_view key) const {
  if (key.empty()) return source_of(*table_, file_) + ": " + (path_.empty() ? "case" : path_);
  const toml::node* n = table_->get(key);
  return (n ? location(*n, key) : source_of(*table_, file_)) + ": " + dotted(key);
}

TableReader TableReader::table(std::string_view key) {
  const toml::node& n = required(key);
  if (!n.is_table()) fail_at(n, key, "a table");
  return TableReader(*n.as_table(), dotted(key), file_, overrides_);
}

std::vector<TableReader> TableReader::tables(std::string_view key) {
  std::vector<TableReader> result;
  const toml::node* n = node(key);
  if (!n) return result;
  const toml::array* array = n->as_array();
  if (!array || (!array->empty() && !array->is_array_of_tables())) {
    fail_at(*n, key, "an array of tables ([[" + dotted(key) + "]])");
  }
  for (std::size_t i = 0; i < array->size(); ++i) {
    result.emplace_back(*array->get(i)->as_table(), dotted(key) + "[" + std::to_string(i) + "]", file_, overrides_);
  }
  return result;
}

void TableReader::reject_unknown_keys() const {
  for (auto&& [key, value] : *table_) {
    if (used_.count(key.str())) continue;
    // The nearest understood key by edit distance, if it is a likely typo.
    std::string nearest;
    std::size_t best = 3;
    for (const std::string& candidate : known_) {
      const std::size_t d = edit_distance(key.str(), candidate);
      if (d < best) best = d, nearest = candidate;
    }
    throw CaseError(location(value, key.str()) + ": " + dotted(key.str()) + ": unknown key" +
                    (nearest.empty() ? "" : " (did you mean " + dotted(nearest) + "?)"));
  }
}

}  // namespace flowmpm
