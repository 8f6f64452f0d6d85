// Structured Cartesian background grid: nodes at origin + i * h along each
// axis, nodal fields as flat arrays indexed i + n_x (j + n_y k). Cells are
// grouped into cubic blocks of `block_cells` cells per axis; the blocks
// are coloured by the parity of their block index (2^D colours) so that
// blocks of one colour share no node (see discretisation/grid/blocks.hpp).
#pragma once
#include <array>
#include <cstddef>
#include <vector>

#include "core/vec.hpp"

namespace flowmpm {

// Heat or solvent on the nodes (tasks/transport.hpp), allocated only when
// the scene carries it.
struct TransportNodes {
  std::vector<double> capacity;  // heat: sum N m C (J/K); solvent: sum N m (kg)
  std::vector<double> value;     // T (K) or c (weight fraction)
  std::vector<double> flow;      // heat flow (W) or solvent flow (kg/s) into the node
  std::vector<double> change;    // the mapped value, then its change over the step
  std::vector<double> reprojected;  // sum N m C (sum N T), sum N m (sum N c): the values mapped back

  void allocate(std::size_t nodes) {
    for (auto* field : {&capacity, &value, &flow, &change, &reprojected}) field->assign(nodes, 0.0);
  }
};

// The nodal fields of one velocity field: all the bodies of a scene
// without contact, or one contact field (discretisation/contact/).
template <int D>
struct NodalField {
  // A nodal vector field, one array per component (component d of node n
  // is field[d][n]): the nodes of a stencil line along x are neighbours in
  // memory, so the compiler can load and add two of them at once.
  using VectorField = std::array<std::vector<double>, D>;

  // Nodal fields: mass m, momentum p, force f, velocity v (after the last
  // grid stage that set it) and dv, the velocity change of grid_integrate.
  std::vector<double> mass;
  VectorField momentum, force, velocity, velocity_change;
  // sum_p V_p M_p |grad N_Ip|^2 (N/m), M the P-wave modulus: the node's
  // stiffness, for shape functions whose gradient jumps (held_node in
  // tasks/grid_update.hpp); empty for the others.
  std::vector<double> stiffness;

  void allocate(std::size_t nodes) {
    mass.assign(nodes, 0.0);
    for (VectorField* field : {&momentum, &force, &velocity, &velocity_change})
      for (auto& component : *field) component.assign(nodes, 0.0);
  }
};

template <int D>
struct Grid : NodalField<D> {  // the scene's first (often only) velocity field
  Vec<D> origin = Vec<D>::Zero();
  Vec<D> h = Vec<D>::Ones();      // cell size per axis (m)
  Vec<D> inv_h = Vec<D>::Ones();
  Index<D> cells{};               // cell count per axis
  Index<D> nodes{};               // cells + 1

  using typename NodalField<D>::VectorField;
  // Transport fields, empty unless the scene conducts heat / diffuses solvent.
  TransportNodes heat, solvent;

  // Only nodes inside [active_lo, active_hi] (inclusive) can carry mass;
  // grid stages clear and visit that box alone.
  Index<D> active_lo{}, active_hi{};

  Grid() = default;
  Grid(const Vec<D>& origin_, const Vec<D>& h_, const Index<D>& cells_)
      : origin(origin_), h(h_), inv_h(h_.cwiseInverse()), cells(cells_) {
    std::size_t n = 1;
    for (int d = 0; d < D; ++d) {
      nodes[d] = cells[d] + 1;
      n *= static_cast<std::size_t>(nodes[d]);
      active_lo[d] = 0;
      active_hi[d] = cells[d];
    }
    this->allocate(n);
  }

  std::size_t node_count() const { return this->mass.size(); }

  [[gnu::always_inline]] std::size_t node_index(const Index<D>& i) const {
    std::size_t index = static_cast<std::size_t>(i[D - 1]);
    for (int d = D - 2; d >= 0; --d) index = index * nodes[d] + i[d];
    return index;
  }

  // Grid coordinate of x along axis d, in cells from the origin.
  [[gnu::always_inline]] double coordinate(const Vec<D>& x, int d) const { return (x[d] - origin[d]) * inv_h[d]; }

  // The cell that holds x (indices may lie outside the grid).
  [[gnu::always_inline]] Index<D> cell_of(const Vec<D>& x) const {
    Index<D> c;
    for (int d = 0; d < D; ++d) c[d] = floor_to_int(coordinate(x, d));
    return c;
  }

  // Inverse of node_index.
  Index<D> node_ijk(std::size_t n) const {
    Index<D> i;
    for (int d = 0; d < D; ++d) {
      i[d] = static_cast<int>(n % static_cast<std::size_t>(nodes[d]));
      n /= static_cast<std::size_t>(nodes[d]);
    }
    return i;
  }

  Vec<D> node_position(const Index<D>& i) const {
    Vec<D> x;
    for (int d = 0; d < D; ++d) x[d] = origin[d] + i[d] * h[d];
    return x;
  }

  // Visits every node of the active box in parallel-friendly slabs: calls
  // f(node_index, node_ijk). Serial; callers parallelise over the last axis.
  template <class F>
  void for_each_active_node_in_slab(int slab, F&& f) const {
    Index<D> i{};
    i[D - 1] = slab;
    visit_axis<D - 2>(i, f);
  }

 private:
  template <int A, class F>
  void visit_axis(Index<D>& i, F& f) const {
    if constexpr (A < 0) {
      f(node_index(i), i);
    } else {
      for (i[A] = active_lo[A]; i[A] <= active_hi[A]; ++i[A]) visit_axis<A - 1>(i, f);
    }
  }
};

}  // namespace flowmpm
