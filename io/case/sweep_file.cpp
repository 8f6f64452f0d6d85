#include "io/case/sweep_file.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <map>
#include <sstream>
#include <utility>

#include "io/case/case_reader.hpp"
#include "io/case/digest.hpp"
#include "io/results/quoted_string.hpp"

namespace flowmpm {
namespace {

// The product expands at most this many cases (each is read up front).
constexpr std::size_t max_cases = 100000;


// The shortest text that reads back to the same double, kept a TOML float:
// positional from 1e-4 to 1e16 (0.0004, not 4e-04), scientific outside.
std::string float_text(double value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value < 0.0 ? "-inf" : "inf";
  const double size = std::abs(value);
  const bool positional = size == 0.0 || (size >= 1e-4 && size < 1e16);
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value,
                                    positional ? std::chars_format::fixed : std::chars_format::scientific);
  std::string text(buffer, result.ptr);
  if (text.find_first_of(".e") == std::string::npos) text += ".0";
  return text;
}

std::string key_text(std::string_view key) {
  const bool bare = !key.empty() && std::all_of(key.begin(), key.end(), [](char c) {
    return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' || c == '-';
  });
  return bare ? std::string(key) : quoted_string(key);
}

// One factor of the product: a [vary] key, or a [[zip]] whose keys advance
// together. items[i][k] is the TOML text of key k in item i.
struct Factor {
  std::vector<std::string> keys;
  std::vector<std::vector<std::string>> items;
  std::vector<std::vector<std::string>> cells;  // the same, as CSV cells
};

// The keys of a table in file order (toml++ keeps them sorted by name).
std::vector<std::pair<std::string, const toml::node*>> keys_in_file_order(const toml::table& table) {
  std::vector<std::pair<std::string, const toml::node*>> keys;
  for (auto&& [key, value] : table) keys.emplace_back(std::string(key.str()), &value);
  std::stable_sort(keys.begin(), keys.end(),
                   [](const auto& a, const auto& b) { return a.second->source().begin < b.second->source().begin; });
  return keys;
}

// Checks that `key` names a case key and is varied only once.
void check_key(const TableReader& t, const std::string& key, const toml::node& value,
               std::map<std::string, std::string>& varied) {
  const std::string where = source_of(value, t.file());
  const bool well_formed = !key.empty() && key.find('=') == std::string::npos && key.front() != '.' &&
                           key.back() != '.' && key.find("..") == std::string::npos;
  if (!well_formed) {
    throw CaseError(where + ": " + t.dotted(key) + ": expected a dotted case key such as \"analysis.dt\"");
  }
  const auto [it, inserted] = varied.emplace(key, where);
  if (!inserted) {
    throw CaseError(where + ": " + t.dotted(key) + ": " + key + " is varied twice (also at " + it->second + ")");
  }
}

// The values of one varied key: a non-empty array of any TOML values.
const toml::array& values_of(const TableReader& t, const std::string& key, const toml::node& value) {
  const toml::array* array = value.as_array();
  if (!array || array->empty()) {
    std::string expected = "a non-empty array of values, one per case";
    if (value.is_table()) expected += " (quote a dotted key: \"analysis.dt\" = [0.01, 0.001])";
    t.fail(key, expected);
  }
  return *array;
}

std::string cell_text(const toml::node& value) {
  return value.is_string() ? std::string(*value.value<std::string>()) : toml_text(value);
}

std::string joined(const std::vector<std::string>& parts, std::string_view separator) {
  std::string out;
  for (const std::string& p : parts) out += (out.empty() ? "" : std::string(separator)) + p;
  return out;
}

// The digest of the file's text (io/case/digest.hpp).
std::string digest_of_file(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return hex_digest(fnv1a(text.str()));
}

toml::table parse_sweep_file(const std::filesystem::path& file) {
  if (!std::filesystem::is_regular_file(file)) throw CaseError(file.string() + ": no such file");
  try {
    return toml::parse_file(file.string());
  } catch (const toml::parse_error& e) {
    throw CaseError(file.string() + ":" + std::to_string(e.source().begin.line) +
                    ": not valid TOML: " + std::string(e.description()));
  }
}

}  // namespace

std::string toml_text(const toml::node& value) {
  switch (value.type()) {
    case toml::node_type::string: return quoted_string(*value.value<std::string>());
    case toml::node_type::integer: return std::to_string(*value.value<std::int64_t>());
    case toml::node_type::floating_point: return float_text(*value.value<double>());
    case toml::node_type::boolean: return *value.value<bool>() ? "true" : "false";
    case toml::node_type::array: {
      std::vector<std::string> items;
      for (const toml::node& item : *value.as_array()) items.push_back(toml_text(item));
      return "[" + joined(items, ", ") + "]";
    }
    case toml::node_type::table: {
      std::vector<std::string> items;
      for (auto&& [key, item] : *value.as_table()) items.push_back(key_text(key.str()) + " = " + toml_text(item));
      return items.empty() ? "{}" : "{ " + joined(items, ", ") + " }";
    }
    default: {
      // Dates and times, in toml++'s own (TOML) form.
      std::ostringstream text;
      value.visit([&text](const auto& v) { text << toml::toml_formatter{v}; });
      return text.str();
    }
  }
}

Sweep read_sweep(const std::filesystem::path& file) {
  const toml::table root = parse_sweep_file(file);
  TableReader t(root, "", file.string());
  Sweep sweep;
  sweep.file = file;
  sweep.base = (file.parent_path() / t.string("base")).lexically_normal();
  if (!std::filesystem::is_regular_file(sweep.base)) {
    t.fail("base", "a case file, relative to the sweep file (" + sweep.base.string() + " does not exist)");
  }
  sweep.base_digest = digest_of_file(sweep.base);
  sweep.output = t.has("output") ? std::filesystem::path(t.string("output"))
                                 : std::filesystem::path("results/sweeps") / file.stem();

  std::vector<Factor> factors;
  std::map<std::string, std::string> varied;
  if (t.has("vary")) {
    TableReader vary = t.table("vary");
    for (const auto& [key, value] : keys_in_file_order(*root.get("vary")->as_table())) {
      vary.node(key);
      const toml::array& values = values_of(vary, key, *value);
      check_key(vary, key, *value, varied);
      Factor f{{key}, {}, {}};
      for (const toml::node& v : values) {
        f.items.push_back({toml_text(v)});
        f.cells.push_back({cell_text(v)});
      }
      factors.push_back(std::move(f));
    }
  }
  const std::vector<TableReader> zips = t.tables("zip");
  for (std::size_t i = 0; i < zips.size(); ++i) {
    TableReader zip = zips[i];
    const auto keys = keys_in_file_order(*root.get("zip")->as_array()->get(i)->as_table());
    if (keys.empty()) zip.fail_table("expected at least one key, e.g. \"analysis.dt\" = [0.01, 0.001]");
    Factor f;
    for (const auto& [key, value] : keys) {
      zip.node(key);
      const toml::array& values = values_of(zip, key, *value);
      check_key(zip, key, *value, varied);
      if (f.keys.empty()) {
        f.items.resize(values.size());
        f.cells.resize(values.size());
      } else if (values.size() != f.items.size()) {
        throw CaseError(source_of(*value, file.string()) + ": " + zip.dotted(key) + ": " +
                        std::to_string(values.size()) + " values, but " + zip.dotted(f.keys.front()) + " has " +
                        std::to_string(f.items.size()) + "; the keys of a [[zip]] advance together, so their "
                        "lists need equal lengths");
      }
      f.keys.push_back(key);
      for (std::size_t j = 0; j < values.size(); ++j) {
        f.items[j].push_back(toml_text(*values.get(j)));
        f.cells[j].push_back(cell_text(*values.get(j)));
      }
    }
    factors.push_back(std::move(f));
  }
  t.reject_unknown_keys();

  std::size_t count = 1;
  for (const Factor& f : factors) {
    sweep.keys.insert(sweep.keys.end(), f.keys.begin(), f.keys.end());
    count *= f.items.size();
    if (count > max_cases) {
      throw CaseError(file.string() + ": the sweep expands to more than " + std::to_string(max_cases) + " cases");
    }
  }

  const std::size_t width = std::max<std::size_t>(3, std::to_string(count - 1).size());
  for (std::size_t n = 0; n < count; ++n) {
    SweepCase sc;
    sc.id = std::to_string(n);
    sc.id.insert(0, width - sc.id.size(), '0');
    // Mixed radix, the last factor fastest.
    std::vector<std::size_t> index(factors.size());
    std::size_t rest = n;
    for (std::size_t k = factors.size(); k-- > 0;) {
      index[k] = rest % factors[k].items.size();
      rest /= factors[k].items.size();
    }
    for (std::size_t k = 0; k < factors.size(); ++k) {
      const Factor& f = factors[k];
      for (std::size_t j = 0; j < f.keys.size(); ++j) {
        sc.overrides.push_back(f.keys[j] + "=" + f.items[index[k]][j]);
        sc.values.push_back(f.cells[index[k]][j]);
      }
    }
    try {
      sc.c = read_case(sweep.base, sc.overrides);
    } catch (const CaseError& e) {
      const std::string with = sc.overrides.empty() ? "the base case" : joined(sc.overrides, ", ");
      throw CaseError(file.string() + ": case " + sc.id + " (" + with + "): " + e.what());
    }
    sweep.cases.push_back(std::move(sc));
  }
  return sweep;
}

}  // namespace flowmpm
