// A circular cylinder (3D only; in 2D a disk is a sphere): the points
// within `radius` of the axis through `center` along `axis`, and within
// length / 2 of `center` along it.
#pragma once
#include <cmath>

#include "discretisation/bodies/body_shape_box.hpp"

namespace flowmpm {

struct CylinderShape {
  static constexpr const char* type_name = "cylinder";
  int axis = 2;
  Vec3 center{};        // m, the middle of the cylinder's axis
  double radius = 0.0;  // m
  double length = 0.0;  // m, along the axis

  static CylinderShape read(ParameterTable& t, const BodyShapeContext& c) {
    t.require(c.dimension == 3, "type", "a shape of a 2D or 1D analysis (a cylinder is 3D; in 2D a disk is a \"sphere\")");
    CylinderShape s;
    s.axis = read_axis(t, "axis", 3);
    s.center = read_point(t, "center", 3);
    s.radius = t.positive("radius", "a positive radius in m");
    s.length = t.positive("length", "a positive length along the axis in m");
    return s;
  }

  // Boundary included.
  bool contains(const Vec3& x) const {
    double r2 = 0.0;
    for (int d = 0; d < 3; ++d)
      if (d != axis) r2 += (x[d] - center[d]) * (x[d] - center[d]);
    return r2 <= radius * radius && std::abs(x[axis] - center[axis]) <= 0.5 * length;
  }
  BoxShape bounds() const {
    BoxShape b;
    for (int d = 0; d < 3; ++d) {
      const double half = d == axis ? 0.5 * length : radius;
      b.min[d] = center[d] - half;
      b.max[d] = center[d] + half;
    }
    return b;
  }
};

}  // namespace flowmpm
