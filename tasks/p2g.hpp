// Particle-to-grid stages (DESIGN.md): p2g_momentum maps mass and momentum,
// p2g_force the internal and body forces, to the nodes:
//   m_I = sum_p N_Ip m_p,  p_I = sum_p N_Ip m_p v_p,
//   f_I = sum_p ( -V_p sigma_p . dN_Ip + N_Ip m_p g ).
// In 1D and 2D only the in-plane block of sigma enters the force.
#pragma once
#include "engine/stencil.hpp"
#include "tasks/parallel_blocks.hpp"

namespace flowmpm {

template <int D, class Shape>
void p2g_momentum(Model<D, Shape>& model) {
  auto& grid = model.grid;
  for_each_active_node(grid, [&](std::size_t n, const Index<D>&) {
    grid.mass[n] = 0.0;
    grid.momentum[n].setZero();
  });
  scatter_by_colour(model, [&](ParticleBatch<D>& b, std::uint32_t first, std::uint32_t last, std::uint32_t) {
    double* mass = grid.mass.data();
    Vec<D>* momentum = grid.momentum.data();
    for (std::uint32_t p = first; p < last; ++p) {
      const Stencil<D, Shape, false> s(grid, b.x[p], b.half_width);
      const double m = b.mass[p];
      const Vec<D> mv = m * b.v[p];
      for (int a = 0; a < s.size; ++a) {
        mass[s.node[a]] += s.N[a] * m;
        momentum[s.node[a]] += s.N[a] * mv;
      }
    }
  });
}

template <int D, class Shape>
void p2g_force(Model<D, Shape>& model) {
  auto& grid = model.grid;
  for_each_active_node(grid, [&](std::size_t n, const Index<D>&) { grid.force[n].setZero(); });
  const Vec<D> g = model.gravity;
  scatter_by_colour(model, [&](ParticleBatch<D>& b, std::uint32_t first, std::uint32_t last, std::uint32_t) {
    Vec<D>* force = grid.force.data();
    for (std::uint32_t p = first; p < last; ++p) {
      const Stencil<D, Shape> s(grid, b.x[p], b.half_width);
      const Voigt& sigma = b.stress[p];
      const double V = b.volume[p];
      double Vsigma[D][D];
      for (int i = 0; i < D; ++i)
        for (int j = 0; j < D; ++j) Vsigma[i][j] = V * sigma[voigt_slot(i, j)];
      const Vec<D> mg = b.mass[p] * g;
      for (int a = 0; a < s.size; ++a) {
        Vec<D> f = s.N[a] * mg;
        for (int i = 0; i < D; ++i)
          for (int j = 0; j < D; ++j) f[i] -= Vsigma[i][j] * s.dN[a][j];
        force[s.node[a]] += f;
      }
    }
  });
}

}  // namespace flowmpm
