// External forces on the grid (docs/guide/loads.md), added to the nodal forces
// at the start of grid_integrate, before the mirror planes fold them, with
// the loads evaluated at the start of the step:
//   nodal forces:        f_I += F(t) on each node of the set;
//   tractions:           f_I += N_I(x_f) t(t) A_f,
//   pressures:           f_I += -N_I(x_f) p(t) A_f n_f,
// (with uGIMP, N_I averaged over the face),
// x_f = x_p + offset the centre of a loaded face of particle p, A_f its
// area and n_f its outward normal: the traction acts on the body's surface,
// not at the particle's centre; N_I are renormalised over the nodes that
// carry mass, so that the whole force acts. (CB-Geo mpm maps a particle traction from
// the particle's centre, which puts part of it a cell inside the body:
// docs/validation/uniaxial_traction.md.) Serial, in a fixed order: a
// scene's loaded faces are few. Body forces enter p2g_force (tasks/p2g.hpp).
// The loads' work (engine/energy_balance.hpp): a face's force times the
// displacement of its centre over the step, a nodal force times the
// node's mean velocity over the update times dt (add_nodal_load_work).
#pragma once
#include "discretisation/discrete_system.hpp"
#include "discretisation/grid/stencil.hpp"

namespace flowmpm {

// The share of a nodal force that velocity field `field` takes at node n:
// all of it without contact; with contact, each field in proportion to its
// mass there (bodies sharing a loaded node share its force).
template <int D, class Shape>
double nodal_load_share(const DiscreteSystem<D, Shape>& system, int field, std::size_t n) {
  if (!system.contact) return 1.0;
  double total = 0.0;
  for (int k = 0; k < system.field_count(); ++k) total += system.field(k).mass[n];
  return total > 0.0 ? system.field(field).mass[n] / total : 0.0;
}

template <int D, class Shape>
void add_external_forces(DiscreteSystem<D, Shape>& system) {
  auto& grid = system.grid;
  const double t = system.t;
  for (const NodalLoad& load : system.loads.nodal) {
    for (int d = 0; d < D; ++d) {
      if (!load.force[d]) continue;
      const double f = (*load.force[d])(t);
      if (!system.contact) {
        for (const std::size_t n : load.nodes) grid.force[d][n] += f;
        continue;
      }
      for (int k = 0; k < system.field_count(); ++k)
        for (const std::size_t n : load.nodes) system.field(k).force[d][n] += f * nodal_load_share(system, k, n);
    }
  }
  for (SurfaceLoad<D>& load : system.loads.surface) {
    const Vec<D> traction = axis_values<D>(load.traction, t);
    const double pressure = load.pressure ? (*load.pressure)(t) : 0.0;
    const ParticleBatch<D>& b = system.batches[load.batch];
    NodalField<D>& field = system.field(b.field);
    for (LoadedFace<D>& face : load.faces) {
      const Vec<D> x = b.x[face.particle] + face.offset;
      face.at = x;
      face.force.setZero();
      // The face's stencil must lie in the nodes the grid stages visit.
      bool inside = true;
      for (int d = 0; d < D; ++d) {
        const double g = grid.coordinate(x, d);
        inside = inside && g >= grid.active_lo[d] + Shape::reach_below && g < grid.active_hi[d] - Shape::reach_above + 1;
      }
      if (!inside) {
        system.flags.fail("a loaded face at " + position_text<D>(x) + " (" + load.description +
                          ") left the nodes near the material");
        continue;
      }
      // Axisymmetric: per radian, the face's area times its radius.
      const double area = system.stress_state == StressState::axisymmetric ? face.area * x[0] : face.area;
      Vec<D> force = area * traction;
      force[face.axis] -= pressure * area * face.sign;
      // The face's force goes to the nodes of its stencil that carry the
      // body, in proportion to N there. A node lighter than a millionth of
      // the face's particle carries none of it: it sees only the far tail
      // of the particles' shape functions, or round-off (uGIMP's particle
      // domains end on the face's grid line), and a share of the force
      // would accelerate it without bound.
      const double light = 1e-6 * b.mass[face.particle];
      // The face is a surface: uGIMP averages N over its extent along the
      // face and evaluates it at the face along its normal (half-width 0),
      // f_I = integral over the face of t N_I. (Averaged along the normal
      // too, N would reach a node beyond the face that the body's particles
      // barely reach, with a share of the force out of all proportion to its
      // mass: a block under a traction blew up in two steps.)
      Vec<D> half_width = b.half_width;
      half_width[face.axis] = 0.0;
      const Stencil<D, Shape, false> s(grid, x, half_width);
      double carried = 0.0;
      for (int a = 0; a < s.size; ++a)
        if (field.mass[s.node(a)] > light) carried += s.N(a);
      if (carried <= 0.0) continue;
      face.force = force;
      for (int a = 0; a < s.size; ++a) {
        if (field.mass[s.node(a)] <= light) continue;
        for (int d = 0; d < D; ++d) field.force[d][s.node(a)] += s.N(a) / carried * force[d];
      }
    }
  }
}

// After the grid update of velocity field `field` (velocities at t and
// t + dt in velocity_change and momentum / mass): the nodal forces' work
// over the step, F . (v + v_new) / 2 dt, of the field's share of them.
template <int D, class Shape>
void add_nodal_load_work(DiscreteSystem<D, Shape>& system, int field) {
  const NodalField<D>& grid = system.field(field);
  const double t = system.t, dt = system.dt;
  for (const NodalLoad& load : system.loads.nodal) {
    for (int d = 0; d < D; ++d) {
      if (!load.force[d]) continue;
      const double f = (*load.force[d])(t);
      for (const std::size_t n : load.nodes) {
        if (grid.mass[n] <= 0.0) continue;
        system.work.load += f * nodal_load_share(system, field, n) * 0.5 *
                            (grid.velocity_change[d][n] + grid.momentum[d][n] / grid.mass[n]) * dt;
      }
    }
  }
}

}  // namespace flowmpm
