// What a reference solution reads besides its own [reference] table: the
// system it measures and the run's end time. Its checks fail through the
// table, naming the file, line and key.
#pragma once
#include <string>
#include <variant>

#include "core/parameter_table.hpp"
#include "discretisation/system_spec.hpp"
#include "materials/linear_elastic.hpp"

namespace flowmpm {

struct ReferenceContext {
  const SystemSpec& system;
  double end_time;  // s
};

// The linear elastic material of the first body: the analytical solutions
// are those of linear elasticity.
inline const LinearElastic& elastic_material(ParameterTable& t, const ReferenceContext& context) {
  const SystemSpec& s = context.system;
  if (s.bodies.at(0).rigid()) t.fail("type", "a case whose first body is not rigid (the solution is elastic)");
  const LinearElastic* m = std::get_if<LinearElastic>(&s.materials.at(s.bodies.at(0).material).model);
  if (!m) t.fail("type", "a case whose first body is linear_elastic (the analytical solution is elastic)");
  return *m;
}

}  // namespace flowmpm
