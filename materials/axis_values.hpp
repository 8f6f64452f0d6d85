// Properties given per material axis (expansion coefficients,
// conductivity, diffusivity): one number for an isotropic model,
// [axial, transverse] for a transversely isotropic one, [x, y, z] for an
// orthotropic one. The layout says how the case file's numbers map onto the
// three material axes.
#pragma once
#include <array>
#include <cstddef>
#include <string_view>

namespace flowmpm {

class ParameterTable;

struct AxisLayout {
  std::size_t count;          // numbers in the case file: 1 (a number), 2 or 3 (an array)
  std::array<int, 3> source;  // material axis i takes the number source[i]
  const char* description;    // for messages: "one per material axis x, y, z"
};

inline constexpr AxisLayout isotropic_axes{1, {0, 0, 0}, "one number (isotropic)"};
inline constexpr AxisLayout orthotropic_axes{3, {0, 1, 2}, "one per material axis x, y, z"};
// Transversely isotropic with the axial direction along material z or y.
inline constexpr AxisLayout transverse_axes_z{2, {1, 1, 0}, "[axial, transverse]"};
inline constexpr AxisLayout transverse_axes_y{2, {1, 0, 1}, "[axial, transverse]"};

// The values of `key` along the material axes x, y, z (a number, or an
// array of layout.count numbers).
std::array<double, 3> read_axis_values(ParameterTable& t, std::string_view key, const AxisLayout& layout);

}  // namespace flowmpm
