// Symbols used throughout (listed once, after STYLE.md rule 8):
//   D      spatial dimension (1, 2, 3), a compile-time parameter
//   x, v   particle position (m) and velocity (m/s)
//   m, V   particle mass (kg) and volume (m^3)
//   sigma  Cauchy stress (Pa), eps small strain (-), both symmetric and kept
//          in Voigt order (xx, yy, zz, yz, xz, xy) with tensor shear terms
//   N, dN  shape function of a node at a particle, and its gradient (1/m)
//   h      cell size (m), dt time step (s), t time (s)
#pragma once
#include <array>
#include <cstdint>

#include <Eigen/Core>

namespace flowmpm {

template <int D>
using Vec = Eigen::Matrix<double, D, 1>;
template <int D>
using Index = std::array<int, D>;

// Symmetric tensor in Voigt order (xx, yy, zz, yz, xz, xy), tensor components.
using Voigt = std::array<double, 6>;

// The Voigt slot of tensor component (i, j).
constexpr int voigt_slot(int i, int j) {
  if (i == j) return i;
  const int k = 3 - i - j;  // the axis that is neither i nor j
  return 3 + k;             // yz -> 3, xz -> 4, xy -> 5
}

// floor(g) as an int, without a libm call (std::floor is one on x86-64
// without SSE4.1); |g| must be well inside the int range.
[[gnu::always_inline]] inline int floor_to_int(double g) {
  const int i = static_cast<int>(g);
  return i - (g < static_cast<double>(i));
}

// floor(g) for g >= 0, where it is truncation: one instruction. For the
// grid coordinates of particles inside the grid (build_model and g2p_motion
// keep every particle where its stencil has nodes, so g >= reach_below).
[[gnu::always_inline]] inline int floor_nonnegative(double g) { return static_cast<int>(g); }

// sigma : eps for symmetric tensors in Voigt order with tensor shear terms.
inline double double_contraction(const Voigt& a, const Voigt& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + 2.0 * (a[3] * b[3] + a[4] * b[4] + a[5] * b[5]);
}

}  // namespace flowmpm
