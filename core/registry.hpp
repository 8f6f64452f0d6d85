// A registry of named alternatives: the models of materials/material.hpp,
// the references of verification/reference.hpp, the body shapes and loads
// of discretisation/. Each is a std::variant whose alternatives declare
//   static constexpr const char* type_name;            // the case file's `type`
//   static Alternative read(ParameterTable&, Context...);
// so that adding one is one new file and one line in the variant. An
// unknown name is an error listing the known ones.
#pragma once
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "core/parameter_table.hpp"

namespace flowmpm {

// "\"a\", \"b\", \"c\"", for messages.
inline std::string quoted_list(const std::vector<std::string>& names) {
  std::string text;
  for (const std::string& n : names) text += (text.empty() ? "\"" : ", \"") + n + "\"";
  return text;
}

template <class Variant>
struct Registry;

template <class... Alternatives>
struct Registry<std::variant<Alternatives...>> {
  using Variant = std::variant<Alternatives...>;

  static std::vector<std::string> names() { return {Alternatives::type_name...}; }

  // Reads the alternative named by the table's `key` (default "type"),
  // which reads the rest of the table.
  template <class... Context>
  static Variant read(ParameterTable& table, std::string_view key, const Context&... context) {
    const std::string type = table.choice(key, names());
    std::optional<Variant> result;
    ((type == Alternatives::type_name ? void(result.emplace(Alternatives::read(table, context...))) : void()), ...);
    return std::move(*result);
  }

  // The type name of the alternative held.
  static const char* name_of(const Variant& v) {
    return std::visit([](const auto& a) { return std::decay_t<decltype(a)>::type_name; }, v);
  }
};

}  // namespace flowmpm
