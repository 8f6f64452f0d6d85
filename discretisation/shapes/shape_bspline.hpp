// Quadratic and cubic B-spline shape functions on the uniform grid
// [Steffen 2008]: C1 and C2 continuous, so particles
// crossing cells cause no jump in force. With r = |x - x_I| / h:
//   quadratic: N = 3/4 - r^2 (r < 1/2), (3/2 - r)^2 / 2 (1/2 <= r < 3/2)
//   cubic:     N = 2/3 - r^2 + r^3/2 (r < 1), (2 - r)^3 / 6 (1 <= r < 2)
// The grid must extend beyond the material: a particle needs all nodes of
// its stencil (see docs/theory/shape_functions.md).
#pragma once
#include <array>

#include "core/vec.hpp"

namespace flowmpm {

struct QuadraticBSpline {
  static constexpr const char* name = "bspline2";
  static constexpr int support = 3;
  static constexpr int reach_below = 1;  // nodes c - 1 ... c + 2, three of them
  static constexpr int reach_above = 2;
  static constexpr bool gradient_jumps = false;  // |dN|^2 / N bounded
  // APIC: D_p = sum_I N_Ip (x_I - x_p)(x_I - x_p)^T = h^2 / 4 I wherever the
  // particle is [Jiang 2015] (docs/theory/transfers.md).
  static constexpr double apic_inertia = 0.25;
  // Stable time step in h / c, 1 to 4 particles per cell (docs/STABILITY.md):
  // USL at a free surface; USF and MUSL as measured on the 2D column, lower
  // than the 2.3 of the bar (not explained).
  static constexpr std::array<double, 4> stable_factor_usl{0.67, 0.74, 0.75, 0.76};
  static constexpr std::array<double, 4> stable_factor_remapped{0.54, 0.54, 0.54, 0.54};

  [[gnu::always_inline]] static void stencil(double g, double inv_h, double, int& base, double (&w)[support],
                                             double (&dw)[support]) {
    base = floor_nonnegative(g - 0.5);  // g >= reach_below = 1
    const double t = g - base;  // in [0.5, 1.5): distance to the first node
    const double a = 1.5 - t, b = t - 1.0, c = t - 0.5;
    w[0] = 0.5 * a * a;
    w[1] = 0.75 - b * b;
    w[2] = 0.5 * c * c;
    dw[0] = -a * inv_h;
    dw[1] = -2.0 * b * inv_h;
    dw[2] = c * inv_h;
  }
};

struct CubicBSpline {
  static constexpr const char* name = "bspline3";
  static constexpr int support = 4;
  static constexpr int reach_below = 1;  // nodes c - 1 ... c + 2
  static constexpr int reach_above = 2;
  static constexpr bool gradient_jumps = false;  // |dN|^2 / N bounded
  static constexpr double apic_inertia = 1.0 / 3.0;  // APIC: D_p = h^2 / 3 I
  // Stable time step in h / c, 1 to 4 particles per cell (docs/STABILITY.md).
  static constexpr std::array<double, 4> stable_factor_usl{1.02, 1.09, 1.11, 1.11};
  static constexpr std::array<double, 4> stable_factor_remapped{0.90, 0.90, 0.90, 0.90};

  [[gnu::always_inline]] static void stencil(double g, double inv_h, double, int& base, double (&w)[support],
                                             double (&dw)[support]) {
    const int c = floor_nonnegative(g);  // g >= reach_below = 1
    base = c - 1;
    const double t = g - c, u = 1.0 - t;  // t in [0, 1)
    w[0] = u * u * u / 6.0;
    w[1] = 2.0 / 3.0 - t * t + 0.5 * t * t * t;
    w[2] = 2.0 / 3.0 - u * u + 0.5 * u * u * u;
    w[3] = t * t * t / 6.0;
    dw[0] = -0.5 * u * u * inv_h;
    dw[1] = (-2.0 * t + 1.5 * t * t) * inv_h;
    dw[2] = (2.0 * u - 1.5 * u * u) * inv_h;
    dw[3] = 0.5 * t * t * inv_h;
  }
};

}  // namespace flowmpm
