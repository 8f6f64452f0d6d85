// A ball |x - center| <= radius: a sphere in 3D, a disk in 2D, a segment
// in 1D.
#pragma once
#include "discretisation/bodies/body_shape_box.hpp"

namespace flowmpm {

struct SphereShape {
  static constexpr const char* type_name = "sphere";
  Vec3 center{};        // m
  double radius = 0.0;  // m
  int dimension = 3;

  static SphereShape read(ParameterTable& t, const BodyShapeContext& c) {
    return {read_point(t, "center", c.dimension), t.positive("radius", "a positive radius in m"), c.dimension};
  }

  // Boundary included.
  bool contains(const Vec3& x) const {
    double r2 = 0.0;
    for (int d = 0; d < 3; ++d) r2 += (x[d] - center[d]) * (x[d] - center[d]);
    return r2 <= radius * radius;
  }
  BoxShape bounds() const {
    BoxShape b;
    for (int d = 0; d < dimension; ++d) {
      b.min[d] = center[d] - radius;
      b.max[d] = center[d] + radius;
    }
    return b;
  }
};

}  // namespace flowmpm
