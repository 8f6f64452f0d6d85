// Grid stages (README "How a step runs"). grid_velocity: v_I = p_I / m_I where m_I is above
// the mass threshold, then the prescribed velocities (p_I follows).
// grid_integrate: p_I += f_I dt, v_I^new = p_I / m_I, prescribed velocities
// at t + dt, and dv_I = v_I^new - v_I for the FLIP update; v_I becomes
// v_I^new so that the stages after it read the updated velocity.
#pragma once
#include "tasks/parallel_blocks.hpp"

namespace flowmpm {

template <int D, class Shape>
void apply_velocity_constraints(DiscreteSystem<D, Shape>& system, double time) {
  auto& grid = system.grid;
  for (const NodeConstraint& c : system.constraints) {
    const double value = c.velocity(time);
    for (std::size_t n : c.nodes) {
      grid.velocity[c.axis][n] = value;
      grid.momentum[c.axis][n] = grid.mass[n] * value;
    }
  }
  // Ghost nodes take their mirror's velocity, reflected about the plane's.
  for (const MirrorPlane& plane : system.mirror_planes) {
    for (int d = 0; d < D; ++d) {
      const bool constrained = plane.velocity[d].has_value();
      const double V = constrained ? (*plane.velocity[d])(time) : 0.0;
      auto& v = grid.velocity[d];
      for (auto [ghost, mirror] : plane.pairs) {
        v[ghost] = constrained ? 2.0 * V - v[mirror] : v[mirror];
        grid.momentum[d][ghost] = grid.mass[ghost] * v[ghost];
      }
    }
  }
}

// Hands what the ghost nodes received to their mirror nodes (MirrorPlane):
// `field` is momentum or force, `mass` too for the former.
template <int D, class Shape>
void fold_mirror_planes(DiscreteSystem<D, Shape>& system, typename Grid<D>::VectorField& field, bool with_mass) {
  auto& grid = system.grid;
  for (const MirrorPlane& plane : system.mirror_planes) {
    for (auto [ghost, mirror] : plane.pairs) {
      if (with_mass) grid.mass[mirror] += grid.mass[ghost];
      for (int d = 0; d < D; ++d) field[d][mirror] += (plane.velocity[d] ? -1.0 : 1.0) * field[d][ghost];
    }
  }
}

template <int D, class Shape>
void grid_velocity(DiscreteSystem<D, Shape>& system) {
  auto& grid = system.grid;
  const double threshold = system.mass_threshold;
  fold_mirror_planes(system, grid.momentum, true);
  for_each_active_node(grid, [&](std::size_t n, const Index<D>&) {
    const bool massive = grid.mass[n] > threshold;
    for (int d = 0; d < D; ++d) grid.velocity[d][n] = massive ? grid.momentum[d][n] / grid.mass[n] : 0.0;
  });
  apply_velocity_constraints(system, system.t);
}

template <int D, class Shape>
void grid_integrate(DiscreteSystem<D, Shape>& system) {
  auto& grid = system.grid;
  const double threshold = system.mass_threshold, dt = system.dt;
  fold_mirror_planes(system, grid.force, false);
  for_each_active_node(grid, [&](std::size_t n, const Index<D>&) {
    const bool massive = grid.mass[n] > threshold;
    for (int d = 0; d < D; ++d) {
      grid.velocity_change[d][n] = grid.velocity[d][n];  // v_I before the update
      if (massive) {
        grid.momentum[d][n] += grid.force[d][n] * dt;
        grid.velocity[d][n] = grid.momentum[d][n] / grid.mass[n];
      } else {
        grid.velocity[d][n] = 0.0;
      }
    }
  });
  apply_velocity_constraints(system, system.t + dt);
  for_each_active_node(grid, [&](std::size_t n, const Index<D>&) {
    for (int d = 0; d < D; ++d) grid.velocity_change[d][n] = grid.velocity[d][n] - grid.velocity_change[d][n];
  });
}

}  // namespace flowmpm
