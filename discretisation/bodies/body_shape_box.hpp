// An axis-aligned box [min, max] (m): a segment in 1D, a rectangle in 2D.
// Also the bounds of every other shape (BodyShape::bounds).
#pragma once
#include "discretisation/bodies/body_shape_context.hpp"

namespace flowmpm {

struct BoxShape {
  static constexpr const char* type_name = "box";
  Vec3 min{}, max{};  // m; 0 on the axes the analysis does not have

  static BoxShape read(ParameterTable& t, const BodyShapeContext& c) {
    BoxShape box{read_point(t, "min", c.dimension), read_point(t, "max", c.dimension)};
    for (int d = 0; d < c.dimension; ++d) t.require(box.min[d] < box.max[d], "max", "a corner above min along every axis");
    return box;
  }

  // Boundary included.
  bool contains(const Vec3& x) const {
    for (int d = 0; d < 3; ++d)
      if (x[d] < min[d] || x[d] > max[d]) return false;
    return true;
  }
  BoxShape bounds() const { return *this; }
};

}  // namespace flowmpm
