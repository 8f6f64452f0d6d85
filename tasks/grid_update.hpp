// Grid stages (README "How a step runs"). grid_velocity: v_I = p_I / m_I where m_I is above
// the mass threshold, then the prescribed velocities (p_I follows).
// grid_integrate: the external forces added (tasks/external_forces.hpp),
// p_I += (f_I + f_d) dt with f_d the damping force if the scene has damping,
// v_I^new = p_I / m_I, prescribed velocities at t + dt, and
// dv_I = v_I^new - v_I for the FLIP update; v_I becomes v_I^new so that the
// stages after it read the updated velocity.
#pragma once
#include <cmath>
#include <vector>

#include "tasks/external_forces.hpp"
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

// p_I += (f_I + f_d) dt with the damping force (Damping), along each axis
// the node is free along:
//   f_d = -alpha |f_I| sign(v_I) - c m_I v_I,
// v_I the velocity before the update. Its power f_d (v_I + v_I^new) / 2 is
// summed per slab of nodes and then over the slabs in order, so the sum
// does not depend on the thread count.
template <int D, class Shape>
void integrate_damped(DiscreteSystem<D, Shape>& system) {
  auto& grid = system.grid;
  const Damping& damping = *system.damping;
  const double threshold = system.mass_threshold, dt = system.dt;
  const double alpha = damping.local(system.t), c = damping.viscous(system.t);
  const int first_slab = grid.active_lo[D - 1];
  std::vector<double> slab_power(static_cast<std::size_t>(grid.active_hi[D - 1] - first_slab + 1), 0.0);
  for_each_active_node(grid, [&](std::size_t n, const Index<D>& ijk) {
    const bool massive = grid.mass[n] > threshold;
    double power = 0.0;
    for (int d = 0; d < D; ++d) {
      const double v = grid.velocity[d][n];
      grid.velocity_change[d][n] = v;  // v_I before the update
      if (!massive) {
        grid.velocity[d][n] = 0.0;
        continue;
      }
      double f = grid.force[d][n], f_d = 0.0;
      if (!((damping.undamped[n] >> d) & 1u)) {
        f_d = -alpha * std::abs(f) * static_cast<double>((v > 0.0) - (v < 0.0)) - c * grid.mass[n] * v;
        f += f_d;
      }
      grid.momentum[d][n] += f * dt;
      grid.velocity[d][n] = grid.momentum[d][n] / grid.mass[n];
      power += f_d * 0.5 * (v + grid.velocity[d][n]);
    }
    slab_power[static_cast<std::size_t>(ijk[D - 1] - first_slab)] += power;
  });
  system.damping_power = 0.0;
  for (const double p : slab_power) system.damping_power += p;
  system.damping_dissipated -= system.damping_power * dt;
}

template <int D, class Shape>
void grid_integrate(DiscreteSystem<D, Shape>& system) {
  auto& grid = system.grid;
  const double threshold = system.mass_threshold, dt = system.dt;
  add_external_forces(system);
  fold_mirror_planes(system, grid.force, false);
  if (system.damping) {
    integrate_damped(system);
  } else {
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
  }
  apply_velocity_constraints(system, system.t + dt);
  for_each_active_node(grid, [&](std::size_t n, const Index<D>&) {
    for (int d = 0; d < D; ++d) grid.velocity_change[d][n] = grid.velocity[d][n] - grid.velocity_change[d][n];
  });
}

}  // namespace flowmpm
