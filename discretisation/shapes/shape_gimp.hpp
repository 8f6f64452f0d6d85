// Uniform GIMP (uGIMP; [Bardenhagen 2004], as used by [Le 2010]): the linear
// hat function averaged over the particle's domain, a box of the particle's
// initial half-width l_p that translates with it (never deformed). In 1D,
// with d = x_p - x_I:
//   |d| < l_p:              S = 1 - (d^2 + l_p^2) / (2 h l_p)
//   l_p <= |d| < h - l_p:   S = 1 - |d| / h
//   h - l_p <= |d| < h + l_p: S = (h + l_p - |d|)^2 / (4 h l_p)
//   otherwise 0,
// products of the 1D weights in 2D and 3D. S and its gradient are
// continuous, so a particle crossing a cell face makes no jump in force.
// Requires l_p <= h / 2 (one particle or more per cell and axis).
#pragma once
#include <array>
#include <cmath>

#include "core/vec.hpp"

namespace flowmpm {

struct GimpShape {
  static constexpr const char* name = "gimp";
  static constexpr int support = 4;  // nodes c - 1 ... c + 2 (at most 3 nonzero)
  static constexpr int reach_below = 1;
  static constexpr int reach_above = 2;
  static constexpr bool gradient_jumps = false;  // |dN|^2 / N bounded
  // APIC: D_p depends on where the particle is; C_p = sum v_I (x) grad N_Ip
  // instead (docs/theory/transfers.md).
  static constexpr double apic_inertia = 0.0;
  // Stable time step in h / c, 1 to 4 particles per cell (docs/STABILITY.md):
  // USL at a free surface, where |dN|^2 / N = 2 ppc / h^2; USF and MUSL.
  static constexpr std::array<double, 4> stable_factor_usl{0.67, 0.63, 0.55, 0.49};
  static constexpr std::array<double, 4> stable_factor_remapped{1.16, 1.16, 1.16, 1.16};

  [[gnu::always_inline]] static void stencil(double g, double inv_h, double lp, int& base, double (&w)[support],
                                             double (&dw)[support]) {
    base = floor_nonnegative(g) - 1;  // g >= reach_below = 1
    for (int k = 0; k < support; ++k) {
      const double d = g - (base + k);  // in cells
      const double r = std::abs(d), sign = d < 0.0 ? -1.0 : 1.0;
      if (r < lp) {
        w[k] = 1.0 - (d * d + lp * lp) / (2.0 * lp);
        dw[k] = -d / lp * inv_h;
      } else if (r < 1.0 - lp) {
        w[k] = 1.0 - r;
        dw[k] = -sign * inv_h;
      } else if (r < 1.0 + lp) {
        const double a = 1.0 + lp - r;
        w[k] = a * a / (4.0 * lp);
        dw[k] = -sign * a / (2.0 * lp) * inv_h;
      } else {
        w[k] = 0.0;
        dw[k] = 0.0;
      }
    }
  }
};

}  // namespace flowmpm
