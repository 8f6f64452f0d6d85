// Set operations on shapes, so that a plate with a hole or a ring is one
// body: `parts` is an array of two or more shape tables.
//   union:        in any part;
//   intersection: in every part;
//   difference:   in the first part and in none of the others.
// The parts are BodyShapes themselves (body_shape.hpp defines the members
// that need them complete).
#pragma once
#include <vector>

#include "discretisation/bodies/body_shape_box.hpp"

namespace flowmpm {

struct BodyShape;

struct UnionOperation {
  static constexpr const char* name = "union";
};
struct IntersectionOperation {
  static constexpr const char* name = "intersection";
};
struct DifferenceOperation {
  static constexpr const char* name = "difference";
};

template <class Operation>
struct CombinedShape {
  static constexpr const char* type_name = Operation::name;
  std::vector<BodyShape> parts;  // two or more

  static CombinedShape read(ParameterTable& t, const BodyShapeContext& c);
  bool contains(const Vec3& x) const;
  BoxShape bounds() const;
};

using UnionShape = CombinedShape<UnionOperation>;
using IntersectionShape = CombinedShape<IntersectionOperation>;
using DifferenceShape = CombinedShape<DifferenceOperation>;

}  // namespace flowmpm
