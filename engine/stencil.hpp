// The nodes a particle touches, with N (and optionally dN) at the particle:
// the tensor product of the shape function's 1D stencils, evaluated once
// per particle and stage. Node a of the stencil is (k_x, k_y, k_z) with
// a = k_x + S (k_y + S k_z), S = Shape::support, so that the S nodes of a
// line along x (one k_y, k_z) are neighbours in the stencil's arrays as in
// the grid's; every loop has a compile-time trip count so that the compiler
// unrolls it completely.
// The per-particle functions of the hot loops (this constructor, the 1D
// shape stencils, Grid::cell_of and node_index, the stress update) are
// always inlined: GCC -O3 left them out of line in the large stage
// instantiations, which kept N and dN in memory (measured with perf).
#pragma once
#include <array>

#include "engine/grid.hpp"
#include "engine/node_pair.hpp"

namespace flowmpm {

template <int D, class Shape, bool WithGradient = true>
struct Stencil {
  static constexpr int S = Shape::support;
  static constexpr int size = D == 1 ? S : D == 2 ? S * S : S * S * S;
  static constexpr int lines = size / S;  // lines of S nodes along x

  std::size_t first;                   // node index of k = (0, 0, 0)
  std::array<std::size_t, size> node;  // node index of each stencil node
  std::array<double, size> N;
  // dN[j][a] = dN_a / dx_j: one array per component, like N.
  std::array<std::array<double, size>, WithGradient ? D : 0> dN;

  // Visits the nodes line by line along x, two at a time:
  // f.template operator()<2>(a, n) for stencil nodes a, a + 1 (grid nodes
  // n, n + 1), and f.template operator()<1>(a, n) for the last node of a
  // line of odd length.
  template <class F>
  [[gnu::always_inline]] void for_each_node_pair(F&& f) const {
    for (int line = 0; line < lines; ++line) {
      const int a = S * line;
      for (int k = 0; k + 1 < S; k += 2) f.template operator()<2>(a + k, node[a + k]);
      if constexpr (S % 2 == 1) f.template operator()<1>(a + S - 1, node[a + S - 1]);
    }
  }

  Vec<D> gradient(int a) const {
    Vec<D> g;
    for (int j = 0; j < D; ++j) g[j] = dN[j][a];
    return g;
  }

  // `half_width`: the particle's half-width per axis in cells (uGIMP).
  [[gnu::always_inline]] Stencil(const Grid<D>& grid, const Vec<D>& x, const Vec<D>& half_width) {
    double w[D][S], dw[D][S];
    Index<D> base;
    for (int d = 0; d < D; ++d) {
      const double g = (x[d] - grid.origin[d]) * grid.inv_h[d];
      Shape::stencil(g, grid.inv_h[d], half_width[d], base[d], w[d], dw[d]);
    }
    first = grid.node_index(base);
    const std::size_t sy = D > 1 ? static_cast<std::size_t>(grid.nodes[0]) : 0;
    const std::size_t sz = D > 2 ? sy * static_cast<std::size_t>(grid.nodes[1]) : 0;
    constexpr int Y = D > 1 ? S : 1, Z = D > 2 ? S : 1;
    // Products over the y and z axes, formed once per (k_y, k_z) pair.
    double w_yz[Z][Y], dy_yz[Z][Y], dz_yz[Z][Y];
    for (int kz = 0; kz < Z; ++kz) {
      for (int ky = 0; ky < Y; ++ky) {
        const double wy = D > 1 ? w[D > 1 ? 1 : 0][ky] : 1.0, wz = D > 2 ? w[D > 2 ? 2 : 0][kz] : 1.0;
        w_yz[kz][ky] = wy * wz;
        dy_yz[kz][ky] = D > 1 ? dw[D > 1 ? 1 : 0][ky] * wz : 0.0;
        dz_yz[kz][ky] = D > 2 ? wy * dw[D > 2 ? 2 : 0][kz] : 0.0;
      }
    }
    for (int kz = 0; kz < Z; ++kz) {
      for (int ky = 0; ky < Y; ++ky) {
        for (int kx = 0; kx < S; ++kx) {
          const int a = kx + S * (ky + S * kz);
          node[a] = first + kx + ky * sy + kz * sz;
          N[a] = w[0][kx] * w_yz[kz][ky];
          if constexpr (WithGradient) {
            dN[0][a] = dw[0][kx] * w_yz[kz][ky];
            if constexpr (D > 1) dN[1][a] = w[0][kx] * dy_yz[kz][ky];
            if constexpr (D > 2) dN[2][a] = w[0][kx] * dz_yz[kz][ky];
          }
        }
      }
    }
  }
};

}  // namespace flowmpm
