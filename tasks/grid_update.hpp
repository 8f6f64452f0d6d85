// Grid stages (DESIGN.md). grid_velocity: v_I = p_I / m_I where m_I is above
// the mass threshold, then the prescribed velocities (p_I follows). 
// grid_integrate: p_I += f_I dt, v_I^new = p_I / m_I, prescribed velocities
// at t + dt, and dv_I = v_I^new - v_I for the FLIP update; v_I becomes
// v_I^new so that the stages after it read the updated velocity.
#pragma once
#include "tasks/parallel_blocks.hpp"

namespace flowmpm {

template <int D, class Shape>
void apply_velocity_constraints(Model<D, Shape>& model, double time) {
  auto& grid = model.grid;
  for (const NodeConstraint& c : model.constraints) {
    const double value = c.velocity(time);
    for (std::size_t n : c.nodes) {
      grid.velocity[n][c.axis] = value;
      grid.momentum[n][c.axis] = grid.mass[n] * value;
    }
  }
}

template <int D, class Shape>
void grid_velocity(Model<D, Shape>& model) {
  auto& grid = model.grid;
  const double threshold = model.mass_threshold;
  for_each_active_node(grid, [&](std::size_t n, const Index<D>&) {
    grid.velocity[n] = grid.mass[n] > threshold ? Vec<D>(grid.momentum[n] / grid.mass[n]) : Vec<D>::Zero();
  });
  apply_velocity_constraints(model, model.t);
}

template <int D, class Shape>
void grid_integrate(Model<D, Shape>& model) {
  auto& grid = model.grid;
  const double threshold = model.mass_threshold, dt = model.dt;
  for_each_active_node(grid, [&](std::size_t n, const Index<D>&) {
    grid.velocity_change[n] = grid.velocity[n];  // v_I before the update
    if (grid.mass[n] > threshold) {
      grid.momentum[n] += grid.force[n] * dt;
      grid.velocity[n] = grid.momentum[n] / grid.mass[n];
    } else {
      grid.velocity[n].setZero();
    }
  });
  apply_velocity_constraints(model, model.t + dt);
  for_each_active_node(grid, [&](std::size_t n, const Index<D>&) {
    grid.velocity_change[n] = grid.velocity[n] - grid.velocity_change[n];
  });
}

}  // namespace flowmpm
