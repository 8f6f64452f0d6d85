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
      grid.velocity[c.axis][n] = value;
      grid.momentum[c.axis][n] = grid.mass[n] * value;
    }
  }
  // Ghost nodes take their mirror's velocity, reflected about the plane's.
  for (const MirrorPlane& plane : model.mirror_planes) {
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
void fold_mirror_planes(Model<D, Shape>& model, typename Grid<D>::VectorField& field, bool with_mass) {
  auto& grid = model.grid;
  for (const MirrorPlane& plane : model.mirror_planes) {
    for (auto [ghost, mirror] : plane.pairs) {
      if (with_mass) grid.mass[mirror] += grid.mass[ghost];
      for (int d = 0; d < D; ++d) field[d][mirror] += (plane.velocity[d] ? -1.0 : 1.0) * field[d][ghost];
    }
  }
}

template <int D, class Shape>
void grid_velocity(Model<D, Shape>& model) {
  auto& grid = model.grid;
  const double threshold = model.mass_threshold;
  fold_mirror_planes(model, grid.momentum, true);
  for_each_active_node(grid, [&](std::size_t n, const Index<D>&) {
    const bool massive = grid.mass[n] > threshold;
    for (int d = 0; d < D; ++d) grid.velocity[d][n] = massive ? grid.momentum[d][n] / grid.mass[n] : 0.0;
  });
  apply_velocity_constraints(model, model.t);
}

template <int D, class Shape>
void grid_integrate(Model<D, Shape>& model) {
  auto& grid = model.grid;
  const double threshold = model.mass_threshold, dt = model.dt;
  fold_mirror_planes(model, grid.force, false);
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
  apply_velocity_constraints(model, model.t + dt);
  for_each_active_node(grid, [&](std::size_t n, const Index<D>&) {
    for (int d = 0; d < D; ++d) grid.velocity_change[d][n] = grid.velocity[d][n] - grid.velocity_change[d][n];
  });
}

}  // namespace flowmpm
