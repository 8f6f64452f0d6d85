// What a body shape (body_shape.hpp) reads besides its own table: the
// dimension of the analysis. Points are Vec3 whatever the dimension, the
// axes the analysis does not have being 0.
#pragma once
#include <string_view>
#include <vector>

#include "core/parameter_table.hpp"
#include "core/vec.hpp"

namespace flowmpm {

struct BodyShapeContext {
  int dimension = 3;
};

// An array of `dimension` numbers as a point (m); the other axes 0.
inline Vec3 read_point(ParameterTable& t, std::string_view key, int dimension) {
  const std::vector<double> values = t.numbers(key, static_cast<std::size_t>(dimension));
  Vec3 x{};
  for (int d = 0; d < dimension; ++d) x[d] = values[d];
  return x;
}

}  // namespace flowmpm
