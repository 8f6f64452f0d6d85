#include "materials/transport_properties.hpp"

#include <string>

#include "core/parameter_table.hpp"

namespace flowmpm {

TransportProperties TransportProperties::read(ParameterTable& t, const AxisLayout& layout) {
  TransportProperties p;
  const std::string per_axis = layout.count == 1 ? "" : std::string(", ") + layout.description;
  if (t.has("heat_capacity")) {
    p.heat_capacity = t.positive("heat_capacity", "a positive specific heat capacity in J/(kg K)");
  }
  auto nonnegative = [&](const char* key, const char* what) {
    Eigen::Vector3d v = Eigen::Vector3d::Zero();
    if (!t.has(key)) return v;
    const std::array<double, 3> values = read_axis_values(t, key, layout);
    for (int i = 0; i < 3; ++i) {
      t.require(values[i] >= 0.0, key, std::string(what) + " >= 0" + per_axis);
      v[i] = values[i];
    }
    return v;
  };
  p.conductivity = nonnegative("conductivity", "a thermal conductivity in W/(m K)");
  p.diffusivity = nonnegative("diffusivity", "a solvent diffusivity in m^2/s");
  if (p.conducts() && p.heat_capacity == 0.0) {
    t.fail("heat_capacity", "the specific heat capacity in J/(kg K) (conductivity is given)");
  }
  if (t.has("reference_temperature")) {
    p.reference_temperature = t.positive("reference_temperature", "the stress-free temperature in K (> 0)");
  }
  return p;
}

}  // namespace flowmpm
