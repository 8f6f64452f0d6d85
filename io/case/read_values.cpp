// Vectors of numbers read from a case table.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "core/number_text.hpp"
#include "io/case/case_limits.hpp"
#include "io/case/case_reader.hpp"
#include "io/case/case_sections.hpp"

namespace flowmpm {

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

}  // namespace flowmpm
