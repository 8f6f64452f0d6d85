// contact_bonds: the forces of imperfect interfaces
// (discretisation/contact/contact_law_interface.hpp, docs/theory/contact.md),
// only in a scene with one, after p2g_force and contact_volumes and before
// grid_integrate. At a node where both fields a and b of an interface carry
// mass:
//   [u] = u_b - u_a,  F_a = t([u], n) A_I = -F_b,
// u_kI each field's displacement at the node (a linear fit to its
// particles', interface_displacement.hpp), n the unit normal out of a (the
// contact laws' choice: that of the body with more volume at the node),
// t the law's traction, and
//   A_I = min(|G_a . n|, |G_b . n|),
// the area of the face both bodies present at the node: G_k . n integrates
// N_I over body k's surface near I (h^(D-1) N_I there on a face along the
// grid, whatever the shape function), and the smaller of the two is the
// part they share (half of h at the node where one body ends on the
// other's face). F is added to each field's nodal force, as the stress's
// is: grid_integrate then updates the momenta, applies the constraints
// (whose reactions take the interface's share) and the velocity changes
// FLIP reads. Per pair it measures the normal force on a (-sum F_a . n,
// negative where the interface pulls), the tangential force's magnitude and
// the energy stored, sum_I A_I (D_n [u]_n^2 + D_t |[u]_t|^2) / 2, which the
// energy balance counts with the stored energy (engine/diagnostics.hpp).
// Parallel over slabs of nodes, the per-slab sums added in slab order:
// thread-count independent.
#pragma once
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "tasks/parallel_blocks.hpp"

namespace flowmpm {

namespace detail {

// What contact_bonds sums per pair over a slab of nodes.
template <int D>
struct BondSums {
  std::vector<double> normal;      // sum of -F_a . n (N)
  std::vector<Vec<D>> tangential;  // sum of the tangential forces on a (N)
  std::vector<double> energy;      // sum of A_I w([u], n) (J)

  explicit BondSums(std::size_t pairs) : normal(pairs, 0.0), tangential(pairs, Vec<D>::Zero()), energy(pairs, 0.0) {}
};

}  // namespace detail

template <int D, class Shape>
void contact_bonds(DiscreteSystem<D, Shape>& system) {
  const auto& grid = system.grid;
  ContactFields<D>& contact = *system.contact;
  const std::size_t pairs = contact.pairs.size();
  const int first = grid.active_lo[D - 1], last = grid.active_hi[D - 1];
  std::vector<detail::BondSums<D>> slab_sums(static_cast<std::size_t>(last - first + 1), detail::BondSums<D>(pairs));
  tbb::parallel_for(tbb::blocked_range<int>(first, last + 1), [&](const tbb::blocked_range<int>& slabs) {
    for (int slab = slabs.begin(); slab != slabs.end(); ++slab) {
      detail::BondSums<D>& sums = slab_sums[static_cast<std::size_t>(slab - first)];
      grid.for_each_active_node_in_slab(slab, [&](std::size_t n, const Index<D>& ijk) {
        for (std::size_t i = 0; i < pairs; ++i) {
          const ContactPair& pair = contact.pairs[i];
          const auto* law = std::get_if<InterfaceLaw>(&pair.law);
          if (!law) continue;
          const int a = pair.first, b = pair.second;
          NodalField<D>& fa = system.field(a);
          NodalField<D>& fb = system.field(b);
          Vec<D> normal;
          if (!(fa.mass[n] > 0.0) || !(fb.mass[n] > 0.0) || !contact.outward_normal(a, b, n, normal)) continue;
          // The interface's area at the node; axisymmetric, per radian: its
          // length in the section (contact_volumes maps areas there) times r.
          double area = std::min(std::abs(contact.gradient(a, n).dot(normal)),
                                 std::abs(contact.gradient(b, n).dot(normal)));
          if (system.stress_state == StressState::axisymmetric) area *= grid.node_position(ijk)[0];
          Vec<D> node;
          for (int d = 0; d < D; ++d) node[d] = ijk[d] * grid.h[d];
          const auto at_node = [&](int k) {
            // The fit extrapolates only along directions its particles
            // spread over by a tenth of a cell (ContactFields::spread_floor).
            return contact.displacement[k - 1].at_node(n, contact.volume[k - 1][n], contact.spread[k - 1], node,
                                                       contact.spread_floor);
          };
          const Vec<D> jump = at_node(b) - at_node(a);
          const Vec<D> force = area * law->traction(jump, normal);
          for (int d = 0; d < D; ++d) {
            fa.force[d][n] += force[d];
            fb.force[d][n] -= force[d];
          }
          const double along = force.dot(normal);
          sums.normal[i] -= along;
          sums.tangential[i] += force - along * normal;
          sums.energy[i] += area * law->energy(jump, normal);
        }
      });
    }
  });
  detail::BondSums<D> total(pairs);
  for (const auto& s : slab_sums) {
    for (std::size_t i = 0; i < pairs; ++i) {
      total.normal[i] += s.normal[i];
      total.tangential[i] += s.tangential[i];
      total.energy[i] += s.energy[i];
    }
  }
  for (std::size_t i = 0; i < pairs; ++i) {
    if (!is_interface(contact.pairs[i].law)) continue;
    contact.pairs[i].normal_force = total.normal[i];
    contact.pairs[i].tangential_force = total.tangential[i].norm();
    contact.pairs[i].interface_energy = total.energy[i];
  }
}

}  // namespace flowmpm
