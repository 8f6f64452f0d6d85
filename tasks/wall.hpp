// Walls (NodeSetSpec::wall, docs/guide/contact.md): a held plane that holds
// only in compression. In grid_integrate, after the update and the
// velocity constraints, each velocity field's nodes on the plane and
// beyond it are treated as in contact with a rigid body moving with the
// wall's velocity V at t + dt: r = v - V, n the unit normal out of the
// material into the wall, and the wall's contact law gives dv(r, n) where
// r . n > 0 (approach; `stick` everywhere, as a held node set). The
// impulse m dv is added to the node's momentum, velocity and velocity
// change; the wall's force (the material's on it) is -sum m dv / dt, and
// its work on the material is sum m dv . (v_start + v_end) / 2, in the
// energy balance with the constraints' (tasks/contact.hpp does the same
// between bodies). Serial over the nodes, in order: deterministic.
#pragma once
#include "tasks/grid_update.hpp"

namespace flowmpm {

// The walls on velocity field k (before its dv is formed: velocity_change
// holds the velocity at the start of the step).
template <int D, class Shape>
void apply_walls(DiscreteSystem<D, Shape>& system, int k) {
  NodalField<D>& grid = system.field(k);
  const double t = system.t + system.dt, dt = system.dt;
  for (Wall<D>& wall : system.walls) {
    const Vec<D> V = wall.velocity_at(t), n = wall.normal();
    for (const std::size_t node : wall.nodes) {
      const double m = grid.mass[node];
      if (!(m > 0.0)) continue;
      Vec<D> v, v_start;
      for (int d = 0; d < D; ++d) {
        v[d] = grid.momentum[d][node] / m;
        v_start[d] = grid.velocity_change[d][node];
      }
      const Vec<D> dv = contact_velocity_change(wall.law, Vec<D>(v - V), n);
      if (dv.isZero(0.0)) continue;
      const bool held = held_node<D, Shape>(grid, node, dt);
      for (int d = 0; d < D; ++d) {
        grid.momentum[d][node] += m * dv[d];
        if (!held) grid.velocity[d][node] += dv[d];
      }
      wall.force -= m * dv / dt;
      wall.work += m * dv.dot(0.5 * (v_start + v + dv));
    }
  }
}

// XPIC's iterates u_k (tasks/xpic.hpp) take the walls too, at t as they
// take the velocity constraints, so that its filter w knows of the walls
// that correct v^L+ (as contact_on_xpic_iterates for contact). Nothing is
// measured: the iterates are no momentum of the step.
template <int D, class Shape>
void walls_on_xpic_iterate(const DiscreteSystem<D, Shape>& system, NodalField<D>& iterate) {
  for (const Wall<D>& wall : system.walls) {
    const Vec<D> V = wall.velocity_at(system.t), n = wall.normal();
    for (const std::size_t node : wall.nodes) {
      if (!(iterate.mass[node] > 0.0)) continue;
      Vec<D> v;
      for (int d = 0; d < D; ++d) v[d] = iterate.velocity[d][node];
      const Vec<D> dv = contact_velocity_change(wall.law, Vec<D>(v - V), n);
      for (int d = 0; d < D; ++d) iterate.velocity[d][node] += dv[d];
    }
  }
}

}  // namespace flowmpm
