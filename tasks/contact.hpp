// Contact stages (docs/theory/contact.md), only in a scene with [[contacts]]
// (discretisation/contact/contact_fields.hpp):
//   contact_volumes:   per contact field k, V_kI = sum_p N_Ip V_p and its
//                      gradient G_kI = sum_p V_p grad N_Ip, from the
//                      particles at the start of the step, and for a field
//                      an interface bonds the sums of its displacement fit
//                      (interface_displacement.hpp);
//   contact_projected: after every grid_velocity: the contact laws applied
//                      to the projected momenta and velocities, which FLIP's
//                      increment counts from (grid_integrate) and the stress
//                      update reads (USF, and MUSL's second projection);
//   contact_updated:   after grid_integrate: the laws applied to the updated
//                      momenta, the impulses added to each field's momentum,
//                      velocity and velocity change (so FLIP and PIC both see
//                      them), the forces and the work measured.
// At a node where fields a and b both carry mass (b may be a rigid body,
// whose velocity V is prescribed and whose mass counts as infinite):
//   r = v_a - v_cm, v_cm = (p_a + p_b) / (m_a + m_b)   (v_cm = V if b is rigid),
// and the pair's law gives a's velocity change dv_a(r, n); b takes the
// opposite impulse, -m_a dv_a. Laws other than stick act only where the
// bodies touch, V_a + V_b >= touch_fraction * (node volume prod h), and
// approach, r . n > 0, n the unit normal out of a:
//   n = G_a / |G_a| or -G_b / |G_b|, the normal of the body with more volume
//       at the node (the better resolved surface there; n_b = -n_a),
//   n = -G_b / |G_b|               against a rigid body (its surface is exact),
// G = sum_p V_p grad N_Ip pointing out of a body at its surface nodes (N_Ip
// grows as a particle moves towards node I). Axisymmetric: V_p is the
// section's area V_p / r_p here, the section's geometry as in plane strain.
// An interface (contact_law_interface.hpp) changes no velocity here: it is
// a force, added to the fields' nodal forces before grid_integrate
// (tasks/contact_bonds.hpp); contact_volumes maps what it needs.
// A node shared by more than two fields applies its pairs one after the
// other, in field order. Each field keeps its own constraints and loads
// (tasks/grid_update.hpp). Serial over a node's pairs, parallel over slabs
// of nodes with per-slab sums added in slab order: thread-count independent.
#pragma once
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <array>
#include <cmath>
#include <utility>
#include <vector>

#include "tasks/grid_update.hpp"
#include "tasks/parallel_blocks.hpp"

namespace flowmpm {

template <int D, class Shape>
void contact_volumes(DiscreteSystem<D, Shape>& system) {
  auto& grid = system.grid;
  ContactFields<D>& contact = *system.contact;
  for (std::size_t k = 1; k <= contact.volume.size(); ++k)
    for_each_active_node(grid, [&](std::size_t n, const Index<D>&) { contact.clear_node(k, n); });
  for (auto& field : contact.displacement) {
    if (field.empty()) continue;
    for_each_active_node(grid, [&](std::size_t n, const Index<D>&) {
      for (auto& s : field.sum) s[n] = 0.0;
    });
  }
  const bool axisymmetric = system.stress_state == StressState::axisymmetric;
  scatter_by_colour(system, [&](ParticleBatch<D>& b, std::uint32_t first, std::uint32_t last, std::uint32_t) {
    if (b.field == 0) return;
    double* const to_volume = contact.volume[b.field - 1].data();
    double* to_gradient[D];
    for (int d = 0; d < D; ++d) to_gradient[d] = contact.volume_gradient[b.field - 1][d].data();
    using Spread = ParticleSpread<D>;
    double* to_spread[Spread::terms];
    for (int t = 0; t < Spread::terms; ++t) to_spread[t] = contact.spread[b.field - 1].sum[t].data();
    // With an interface: sum_p N_Ip V_p q_p too, q the terms of the displacement fit.
    using Fit = InterfaceDisplacement<D>;
    const bool bonded = b.field <= contact.deformable_count() && !contact.displacement[b.field - 1].empty();
    double* to_fit[Fit::terms];
    for (int t = 0; t < Fit::terms; ++t) to_fit[t] = bonded ? contact.displacement[b.field - 1].sum[t].data() : nullptr;
    const auto scatter = [&]<bool Bonded>() {
      for (std::uint32_t p = first; p < last; ++p) {
        const Stencil<D, Shape, true> s(grid, b.x[p], b.half_width);
        // Axisymmetric: the section's area A_p = V_p / r_p, so that the
        // touch test and the normals see the (r, z) section as plane strain
        // does (the r weight of V would tilt every normal outwards by
        // grad r, and leave the nodes near the axis never full).
        const double V = axisymmetric ? b.volume[p] / b.x[p][0] : b.volume[p];
        std::array<double, Spread::terms> Vs = Spread::particle_terms(Vec<D>(b.x[p] - grid.origin));
        for (double& q : Vs) q *= V;
        std::array<double, Fit::terms> Vq;
        if constexpr (Bonded) {
          Vq = Fit::particle_terms(Vec<D>(b.x[p] - grid.origin), Vec<D>(b.x[p] - b.x0[p]));
          for (double& q : Vq) q *= V;
        }
        s.for_each_node_pair([&]<int Count>(int line, int k, std::size_t n) {
          const auto w = s.template pair_weights<Count>(line, k);
          store_nodes<Count>(to_volume + n, load_nodes<Count>(to_volume + n) + V * w.N);
          for (int d = 0; d < D; ++d)
            store_nodes<Count>(to_gradient[d] + n, load_nodes<Count>(to_gradient[d] + n) + V * w.dN[d]);
          for (int t = 0; t < Spread::terms; ++t)
            store_nodes<Count>(to_spread[t] + n, load_nodes<Count>(to_spread[t] + n) + Vs[t] * w.N);
          if constexpr (Bonded)
            for (int t = 0; t < Fit::terms; ++t)
              store_nodes<Count>(to_fit[t] + n, load_nodes<Count>(to_fit[t] + n) + Vq[t] * w.N);
        });
      }
    };
    bonded ? scatter.template operator()<true>() : scatter.template operator()<false>();
  });
  // A rigid body is at a node where it has volume there, and there the
  // deformable body's velocity must keep to it. A particle on the edge of
  // a stencil (on a node plane with linear shape functions, at a cell's
  // centre with quadratic B-splines) gives the node a weight of rounding's
  // size instead of 0 (1e-16; 1e-32 with a B-spline), and a rigid body
  // with that much volume at a node deep inside the other body held it
  // (docs/theory/contact.md): below 1e-9 of the node's volume it is none.
  double node_volume = 1.0;
  for (int d = 0; d < D; ++d) node_volume *= grid.h[d];
  for (std::size_t k = contact.deformable.size() + 1; k <= contact.volume.size(); ++k)
    for_each_active_node(grid, [&](std::size_t n, const Index<D>&) {
      if (contact.volume[k - 1][n] < ContactFields<D>::least_volume * node_volume) contact.clear_node(k, n);
    });
}

namespace detail {

// The velocities of node n's fields, corrected pair by pair, and the
// impulses summed. `Updated`: after grid_integrate, from the updated
// momenta; otherwise the projected velocities, and their momenta with them.
template <int D, class Shape, bool Updated>
struct NodeContact {
  DiscreteSystem<D, Shape>& system;
  const ContactFields<D>& contact;
  std::vector<NodalField<D>*> corrected;  // per velocity field, the nodal values corrected
  std::vector<Vec<D>> rigid_velocity;  // per rigid body, at this stage's time
  double node_volume = 1.0;            // prod h
  // Scratch, per field: mass, velocity, velocity change so far, and (Updated)
  // the velocity at the start of the step.
  std::vector<double> m;
  std::vector<Vec<D>> v, dv, v_start;
  std::vector<char> held;  // per field: whether node n is held for it (grid_update.hpp)

  NodeContact(DiscreteSystem<D, Shape>& s, double time, std::vector<NodalField<D>*> nodal)
      : system(s),
        contact(*s.contact),
        corrected(std::move(nodal)),
        m(s.field_count()),
        v(s.field_count()),
        dv(s.field_count()),
        v_start(s.field_count()),
        held(s.field_count()) {
    for (const RigidMotion<D>& r : contact.rigid) rigid_velocity.push_back(r.at(time));
    for (int d = 0; d < D; ++d) node_volume *= s.grid.h[d];
  }

  bool touch(const ContactPair& pair, std::size_t n) const {
    return contact.volume[pair.first - 1][n] + contact.volume[pair.second - 1][n] >=
           pair.touch_fraction * node_volume;
  }

  // The law's velocity change of field a for relative velocity r: the
  // whole of -r for stick; else only where the pair touches and approaches.
  // Sets `normal` (zero for stick).
  Vec<D> change(int pair_index, int a, int b, std::size_t n, const Vec<D>& r, Vec<D>& normal) const {
    normal.setZero();
    if (pair_index < 0) return -r;  // fields no contact pairs stick
    const ContactPair& pair = contact.pairs[static_cast<std::size_t>(pair_index)];
    if (detects_contact(pair.law)) {
      if (!touch(pair, n)) return Vec<D>::Zero();
      if (!contact.outward_normal(a, b, n, normal)) return Vec<D>::Zero();
    }
    return contact_velocity_change(pair.law, r, normal);
  }

  // Corrects node n; adds its impulses and their work to `sums`.
  void operator()(std::size_t n, ContactImpulses<D>& sums) {
    const int fields = system.field_count();
    int present = 0;
    for (int k = 0; k < fields; ++k) {
      const NodalField<D>& f = *corrected[k];
      m[k] = f.mass[n];
      if (!(m[k] > 0.0)) continue;
      ++present;
      for (int d = 0; d < D; ++d) {
        v[k][d] = Updated ? f.momentum[d][n] / m[k] : f.velocity[d][n];
        if constexpr (Updated) v_start[k][d] = v[k][d] - f.velocity_change[d][n];
      }
      dv[k].setZero();
    }
    if (present + (contact.rigid_at(n) ? 1 : 0) < 2) return;
    for (int k = 0; k < fields; ++k) held[k] = m[k] > 0.0 && held_node<D, Shape>(*corrected[k], n, system.dt);
    Vec<D> normal;
    for (int a = 0; a < fields; ++a) {
      if (!(m[a] > 0.0)) continue;
      // Deformable pairs.
      for (int b = a + 1; b < fields; ++b) {
        if (!(m[b] > 0.0)) continue;
        const int pair = contact.pair_index(a, b);
        if (pair >= 0 && is_interface(contact.pairs[static_cast<std::size_t>(pair)].law)) continue;
        // A held node (a sliver of a body's mass with the whole force of
        // its stress, tasks/grid_update.hpp) has no velocity of its body:
        // two bodies that may part meet at the nodes beside it
        // (docs/theory/contact.md). Fields in stick stay one field.
        if ((held[a] || held[b]) && pair >= 0 && detects_contact(contact.pairs[static_cast<std::size_t>(pair)].law))
          continue;
        const Vec<D> va = v[a] + dv[a], vb = v[b] + dv[b];
        const Vec<D> r = (m[b] / (m[a] + m[b])) * (va - vb);  // v_a - v_cm
        const Vec<D> change_a = this->change(pair, a, b, n, r, normal);
        if (change_a.isZero(0.0)) continue;
        const Vec<D> impulse = m[a] * change_a;
        const Vec<D> change_b = -impulse / m[b];
        dv[a] += change_a;
        dv[b] += change_b;
        if (pair >= 0) add_pair_sums(sums, static_cast<std::size_t>(pair), impulse, normal);
      }
      // Rigid bodies.
      for (std::size_t ri = 0; ri < contact.rigid.size(); ++ri) {
        const int b = fields + static_cast<int>(ri);
        const int pair = contact.pair_index(a, b);
        if (pair < 0 || !(contact.volume[b - 1][n] > 0.0)) continue;
        const Vec<D> va = v[a] + dv[a];
        const Vec<D> change_a = this->change(pair, a, b, n, Vec<D>(va - rigid_velocity[ri]), normal);
        if (change_a.isZero(0.0)) continue;
        const Vec<D> impulse = m[a] * change_a;
        dv[a] += change_a;
        sums.rigid_impulse[ri] += impulse;
        sums.rigid_work[ri] += impulse.dot(rigid_velocity[ri]);
        add_pair_sums(sums, static_cast<std::size_t>(pair), impulse, normal);
      }
    }
    // Write back what changed.
    for (int k = 0; k < fields; ++k) {
      if (!(m[k] > 0.0) || dv[k].isZero(0.0)) continue;
      NodalField<D>& f = *corrected[k];
      if constexpr (Updated) {
        // The contact's impulse on the field times the mean of its velocity
        // at the start and at the end of the step. At a held node
        // (grid_update.hpp: a sliver of a body's mass with the full force of
        // its stress) p_I / m_I is no velocity of the body, and what the
        // contact leaves of it (friction takes at most mu times the normal
        // change) would book a work of order (f_I dt)^2 / m_I: its particles
        // take the impulse in N_Ip p_I / m_I, moving at about the node's
        // start-of-step velocity, so the impulse's work is its product with that.
        sums.work += m[k] * dv[k].dot(held[k] ? v_start[k] : Vec<D>(0.5 * (v_start[k] + v[k] + dv[k])));
        for (int d = 0; d < D; ++d) {
          f.momentum[d][n] += m[k] * dv[k][d];
          if (!held[k]) f.velocity[d][n] += dv[k][d];
          f.velocity_change[d][n] += dv[k][d];
        }
      } else {
        // An impulse at an instant: its work is the change of the kinetic
        // energy, the impulse times the mean of the velocities before and after.
        sums.work += m[k] * dv[k].dot(v[k] + 0.5 * dv[k]);
        for (int d = 0; d < D; ++d) {
          f.momentum[d][n] += m[k] * dv[k][d];
          f.velocity[d][n] += dv[k][d];
        }
      }
    }
  }

  static void add_pair_sums(ContactImpulses<D>& sums, std::size_t pair, const Vec<D>& impulse, const Vec<D>& normal) {
    const double along = impulse.dot(normal);
    sums.normal[pair] -= along;
    sums.tangential[pair] += impulse - along * normal;
  }
};

// Each velocity field's nodal values.
template <int D, class Shape>
std::vector<NodalField<D>*> velocity_fields(DiscreteSystem<D, Shape>& system) {
  std::vector<NodalField<D>*> fields;
  for (int k = 0; k < system.field_count(); ++k) fields.push_back(&system.field(k));
  return fields;
}

// Runs NodeContact on `fields` (by default the velocity fields) over the
// active nodes, slab by slab in parallel, and returns the sums of each slab
// in slab order.
template <int D, class Shape, bool Updated>
std::vector<ContactImpulses<D>> contact_pass(DiscreteSystem<D, Shape>& system, double time,
                                             const std::vector<NodalField<D>*>& fields) {
  const auto& grid = system.grid;
  const int first = grid.active_lo[D - 1], last = grid.active_hi[D - 1];
  std::vector<ContactImpulses<D>> slab_sums(static_cast<std::size_t>(last - first + 1), system.contact->no_impulses());
  tbb::parallel_for(tbb::blocked_range<int>(first, last + 1), [&](const tbb::blocked_range<int>& slabs) {
    NodeContact<D, Shape, Updated> node(system, time, fields);
    for (int slab = slabs.begin(); slab != slabs.end(); ++slab) {
      ContactImpulses<D>& sums = slab_sums[static_cast<std::size_t>(slab - first)];
      grid.for_each_active_node_in_slab(slab, [&](std::size_t n, const Index<D>&) { node(n, sums); });
    }
  });
  return slab_sums;
}

// The slabs' sums, added in slab order.
template <int D>
ContactImpulses<D> slab_total(const std::vector<ContactImpulses<D>>& slab_sums, const ContactFields<D>& contact) {
  ContactImpulses<D> total = contact.no_impulses();
  for (const auto& s : slab_sums) total += s;
  return total;
}

}  // namespace detail

// The projected pass's impulses reach the particles' velocities (and so
// their momentum and kinetic energy) in the share that the particles take
// the grid's velocity rather than its increment: all of them for PIC, APIC
// and XPIC, 1 - a for the blend, none for FLIP, whose increment counts from
// the corrected velocity. Each pass replaces the last one's: the pass after
// MUSL's second projection corrects only what its stress update reads, and
// the next step's first pass takes its place.
template <int D, class Shape>
void contact_projected(DiscreteSystem<D, Shape>& system) {
  ContactFields<D>& contact = *system.contact;
  contact.projected = detail::slab_total(detail::contact_pass<D, Shape, false>(system, system.t, detail::velocity_fields(system)), contact);
  contact.projected *= 1.0 - system.flip_fraction;
}

// XPIC's iterates u_k = Q^(k-1) v^L (tasks/xpic.hpp) take the contact laws
// as the projected velocities do, with the same touch test and normals and
// each iterate's own approach test, as NairnMPM imposes contact on every
// increment of its XPIC recursion [NairnMPM]: so that the filter w, whose
// particles' velocity is sum_I N_Ip (v_I^L+ - w_I), knows of the contact
// that corrects v^L+ (two fields in stick are one field's XPIC). Their
// impulses count nowhere: the iterates are no momentum of the step.
// Only the nodes where two or more fields carry mass can change: those of
// contact_nodes, found once per step, slab by slab in parallel and joined
// in slab order.
template <int D, class Shape>
std::vector<std::size_t> contact_nodes(const DiscreteSystem<D, Shape>& system) {
  const auto& grid = system.grid;
  const ContactFields<D>& contact = *system.contact;
  const int fields = system.field_count();
  const int first = grid.active_lo[D - 1], last = grid.active_hi[D - 1];
  std::vector<std::vector<std::size_t>> slab_nodes(static_cast<std::size_t>(last - first + 1));
  tbb::parallel_for(tbb::blocked_range<int>(first, last + 1), [&](const tbb::blocked_range<int>& slabs) {
    for (int slab = slabs.begin(); slab != slabs.end(); ++slab) {
      std::vector<std::size_t>& nodes = slab_nodes[static_cast<std::size_t>(slab - first)];
      grid.for_each_active_node_in_slab(slab, [&](std::size_t n, const Index<D>&) {
        // As NodeContact counts them: the fields with mass, and any rigid body as one.
        int present = 0;
        for (int k = 0; k < fields; ++k) present += system.field(k).mass[n] > 0.0 ? 1 : 0;
        if (present + (contact.rigid_at(n) ? 1 : 0) >= 2) nodes.push_back(n);
      });
    }
  });
  std::vector<std::size_t> nodes;
  for (const auto& s : slab_nodes) nodes.insert(nodes.end(), s.begin(), s.end());
  return nodes;
}

template <int D, class Shape>
void contact_on_xpic_iterates(DiscreteSystem<D, Shape>& system, const std::vector<std::size_t>& nodes) {
  std::vector<NodalField<D>*> iterates;
  for (XpicNodes<D>& x : system.xpic) iterates.push_back(&x.iterate);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, nodes.size(), 256), [&](const tbb::blocked_range<std::size_t>& r) {
    detail::NodeContact<D, Shape, false> node(system, system.t, iterates);
    ContactImpulses<D> discarded = system.contact->no_impulses();
    for (std::size_t i = r.begin(); i != r.end(); ++i) node(nodes[i], discarded);
  });
}

template <int D, class Shape>
void contact_updated(DiscreteSystem<D, Shape>& system) {
  ContactFields<D>& contact = *system.contact;
  const double dt = system.dt;
  ContactImpulses<D> total = detail::slab_total(detail::contact_pass<D, Shape, true>(system, system.t + dt, detail::velocity_fields(system)), contact);
  total += contact.projected;  // the step's impulses: at the projection and after the update
  contact.projected = contact.no_impulses();
  for (std::size_t i = 0; i < contact.pairs.size(); ++i) {
    if (is_interface(contact.pairs[i].law)) continue;  // its forces are contact_bonds'
    contact.pairs[i].normal_force = total.normal[i] / dt;
    contact.pairs[i].tangential_force = total.tangential[i].norm() / dt;
  }
  for (std::size_t r = 0; r < contact.rigid.size(); ++r) {
    contact.rigid[r].force = -total.rigid_impulse[r] / dt;  // on the rigid body
    contact.rigid[r].work += total.rigid_work[r];
  }
  system.work.contact += total.work;
}

}  // namespace flowmpm
