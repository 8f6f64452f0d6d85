// XPIC(m) [Hammerquist 2017] (docs/theory/transfers.md):
// the particles' new velocity is
//   v_p^(n+1) = sum_I N_Ip (v_I^L+ - w_I),  w = v^L - v*,
//   v* = sum_{k=1..m} (-1)^(k+1) C(m, k) Q^(k-1) v^L,
// v^L = M^-1 S V^n the lumped nodal velocity of the particles' velocities
// at the start of the step, v^L+ the grid's velocity after grid_integrate,
// and Q the grid-particle-grid projection
//   (Q u)_I = (1 / m_I) sum_p N_Ip m_p sum_J N_Jp u_J.
// Then S^T v* = (I - (I - P)^m) V^n, P = S^T M^-1 S the particle-grid-
// particle projection: XPIC(1) is PIC, and as m grows the update keeps all
// of V^n but its part in the null space of P (FLIP's noise). Every u_k
// takes the velocity constraints at t (a prescribed node keeps its value in
// every u_k, so v* = v^L there: the coefficients sum to 1). Summed here as
//   w = sum_k a_k u_k,  u_k = Q^(k-1) v^L,  a_1 = 1 - m,  a_k = (-1)^k C(m, k),
// so that w = 0 exactly for m = 1 and XPIC(1) is PIC bit for bit.
// Computed at the start of g2p_motion, while the particles are still at
// x^n: m passes over the particles (v^L mapped again, then a gather and a
// scatter per projection), in p2g's colour order (deterministic), each
// contact field on its own, every iterate taking the contact laws and the
// walls as the velocity constraints (tasks/contact.hpp, tasks/wall.hpp).
#pragma once
#include "tasks/contact.hpp"
#include "tasks/grid_update.hpp"
#include "tasks/parallel_blocks.hpp"
#include "tasks/wall.hpp"

namespace flowmpm {

// Whether g2p takes XPIC's filtered velocity u for the particles' velocity
// and strain: not with contact or walls, whose laws the iterates take but
// which correct v^L+ once more after the grid update. There v_p comes from
// v^L+ - w as two sums, and L_p from v^L+: measured better than L_p from u
// (the stuck block on the incline crept 0.26 % of a cell on the rigid
// plane and 1.2 % on a wall at 5 mm, against 0.07 % and 0.24 %; Sulsky's
// disks kept 0.633 of their kinetic energy against 0.673), though only u
// makes two fields in stick one field's XPIC under USL exactly (0.913
// against 0.897; docs/theory/transfers.md).
template <int D, class Shape>
bool xpic_filters_strain(const DiscreteSystem<D, Shape>& system) {
  return !system.contact && system.walls.empty();
}

namespace detail {

// The iterate's momentum sum_p N_Ip m_p v_p: with the particles' velocities
// (First) or with v_p = sum_J N_Jp u_J, u the last iterate.
template <int D, class Shape, bool First>
void xpic_map(DiscreteSystem<D, Shape>& system) {
  for (XpicNodes<D>& x : system.xpic) {
    for_each_active_node(system.grid, [&](std::size_t n, const Index<D>&) {
      for (int d = 0; d < D; ++d) x.iterate.momentum[d][n] = 0.0;
    });
  }
  const auto& grid = system.grid;
  scatter_by_colour(system, [&](ParticleBatch<D>& b, std::uint32_t first, std::uint32_t last, std::uint32_t) {
    if (system.is_rigid(b)) return;
    NodalField<D>& iterate = system.xpic[b.field].iterate;
    double* to_momentum[D];
    const double* u[D];
    for (int d = 0; d < D; ++d) {
      to_momentum[d] = iterate.momentum[d].data();
      u[d] = iterate.velocity[d].data();
    }
    for (std::uint32_t p = first; p < last; ++p) {
      const Stencil<D, Shape, false> s(grid, b.x[p], b.half_width);
      Vec<D> v;
      if constexpr (First) {
        v = b.v[p];
      } else {
        NodePair v_sum[D] = {};
        s.for_each_node_pair([&]<int Count>(int line, int k, std::size_t n) {
          const NodePair N = s.template pair_weights<Count>(line, k).N;
          for (int i = 0; i < D; ++i) v_sum[i] += N * load_nodes<Count>(u[i] + n);
        });
        for (int i = 0; i < D; ++i) v[i] = sum(v_sum[i]);
      }
      const Vec<D> mv = b.mass[p] * v;
      s.for_each_node_pair([&]<int Count>(int line, int k, std::size_t n) {
        const NodePair N = s.template pair_weights<Count>(line, k).N;
        for (int i = 0; i < D; ++i)
          store_nodes<Count>(to_momentum[i] + n, load_nodes<Count>(to_momentum[i] + n) + N * mv[i]);
      });
    }
  });
}

// u_k = momentum / m_I (0 on an empty node) with the constraints at t, as
// grid_velocity, and the contact laws, as contact_projected; then
// w = a u_k (First) or w += a u_k.
template <int D, class Shape, bool First>
void xpic_iterate(DiscreteSystem<D, Shape>& system, double a, const std::vector<std::size_t>& contact_nodes) {
  for (int k = 0; k < system.field_count(); ++k) {
    const NodalField<D>& field = system.field(k);
    NodalField<D>& iterate = system.xpic[k].iterate;
    fold_mirror_planes(system, iterate, iterate.momentum, false);  // the mass is folded already
    for_each_active_node(system.grid, [&](std::size_t n, const Index<D>&) {
      if constexpr (First) iterate.mass[n] = field.mass[n];
      const double m = iterate.mass[n];
      for (int d = 0; d < D; ++d) iterate.velocity[d][n] = m > 0.0 ? iterate.momentum[d][n] / m : 0.0;
    });
    apply_velocity_constraints(system, iterate, system.t);
    walls_on_xpic_iterate(system, iterate);
  }
  if (system.contact) contact_on_xpic_iterates(system, contact_nodes);
  for (int k = 0; k < system.field_count(); ++k) {
    XpicNodes<D>& x = system.xpic[k];
    const NodalField<D>& iterate = x.iterate;
    for_each_active_node(system.grid, [&](std::size_t n, const Index<D>&) {
      for (int d = 0; d < D; ++d) {
        const double u = iterate.velocity[d][n];
        x.correction[d][n] = First ? a * u : x.correction[d][n] + a * u;
      }
    });
  }
}

}  // namespace detail

// w on every velocity field's XpicNodes, and (xpic_filters_strain) in its
// iterate's velocity the filtered grid velocity u_I = v_I^L+ - w_I, from
// which g2p takes the particles' new velocity and, under USL, their
// velocity gradient.
template <int D, class Shape>
void xpic_correction(DiscreteSystem<D, Shape>& system) {
  const int m = system.xpic_order;
  const std::vector<std::size_t> nodes = system.contact ? contact_nodes(system) : std::vector<std::size_t>{};
  detail::xpic_map<D, Shape, true>(system);
  detail::xpic_iterate<D, Shape, true>(system, 1.0 - m, nodes);
  double binomial = m;  // C(m, k - 1)
  for (int k = 2; k <= m; ++k) {
    binomial = binomial * (m - k + 1) / k;
    detail::xpic_map<D, Shape, false>(system);
    detail::xpic_iterate<D, Shape, false>(system, k % 2 == 0 ? binomial : -binomial, nodes);
  }
  if (!xpic_filters_strain(system)) return;
  for (int k = 0; k < system.field_count(); ++k) {
    const NodalField<D>& field = system.field(k);
    XpicNodes<D>& x = system.xpic[k];
    for_each_active_node(system.grid, [&](std::size_t n, const Index<D>&) {
      for (int d = 0; d < D; ++d) x.iterate.velocity[d][n] = field.velocity[d][n] - x.correction[d][n];
    });
  }
}

}  // namespace flowmpm
