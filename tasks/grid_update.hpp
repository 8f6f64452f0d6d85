// Grid stages (docs/theory/step.md). grid_velocity: v_I = p_I / m_I
// (0 on empty nodes), then the prescribed velocities (p_I follows).
// grid_integrate: the external forces added (tasks/external_forces.hpp),
// p_I += (f_I + f_d) dt with f_d the damping force if the scene has damping,
// v_I^new = p_I / m_I (but see held_node), prescribed velocities at t + dt, dv_I = v_I^new - v_I for the FLIP update,
// and the constraints' reactions; v_I becomes v_I^new so that the stages
// after it read the updated velocity.
#pragma once
#include <cmath>
#include <vector>

#include "tasks/external_forces.hpp"
#include "tasks/parallel_blocks.hpp"

namespace flowmpm {

// On one velocity field (every field of a contact scene holds them).
template <int D, class Shape>
void apply_velocity_constraints(DiscreteSystem<D, Shape>& system, NodalField<D>& grid, double time) {
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
void fold_mirror_planes(DiscreteSystem<D, Shape>& system, NodalField<D>& grid, typename NodalField<D>::VectorField& field,
                        bool with_mass) {
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
  const double dt = system.dt;
  for (NodeConstraint& c : system.constraints) {
    const int a = c.axis;
    double J = 0.0;
    for (int k = 0; k < system.field_count(); ++k) {
      const NodalField<D>& grid = system.field(k);
      const auto impulse = [&](std::size_t n, double mass, double force) {
        return mass * grid.velocity_change[a][n] - force * dt;
      };
      for (std::size_t n : c.nodes) J += impulse(n, grid.mass[n], grid.force[a][n]);
      if (c.mirror_plane >= 0) {
        // Along a constrained axis the fold is antisymmetric: f_mirror += -f_ghost.
        for (auto [ghost, mirror] : system.mirror_planes[c.mirror_plane].pairs) {
          J += impulse(ghost, grid.mass[ghost], grid.force[a][ghost]);
          J += impulse(mirror, grid.mass[mirror] - grid.mass[ghost], grid.force[a][mirror] + grid.force[a][ghost]);
        }
      }
    }
    c.reaction = J / dt;
    c.work += J * c.velocity(system.t + dt);  // the reaction's power at the prescribed velocity
  }
}

template <int D, class Shape>
void grid_velocity(DiscreteSystem<D, Shape>& system) {
  for (int k = 0; k < system.field_count(); ++k) {
    NodalField<D>& field = system.field(k);
    fold_mirror_planes(system, field, field.momentum, true);
    for_each_active_node(system.grid, [&](std::size_t n, const Index<D>&) {
      // p / m is a mean of particle velocities, however light the node: a node
      // left at v = 0 would strain a rigidly moving body, (0 - v) dN dt.
      const double m = field.mass[n];
      for (int d = 0; d < D; ++d) field.velocity[d][n] = m > 0.0 ? field.momentum[d][n] / m : 0.0;
    });
    apply_velocity_constraints(system, field, system.t);
  }
}

// A node too light for its stiffness: its own frequency sqrt(k_I / m_I),
// k_I = sum_p V_p M_p |grad N_Ip|^2 (M the P-wave modulus), exceeds 1 / dt.
// Only linear shape functions make such nodes, and only USL and APIC need
// them held (the grid keeps their stiffness only then): where a particle's weight
// N_Ip on a node vanishes, its gradient does not (at the material's moving
// edge), and v_I + f_I dt / m_I would throw the stress update (USL) and the
// positions off by (c dt / h)^2 / N_Ip times the strain in one step
// (docs/STABILITY.md); APIC's affine velocity sum_I v_I (x) dN_Ip would take
// f_I dt / m_I whole (docs/theory/transfers.md; APIC's v_p and x_p take
// p_I / m_I instead). Such a node hands the stress, position and affine
// velocity updates its
// start-of-step velocity, as USF and MUSL do at every node, while FLIP still
// gives its particles the whole increment f_I dt / m_I (N_Ip f_I dt / m_I
// is bounded), so that momentum is kept.
template <int D, class Shape>
bool held_node(const NodalField<D>& grid, std::size_t n, double dt) {
  if constexpr (Shape::gradient_jumps)
    return !grid.stiffness.empty() && grid.mass[n] > 0.0 && grid.stiffness[n] * dt * dt > grid.mass[n];
  return false;
}

// p_I += (f_I + f_d) dt with the damping force (Damping), along each axis
// the node is free along:
//   f_d = -alpha |f_I| sign(v_I) - c m_I v_I,
// v_I the velocity before the update. Its power f_d (v_I + v_I^new) / 2,
// v_I^new = p_I / m_I (a held node's too), is the damping's share of the
// grid's kinetic energy change; it is summed per slab of nodes and then over
// the slabs in order, so the sum does not depend on the thread count.
// Returns the power (W).
template <int D, class Shape>
double integrate_damped(DiscreteSystem<D, Shape>& system, NodalField<D>& grid) {
  const Damping& damping = *system.damping;
  const double dt = system.dt;
  const double alpha = damping.local(system.t), c = damping.viscous(system.t);
  const int first_slab = system.grid.active_lo[D - 1];
  std::vector<double> slab_power(static_cast<std::size_t>(system.grid.active_hi[D - 1] - first_slab + 1), 0.0);
  for_each_active_node(system.grid, [&](std::size_t n, const Index<D>& ijk) {
    const double m = grid.mass[n];
    const bool held = held_node<D, Shape>(grid, n, dt);
    double power = 0.0;
    for (int d = 0; d < D; ++d) {
      const double v = grid.velocity[d][n];
      grid.velocity_change[d][n] = v;  // v_I before the update
      if (m <= 0.0) continue;
      double f = grid.force[d][n], f_d = 0.0;
      if (!((damping.undamped[n] >> d) & 1u)) {
        f_d = -alpha * std::abs(f) * static_cast<double>((v > 0.0) - (v < 0.0)) - c * m * v;
        f += f_d;
      }
      grid.momentum[d][n] += f * dt;
      const double v_new = grid.momentum[d][n] / m;
      if (!held) grid.velocity[d][n] = v_new;
      power += f_d * 0.5 * (v + v_new);
    }
    slab_power[static_cast<std::size_t>(ijk[D - 1] - first_slab)] += power;
  });
  double power = 0.0;
  for (const double p : slab_power) power += p;
  return power;
}

template <int D, class Shape>
void apply_walls(DiscreteSystem<D, Shape>& system, int k);  // tasks/wall.hpp

template <int D, class Shape>
void grid_integrate(DiscreteSystem<D, Shape>& system) {
  const double dt = system.dt;
  add_external_forces(system);
  for (Wall<D>& wall : system.walls) wall.force.setZero();
  // In a contact scene, FLIP's velocity change counts from the projected
  // momentum as contact_projected corrected it (tasks/contact.hpp).
  const bool from_momentum = system.contact.has_value();
  if (system.damping) system.damping_power = 0.0;
  for (int k = 0; k < system.field_count(); ++k) {
    NodalField<D>& grid = system.field(k);
    fold_mirror_planes(system, grid, grid.force, false);
    if (system.damping) {
      if (from_momentum) {
        for_each_active_node(system.grid, [&](std::size_t n, const Index<D>&) {
          for (int d = 0; d < D; ++d)
            if (grid.mass[n] > 0.0) grid.velocity[d][n] = grid.momentum[d][n] / grid.mass[n];
        });
      }
      system.damping_power += integrate_damped(system, grid);
    } else {
      for_each_active_node(system.grid, [&](std::size_t n, const Index<D>&) {
        const double m = grid.mass[n];
        const bool held = held_node<D, Shape>(grid, n, dt);
        for (int d = 0; d < D; ++d) {
          // v_I before the update
          grid.velocity_change[d][n] = from_momentum && m > 0.0 ? grid.momentum[d][n] / m : grid.velocity[d][n];
          if (m > 0.0) {
            grid.momentum[d][n] += grid.force[d][n] * dt;
            if (!held) grid.velocity[d][n] = grid.momentum[d][n] / m;
          }
        }
      });
    }
    apply_velocity_constraints(system, grid, system.t + dt);
    if (!system.walls.empty()) apply_walls(system, k);
    add_nodal_load_work(system, k);
    // dv_I for FLIP; a held node's is that of its momentum.
    for_each_active_node(system.grid, [&](std::size_t n, const Index<D>&) {
      const bool held = held_node<D, Shape>(grid, n, dt);
      for (int d = 0; d < D; ++d) {
        const double v_new = held ? grid.momentum[d][n] / grid.mass[n] : grid.velocity[d][n];
        grid.velocity_change[d][n] = v_new - grid.velocity_change[d][n];
      }
    });
  }
  if (system.damping) system.damping_dissipated -= system.damping_power * dt;
  measure_reactions(system);
}

}  // namespace flowmpm
