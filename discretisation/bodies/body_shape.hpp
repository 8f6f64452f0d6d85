// The registry of body shapes: the region a body's particles fill
// (build_system.hpp fills it on a lattice) and the regions that loads
// select particles in. Each shape is a type with
//   static constexpr const char* type_name;            // the table's `type`
//   static Shape read(ParameterTable&, const BodyShapeContext&);
//   bool contains(const Vec3& x) const;                // boundary included
//   BoxShape bounds() const;                           // an enclosing box
// Adding one is one new file and one line in the variant below
// (docs/ARCHITECTURE.md "A load, a body shape").
#pragma once
#include <algorithm>
#include <variant>

#include "core/registry.hpp"
#include "discretisation/bodies/body_shape_box.hpp"
#include "discretisation/bodies/body_shape_combination.hpp"
#include "discretisation/bodies/body_shape_cylinder.hpp"
#include "discretisation/bodies/body_shape_sphere.hpp"

namespace flowmpm {

struct BodyShape {
  using Variant = std::variant<BoxShape, SphereShape, CylinderShape, UnionShape, IntersectionShape, DifferenceShape>;
  Variant shape;

  // Reads a shape table: `type`, then the shape's own keys.
  static BodyShape read(ParameterTable& t, const BodyShapeContext& c);

  bool contains(const Vec3& x) const {
    return std::visit([&](const auto& s) { return s.contains(x); }, shape);
  }
  BoxShape bounds() const {
    return std::visit([](const auto& s) { return s.bounds(); }, shape);
  }
  const char* type() const { return Registry<Variant>::name_of(shape); }
};

inline std::vector<std::string> body_shape_names() { return Registry<BodyShape::Variant>::names(); }

inline BodyShape BodyShape::read(ParameterTable& t, const BodyShapeContext& c) {
  return {Registry<Variant>::read(t, "type", c)};
}

template <class Operation>
CombinedShape<Operation> CombinedShape<Operation>::read(ParameterTable& t, const BodyShapeContext& c) {
  CombinedShape s;
  t.read_tables("parts", [&](ParameterTable& part) { s.parts.push_back(BodyShape::read(part, c)); });
  t.require(s.parts.size() >= 2, "parts", std::string("two or more shape tables ([[...parts]]) for a ") + type_name);
  if constexpr (std::is_same_v<Operation, IntersectionOperation>) {
    const BoxShape b = s.bounds();
    for (int d = 0; d < c.dimension; ++d)
      t.require(b.min[d] < b.max[d], "parts", "parts whose bounding boxes overlap (an intersection that can hold particles)");
  }
  return s;
}

template <class Operation>
bool CombinedShape<Operation>::contains(const Vec3& x) const {
  if constexpr (std::is_same_v<Operation, UnionOperation>) {
    return std::ranges::any_of(parts, [&](const BodyShape& p) { return p.contains(x); });
  } else if constexpr (std::is_same_v<Operation, IntersectionOperation>) {
    return std::ranges::all_of(parts, [&](const BodyShape& p) { return p.contains(x); });
  } else {
    return parts.front().contains(x) &&
           std::none_of(parts.begin() + 1, parts.end(), [&](const BodyShape& p) { return p.contains(x); });
  }
}

// Union: the box around every part's; intersection: the common part of
// theirs; difference: the first part's.
template <class Operation>
BoxShape CombinedShape<Operation>::bounds() const {
  BoxShape b = parts.front().bounds();
  if constexpr (!std::is_same_v<Operation, DifferenceOperation>) {
    constexpr bool hull = std::is_same_v<Operation, UnionOperation>;
    for (std::size_t i = 1; i < parts.size(); ++i) {
      const BoxShape p = parts[i].bounds();
      for (int d = 0; d < 3; ++d) {
        b.min[d] = hull ? std::min(b.min[d], p.min[d]) : std::max(b.min[d], p.min[d]);
        b.max[d] = hull ? std::max(b.max[d], p.max[d]) : std::min(b.max[d], p.max[d]);
      }
    }
  }
  return b;
}

}  // namespace flowmpm
