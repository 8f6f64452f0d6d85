// Grid stages (README "How a step runs"). grid_velocity: v_I = p_I / m_I where m_I is above
// the mass threshold, then the prescribed velocities (p_I follows).
// grid_integrate: p_I += f_I dt, v_I^new = p_I / m_I, the constraints'
// reactions, prescribed velocities at t + dt, and dv_I = v_I^new - v_I for
// the FLIP update; v_I becomes v_I^new so that the stages after it read the
// updated velocity.
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

// The reaction of each constraint over the step: the impulse the body's
// particles receive at a node beyond its own forces, m_I dv_I - f_I dt
// (the particles' momentum changes by sum_I m_I dv_I in the FLIP update and
// by sum_I f_I dt where nothing is prescribed), summed over the set's nodes
// and divided by dt; = -sum_I f_I for a fixed support. Where the set is a
// mirror plane, its ghost nodes and the mirror nodes count too, with the
// mass and force the body's particles put there (the folded image's share
// taken off), so that the reactions of all sets add up to the total external
// force of the supports. A node in two sets counts in both; at a corner of
// two mirror planes the image shares are approximate. Serial over the
// constrained nodes, in their order: deterministic.
template <int D, class Shape>
void measure_reactions(DiscreteSystem<D, Shape>& system) {
  const auto& grid = system.grid;
  const double dt = system.dt;
  for (NodeConstraint& c : system.constraints) {
    const int a = c.axis;
    const auto impulse = [&](std::size_t n, double mass, double force) {
      return mass * grid.velocity_change[a][n] - force * dt;
    };
    double J = 0.0;
    for (std::size_t n : c.nodes) J += impulse(n, grid.mass[n], grid.force[a][n]);
    if (c.mirror_plane >= 0) {
      // Along a constrained axis the fold is antisymmetric: f_mirror += -f_ghost.
      for (auto [ghost, mirror] : system.mirror_planes[c.mirror_plane].pairs) {
        J += impulse(ghost, grid.mass[ghost], grid.force[a][ghost]);
        J += impulse(mirror, grid.mass[mirror] - grid.mass[ghost], grid.force[a][mirror] + grid.force[a][ghost]);
      }
    }
    c.reaction = J / dt;
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
  measure_reactions(system);
}

}  // namespace flowmpm
