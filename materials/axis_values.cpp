#include "materials/axis_values.hpp"

#include <vector>

#include "core/parameter_table.hpp"

namespace flowmpm {

std::array<double, 3> read_axis_values(ParameterTable& t, std::string_view key, const AxisLayout& layout) {
  std::vector<double> values;
  if (layout.count == 1) {
    values.push_back(t.number(key));
  } else {
    values = t.numbers(key, layout.count);
  }
  std::array<double, 3> along_axes{};
  for (int i = 0; i < 3; ++i) along_axes[i] = values[static_cast<std::size_t>(layout.source[i])];
  return along_axes;
}

}  // namespace flowmpm
