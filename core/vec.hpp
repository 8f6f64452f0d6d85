// Small fixed-size vectors of the engine. The symbols used throughout (D, x,
// v, m, V, sigma, eps, N, dN, h, dt, t) are listed once, in
// docs/ARCHITECTURE.md "Symbols".
#pragma once
#include <array>

#include <Eigen/Core>

namespace flowmpm {

// A point or vector in D dimensions (m, m/s, ...), and a grid index.
template <int D>
using Vec = Eigen::Matrix<double, D, 1>;
template <int D>
using Index = std::array<int, D>;

// A point or vector as a case gives it, whatever the dimension: the axes the
// analysis does not have are 0.
using Vec3 = std::array<double, 3>;

// floor(g) as an int, without a libm call (std::floor is one on x86-64
// without SSE4.1); |g| must be well inside the int range.
[[gnu::always_inline]] inline int floor_to_int(double g) {
  const int i = static_cast<int>(g);
  return i - (g < static_cast<double>(i));
}

// floor(g) for g >= 0, where it is truncation: one instruction. For the
// grid coordinates of particles inside the grid (the set-up and g2p_motion
// keep every particle where its stencil has nodes, so g >= reach_below).
[[gnu::always_inline]] inline int floor_nonnegative(double g) { return static_cast<int>(g); }

}  // namespace flowmpm
