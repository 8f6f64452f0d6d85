// The nodes a particle touches, with N (and optionally dN) at the particle:
// the tensor product of the shape function's 1D stencils, evaluated once
// per particle and stage. Node a of the stencil is (k_x, k_y, k_z) with
// a = k_x + n (k_y + n k_z), n = Shape::support: the n nodes of a line
// along x (one k_y, k_z) are neighbours in the grid. The stencil keeps the
// factors, not the n^D products: along x, the 1D weights w_x and
// derivatives dw_x; per line, w_yz = w_y w_z, dy_yz = dw_y w_z and
// dz_yz = w_y dw_z. Then N = w_x w_yz, dN/dx = dw_x w_yz, dN/dy = w_x dy_yz
// and dN/dz = w_x dz_yz, formed two nodes at a time where they are used.
// Every loop has a compile-time trip count, so the compiler unrolls it.
// The per-particle functions of the hot loops (this constructor, the 1D
// shape stencils, Grid::cell_of and node_index, the stress update) are
// always inlined: GCC -O3 left them out of line in the large stage
// instantiations (measured with perf).
#pragma once
#include <array>
#include <utility>

#include "discretisation/grid/grid.hpp"
#include "discretisation/grid/node_pair.hpp"

namespace flowmpm {

// What a stencil's second factor (PairWeights::dN, gradient()) holds:
//   gradient: dN_Ip (1/m);
//   offset:   N_Ip (x_I - x_p) (m), for APIC's p2g;
//   affine:   APIC's G_Ip, C_p = sum_I v_I (x) G_Ip (1/m): D_p^-1 (x_I - x_p) N_Ip
//             with D_p = apic_inertia h^2 where the shape function has one
//             (B-splines), dN_Ip where it has none (linear, GIMP)
//             (docs/theory/transfers.md).
// Each is the tensor product of 1D factors, as the gradient is.
enum class StencilFactor { gradient, offset, affine };

template <int D, class Shape, bool WithGradient = true, StencilFactor Factor = StencilFactor::gradient>
struct Stencil {
  static constexpr int support = Shape::support;
  static constexpr int size = D == 1 ? support : D == 2 ? support * support : support * support * support;
  static constexpr int lines = size / support;  // lines of support nodes along x

  std::array<double, support> w_x, dw_x;
  std::array<std::size_t, lines> line_node;  // node index of k_x = 0
  std::array<double, lines> w_yz, dy_yz, dz_yz;

  Stencil() = default;
  // `half_width`: the particle's half-width per axis in cells (uGIMP).
  [[gnu::always_inline]] Stencil(const Grid<D>& grid, const Vec<D>& x, const Vec<D>& half_width) {
    double w[D][support], dw[D][support];
    Index<D> base;
    for (int d = 0; d < D; ++d) {
      const double g = grid.coordinate(x, d);
      Shape::stencil(g, grid.inv_h[d], half_width[d], base[d], w[d], dw[d]);
      if constexpr (Factor == StencilFactor::offset ||
                    (Factor == StencilFactor::affine && Shape::apic_inertia > 0.0)) {
        // (x_I - x_p)_d = (base + k - g) h_d; over D_p = apic_inertia h_d^2.
        const double scale = Factor == StencilFactor::offset ? grid.h[d] : grid.inv_h[d] / Shape::apic_inertia;
        for (int k = 0; k < support; ++k) dw[d][k] = w[d][k] * ((base[d] + k - g) * scale);
      }
    }
    for (int k = 0; k < support; ++k) {
      w_x[k] = w[0][k];
      dw_x[k] = dw[0][k];
    }
    const std::size_t first = grid.node_index(base);
    const std::size_t sy = D > 1 ? static_cast<std::size_t>(grid.nodes[0]) : 0;
    const std::size_t sz = D > 2 ? sy * static_cast<std::size_t>(grid.nodes[1]) : 0;
    constexpr int Y = D > 1 ? support : 1, Z = D > 2 ? support : 1;
    for (int kz = 0; kz < Z; ++kz) {
      for (int ky = 0; ky < Y; ++ky) {
        const int line = ky + Y * kz;
        const double wy = D > 1 ? w[D > 1 ? 1 : 0][ky] : 1.0, wz = D > 2 ? w[D > 2 ? 2 : 0][kz] : 1.0;
        line_node[line] = first + ky * sy + kz * sz;
        w_yz[line] = wy * wz;
        dy_yz[line] = D > 1 ? dw[D > 1 ? 1 : 0][ky] * wz : 0.0;
        dz_yz[line] = D > 2 ? wy * dw[D > 2 ? 2 : 0][kz] : 0.0;
      }
    }
  }

  // N and dN of nodes k, k + 1 of `line` (Count = 2), or of node k and 0
  // (Count = 1).
  struct PairWeights {
    NodePair N;
    NodePair dN[D];
  };
  template <int Count>
  [[gnu::always_inline]] PairWeights pair_weights(int line, int k) const {
    PairWeights p;
    const NodePair wx = load_nodes<Count>(&w_x[k]);
    p.N = wx * w_yz[line];
    if constexpr (WithGradient) {
      p.dN[0] = load_nodes<Count>(&dw_x[k]) * w_yz[line];
      if constexpr (D > 1) p.dN[1] = wx * dy_yz[line];
      if constexpr (D > 2) p.dN[2] = wx * dz_yz[line];
    }
    return p;
  }

  // Visits the nodes line by line along x, two at a time:
  // f.template operator()<2>(line, k, n) for nodes k, k + 1 of the line
  // (grid nodes n, n + 1), and f.template operator()<1>(line, k, n) for the
  // last node of a line of odd length.
  // The lines are unrolled where they are few (four for linear shape
  // functions in 3D): GCC stopped unrolling p2g's loop over them once the
  // nodal stiffness (held_node) joined the pass, which cost about 20
  // instructions per particle-step (callgrind); the arithmetic is the same.
  template <class F>
  [[gnu::always_inline]] void for_each_node_pair(F&& f) const {
    if constexpr (lines <= 4) {
      [&]<int... Line>(std::integer_sequence<int, Line...>) {
        (visit_line(f, Line), ...);
      }(std::make_integer_sequence<int, lines>{});
    } else {
      for (int line = 0; line < lines; ++line) visit_line(f, line);
    }
  }

  template <class F>
  [[gnu::always_inline]] void visit_line(F& f, int line) const {
    for (int k = 0; k + 1 < support; k += 2) f.template operator()<2>(line, k, line_node[line] + k);
    if constexpr (support % 2 == 1) f.template operator()<1>(line, support - 1, line_node[line] + support - 1);
  }

  // One node at a time, for checks and set-up: node a's index, N and dN.
  std::size_t node(int a) const { return line_node[a / support] + a % support; }
  double N(int a) const { return w_x[a % support] * w_yz[a / support]; }
  Vec<D> gradient(int a) const {
    Vec<D> g;
    g[0] = dw_x[a % support] * w_yz[a / support];
    if constexpr (D > 1) g[1] = w_x[a % support] * dy_yz[a / support];
    if constexpr (D > 2) g[2] = w_x[a % support] * dz_yz[a / support];
    return g;
  }
};

}  // namespace flowmpm
