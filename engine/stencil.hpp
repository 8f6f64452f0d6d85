// The nodes a particle touches, with N and dN at the particle: the tensor
// product of the shape function's 1D stencils, evaluated once per particle
// and stage.
#pragma once
#include <array>

#include "engine/grid.hpp"

namespace flowmpm {

template <int D, class Shape>
struct Stencil {
  static constexpr int size = [] {
    int n = 1;
    for (int d = 0; d < D; ++d) n *= Shape::support;
    return n;
  }();

  std::array<std::size_t, size> node;
  std::array<double, size> N;
  std::array<Vec<D>, size> dN;

  Stencil(const Grid<D>& grid, const Vec<D>& x) {
    double w[D][Shape::support], dw[D][Shape::support];
    Index<D> base;
    for (int d = 0; d < D; ++d) {
      const double g = (x[d] - grid.origin[d]) * grid.inv_h[d];
      Shape::stencil(g, grid.inv_h[d], base[d], w[d], dw[d]);
    }
    const std::size_t first = grid.node_index(base);
    for (int a = 0; a < size; ++a) {
      int k[D];
      int rest = a;
      for (int d = 0; d < D; ++d) {
        k[d] = rest % Shape::support;
        rest /= Shape::support;
      }
      std::size_t offset = 0, stride = 1;
      double n = 1.0;
      for (int d = 0; d < D; ++d) {
        offset += static_cast<std::size_t>(k[d]) * stride;
        stride *= static_cast<std::size_t>(grid.nodes[d]);
        n *= w[d][k[d]];
      }
      node[a] = first + offset;
      N[a] = n;
      for (int d = 0; d < D; ++d) {
        double g = dw[d][k[d]];
        for (int e = 0; e < D; ++e)
          if (e != d) g *= w[e][k[e]];
        dN[a][d] = g;
      }
    }
  }
};

}  // namespace flowmpm
