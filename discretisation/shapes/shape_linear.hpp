// Linear (classic MPM) shape functions: the tensor product of 1D hat
// functions N(xi) = 1 - |xi|, xi = (x - x_I) / h. A particle in cell c
// touches the two nodes c and c + 1 along each axis. The particle domain is
// a Dirac point, so the gradient jumps when a particle crosses a cell face
// (the cell-crossing error of classic MPM).
#pragma once
#include <array>

#include "core/vec.hpp"

namespace flowmpm {

struct LinearShape {
  static constexpr const char* name = "linear";
  // Nodes of support per axis.
  static constexpr int support = 2;
  // Nodes touched, relative to the cell c that holds the particle:
  // c - reach_below ... c + reach_above.
  static constexpr int reach_below = 0;
  static constexpr int reach_above = 1;
  // The gradient keeps its full size where the weight vanishes (at a cell
  // face): the grid update watches the nodes this makes too light for their
  // stiffness (tasks/grid_update.hpp held_node).
  static constexpr bool gradient_jumps = true;
  // APIC: grad N_Ip = D_p^-1 (x_I - x_p) N_Ip exactly, D_p singular on a node:
  // C_p = sum v_I (x) grad N_Ip [Jiang 2015] (docs/theory/transfers.md).
  static constexpr double apic_inertia = 0.0;
  // The largest stable time step, in h / c, for 1 to 4 particles per cell
  // and axis (docs/STABILITY.md): with the stress from the updated grid
  // velocity (USL; the lattice allows 0.71-0.77, but at a moving free
  // surface held_node leaves a weak growth, at most 1.016 per step at 0.55)
  // and from velocities mapped from the particles (USF, MUSL).
  static constexpr std::array<double, 4> stable_factor_usl{0.55, 0.55, 0.55, 0.55};
  static constexpr std::array<double, 4> stable_factor_remapped{1.0, 1.0, 1.0, 1.0};
  // USL in an axisymmetric analysis: lower from 2 particles per cell on, the
  // growth starting next to the axis, whose nodes weigh little (masses go
  // as r); measured on a solid section on the axis (docs/STABILITY.md).
  // The other shape functions, and USF and MUSL, keep their limits there.
  static constexpr std::array<double, 4> stable_factor_usl_axisymmetric{0.55, 0.39, 0.335, 0.31};

  // 1D stencil for a particle at grid coordinate g = (x - origin) / h with
  // half-width l_p / h (unused here): first node `base`, weights w and
  // derivatives dw = dN/dx.
  [[gnu::always_inline]] static void stencil(double g, double inv_h, double, int& base, double (&w)[support],
                                             double (&dw)[support]) {
    base = floor_nonnegative(g);  // g >= 0 inside the grid
    const double s = g - base;
    w[0] = 1.0 - s;
    w[1] = s;
    dw[0] = -inv_h;
    dw[1] = inv_h;
  }
};

}  // namespace flowmpm
