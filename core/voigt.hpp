// Symmetric second-order tensors (stress sigma, strain eps) in Voigt order
// (xx, yy, zz, yz, xz, xy) with tensor (not engineering) shear components.
#pragma once
#include <array>

namespace flowmpm {

using Voigt = std::array<double, 6>;

// The component names, in Voigt order.
using TensorComponentNames = std::array<const char*, 6>;
inline constexpr TensorComponentNames voigt_component_names = {"xx", "yy", "zz", "yz", "xz", "xy"};
// The same in axisymmetric analysis (x the radius r, y the axial z, z the
// hoop direction theta), as results.h5 lists them (rr zz tt rz zt rt).
inline constexpr TensorComponentNames axisymmetric_component_names = {"rr", "zz", "tt", "zt", "rt", "rz"};
inline const TensorComponentNames& tensor_component_names(bool axisymmetric) {
  return axisymmetric ? axisymmetric_component_names : voigt_component_names;
}

// The order a symmetric tensor's six values are listed in outside the
// engine (case keys, particle files, results.h5): xx, yy, zz, xy, yz, xz,
// VTK's; entry k is the Voigt slot of the k-th value listed.
inline constexpr std::array<int, 6> voigt_slot_of_listed = {0, 1, 2, 5, 3, 4};

// The Voigt slot of tensor component (i, j).
constexpr int voigt_slot(int i, int j) {
  if (i == j) return i;
  const int k = 3 - i - j;  // the axis that is neither i nor j
  return 3 + k;             // yz -> 3, xz -> 4, xy -> 5
}

// a : b for symmetric tensors in Voigt order with tensor shear terms.
inline double double_contraction(const Voigt& a, const Voigt& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + 2.0 * (a[3] * b[3] + a[4] * b[4] + a[5] * b[5]);
}

}  // namespace flowmpm
