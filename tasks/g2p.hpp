// Grid-to-particle stages (docs/theory/step.md).
// g2p_motion: v_p <- a (v_p + sum_I N_Ip dv_I) + (1 - a) sum_I N_Ip v_I
//             (a = 1 FLIP, a = 0 PIC), x_p <- x_p + dt sum_I N_Ip v_I,
//             with v_I the velocity after grid_integrate;
//             APIC: v_p <- sum_I N_Ip v_I, C_p <- sum_I v_I (x) G_Ip
//             (Stencil's StencilFactor::affine) [Jiang 2015];
//             XPIC(m): v_p <- sum_I N_Ip (v_I - w_I) (tasks/xpic.hpp),
//             x_p as above, and under USL L_p from v_I - w_I too
//             (from v_I in a scene with contact or walls);
//             docs/theory/transfers.md.
// g2p_stress: L_p = sum_I v_I (x) dN_Ip, d eps = sym(L_p) dt, the material
//             update sigma(d eps), eps += d eps, V_p *= 1 + tr(d eps)
//             (axisymmetric: d eps_tt = v_r / r_p dt, v_r = sum_I N_Ip v_I,r,
//             in the zz slot, [Sulsky 1996]); a
//             model asking for nonlocal averages gets them and keeps its
//             start of step (tasks/nonlocal_settle.hpp).
// The material update sees the particle's own temperature and
// concentration when the scene carries them (tasks/transport.hpp, whose
// branch of the step graph joins before this stage).
// USL does both in one pass over the particles, with N and dN at the
// positions of the start of the step: the stencil of the step's p2g, as in
// CB-Geo mpm. MUSL's g2p_stress follows the remap, so it and the remap see
// the updated positions.
#pragma once
#include <atomic>
#include <cmath>

#include "discretisation/grid/stencil.hpp"
#include "tasks/parallel_blocks.hpp"
#include "tasks/xpic.hpp"

namespace flowmpm {

namespace detail {

// A batch's particle temperatures and concentrations for the material
// update (null when the scene carries none), and its material's T_ref.
// The steps are the changes since the last stress update (since the
// stress-free state before the first): the update takes and clears them.
struct TransportedInput {
  const double* temperature = nullptr;
  double* temperature_step = nullptr;
  const double* concentration = nullptr;
  double* concentration_step = nullptr;
  double reference_temperature = 0.0;  // K
};

// The material update of particle p for its velocity gradient L and, in
// axisymmetric, its hoop rate v_r / r (0 otherwise) (g2p_stress). Returns the work done on it by its expansion strains over
// the step (J), -V sigma_mid : d eps_expansion, with `ExpansionWork`.
// Nonlocal: the model asks for nonlocal averages; the update gets them,
// and the particle's start of step is kept for tasks/nonlocal_settle.hpp
// to redo the update.
template <int D, class Shape, StressState Kind, bool ExpansionWork, class MaterialModel, bool Nonlocal = false>
[[gnu::always_inline]] inline double update_particle_stress(DiscreteSystem<D, Shape>& system, ParticleBatch<D>& b, std::size_t p,
                                                         const double (&L)[D][D], double hoop,
                                                         const MaterialModel& material,
                                                         typename MaterialModel::State& state,
                                                         const TransportedInput& transported) {
  const double dt = system.dt;
  Voigt deps{};
  for (int i = 0; i < D; ++i)
    for (int j = i; j < D; ++j) deps[voigt_slot(i, j)] = 0.5 * (L[i][j] + L[j][i]) * dt;
  if constexpr (Kind == StressState::axisymmetric) deps[2] = hoop * dt;
  MaterialInput input;
  input.t = system.t + dt;
  input.dt = dt;
  input.length = b.particle_length;
  for (int i = 0; i < D; ++i)
    for (int j = 0; j < D; ++j) input.dL(i, j) = L[i][j] * dt;
  if constexpr (Kind == StressState::axisymmetric) input.dL(2, 2) = hoop * dt;
  if (transported.temperature) {
    input.temperature_change = transported.temperature[p] - transported.reference_temperature;
    input.temperature_step = transported.temperature_step[p];
    transported.temperature_step[p] = 0.0;
  }
  if (transported.concentration) {
    input.concentration = transported.concentration[p];
    input.concentration_step = transported.concentration_step[p];
    transported.concentration_step[p] = 0.0;
  }
  if constexpr (Nonlocal) {
    input.nonlocal_others = b.nonlocal_others[p];
    input.nonlocal_self_weight = b.nonlocal_self_weight[p];
    auto& kept = b.step_start;
    std::get<StateArray<MaterialModel>>(kept.states)[p] = state;
    kept.stress[p] = b.stress[p];
    kept.strain[p] = b.strain[p];
    kept.volume[p] = b.volume[p];
    for (int i = 0; i < D; ++i)
      for (int j = 0; j < D; ++j) kept.L[p][D * i + j] = L[i][j];
    kept.L[p][D * D] = hoop;
  }
  double expansion_work = 0.0;
  if constexpr (ExpansionWork) {
    const Voigt before = b.stress[p];
    material.template update<Kind>(state, b.stress[p], deps, input);
    Voigt mid;
    for (int i = 0; i < 6; ++i) mid[i] = 0.5 * (before[i] + b.stress[p][i]);
    expansion_work = b.volume[p] * material.expansion_work(state, mid, input);
  } else {
    material.template update<Kind>(state, b.stress[p], deps, input);
  }
  if (!std::isfinite(b.stress[p][0] + b.stress[p][1] + b.stress[p][2] + b.stress[p][3] + b.stress[p][4] +
                     b.stress[p][5])) {
    system.flags.fail("a particle at " + position_text<D>(b.x[p]) + ": its stress is not finite");
  }
  for (int i = 0; i < 6; ++i) b.strain[p][i] += deps[i];
  b.volume[p] *= 1.0 + deps[0] + deps[1] + deps[2];
  return expansion_work;
}

// Calls f(update) with update(p, L, hoop) the update of `b`'s particles by
// `material`: one dispatch on the stress state and whether the batch asks
// for nonlocal averages per call, none per particle. `Hoop` (with_hoop):
// the analysis is axisymmetric, the only 2D stress state compiled with it.
template <bool Hoop, int D, class Shape, class M, class F>
void with_material_update(DiscreteSystem<D, Shape>& system, ParticleBatch<D>& b, const M& material, F&& f) {
  auto& states = std::get<StateArray<M>>(b.states);
  TransportedInput transported;
  if (system.heat) {
    transported.temperature = b.temperature.data();
    transported.temperature_step = b.temperature_step.data();
    transported.reference_temperature = material.transport().reference_temperature.value_or(0.0);
  }
  if (system.solvent) {
    transported.concentration = b.concentration.data();
    transported.concentration_step = b.concentration_step.data();
  }
  // The expansion work, for models that can do it; a model that says
  // it does not expand (expands()) skips it, its update alone as before.
  auto for_state = [&]<StressState Kind>() {
    if constexpr (NonlocalModel<M>) {
      if (!b.nonlocal_others.empty()) {
        // A nonlocal model has no expansion strains: no expansion work.
        f([&](std::size_t p, const double(&L)[D][D], double hoop) {
          return update_particle_stress<D, Shape, Kind, false, M, true>(system, b, p, L, hoop, material, states[p],
                                                                       transported);
        });
        return;
      }
    }
    typename M::State no_state{};
    auto with_work = [&]<bool Work>() {
      f([&](std::size_t p, const double(&L)[D][D], double hoop) {
        return update_particle_stress<D, Shape, Kind, Work>(system, b, p, L, hoop, material,
                                                            states.empty() ? no_state : states[p], transported);
      });
    };
    constexpr bool can_work = requires(const typename M::State& s, const Voigt& v, const MaterialInput& in) {
      material.expansion_work(s, v, in);
    };
    if constexpr (!can_work) {
      with_work.template operator()<false>();
    } else if constexpr (requires { material.expands(); }) {
      if (material.expands()) {
        with_work.template operator()<true>();
      } else {
        with_work.template operator()<false>();
      }
    } else {
      with_work.template operator()<true>();
    }
  };
  if constexpr (D == 3) {
    for_state.template operator()<StressState::three_d>();
  } else if constexpr (D == 1) {
    for_state.template operator()<StressState::uniaxial_stress>();
  } else if constexpr (Hoop) {
    for_state.template operator()<StressState::axisymmetric>();
  } else if (system.stress_state == StressState::plane_stress) {
    for_state.template operator()<StressState::plane_stress>();
  } else {
    for_state.template operator()<StressState::plane_strain>();
  }
}

// The same for the batch's own material: one dispatch on it per call.
template <bool Hoop, int D, class Shape, class F>
void with_stress_update(DiscreteSystem<D, Shape>& system, ParticleBatch<D>& b, F&& f) {
  std::visit([&](const auto& material) { with_material_update<Hoop>(system, b, material, f); },
             system.materials[b.material]);
}

// Takes `max` up to `value` (max is exact, so any order gives the same).
inline void raise_to(std::atomic<double>& max, double value) {
  double seen = max.load(std::memory_order_relaxed);
  while (value > seen && !max.compare_exchange_weak(seen, value)) {
  }
}

// A rigid body's particles [first, last) move with its prescribed velocity
// at the end of the step, x += V(t + dt) dt (tasks/contact.hpp); a re-sort
// is due when one leaves [stay_lo, stay_hi] (cells), as in g2p.
template <int D, class Shape>
[[gnu::noinline, gnu::cold]] void move_rigid(DiscreteSystem<D, Shape>& system, ParticleBatch<D>& b, std::uint32_t first, std::uint32_t last,
                const Index<D>& stay_lo, const Index<D>& stay_hi, std::atomic<double>& max_speed_sq) {
  const ContactFields<D>& contact = *system.contact;
  const Vec<D> V = contact.rigid[b.field - 1 - contact.deformable_count()].at(system.t + system.dt);
  const auto& grid = system.grid;
  bool stays = true;
  for (std::uint32_t p = first; p < last; ++p) {
    const Vec<D> x_new = b.x[p] + system.dt * V;
    for (int d = 0; d < D; ++d) {
      const double g = grid.coordinate(x_new, d);
      if (!(g >= Shape::reach_below && g < grid.cells[d] - Shape::reach_above + 1)) {
        system.flags.fail("a particle of a rigid body at " + position_text<D>(b.x[p]) + " would move to " +
                          position_text<D>(x_new) + ", outside the grid");
        return;
      }
      const int c = floor_nonnegative(g);
      stays = stays && c >= stay_lo[d] && c <= stay_hi[d];
    }
    b.v[p] = V;
    b.x[p] = x_new;
  }
  raise_to(max_speed_sq, V.squaredNorm());
  if (!stays) system.flags.resort_needed.store(true, std::memory_order_relaxed);
}

// p_I / m_I at nodes n, n + 1 (Count = 2) or n (Count = 1); 0 on an empty node.
template <int Count>
[[gnu::always_inline]] inline NodePair momentum_velocity(const double* p, const double* m) {
  NodePair v = {};
  for (int lane = 0; lane < Count; ++lane) v[lane] = m[lane] > 0.0 ? p[lane] / m[lane] : 0.0;
  return v;
}

// One pass over the particles: g2p_motion, g2p_stress, or both (USL), from
// one stencil per particle at its position at the start of the pass.
// `Apic`: APIC's velocity update; otherwise FLIP, PIC and their blend
// (flip_fraction), or XPIC's (a branch per particle, not a second copy of
// the pass and of its material updates). `Hoop`: axisymmetric (the hoop
// rate, and no particle onto the axis). `HeldShare`: PIC, the blend or
// XPIC where nodes may be held (below).
template <int D, class Shape, bool Motion, bool Stress, bool Apic = false, bool Hoop = false, bool HeldShare = false>
void g2p(DiscreteSystem<D, Shape>& system) {
  constexpr bool apic = Motion && Apic;
  const bool xpic = Motion && !Apic && system.velocity_update == VelocityUpdate::xpic;
  // XPIC takes v_p, and under USL L_p, from its filtered velocity u
  // (tasks/xpic.hpp, docs/theory/transfers.md).
  const bool xpic_filtered = xpic && xpic_filters_strain(system);
  // APIC's G_Ip is the gradient itself where the shape function has no D_p.
  constexpr bool affine_is_gradient = Shape::apic_inertia == 0.0;
  // Held nodes (linear shape functions, tasks/grid_update.hpp held_node)
  // keep their start-of-step velocity v_I for the stress update, the
  // positions and APIC's C_p (bounded where N_Ip vanishes), but their
  // momentum p_I takes the whole f_I dt. The velocity a particle carries
  // away takes that too, so that momentum is kept and no torque is lost:
  // APIC's v_p and x_p are sum_I N_Ip p_I / m_I; PIC, the blend and XPIC
  // add the held nodes' share sum_I N_Ip (p_I / m_I - v_I) to the velocity
  // (without it they dropped the held nodes' f_I dt, tests/test_transfers.cpp).
  // FLIP's increment is whole already.
  constexpr bool apic_from_momentum = apic && Shape::gradient_jumps;
  constexpr bool held_share = Motion && HeldShare && Shape::gradient_jumps;
  using Layout = BlockLayout<D, Shape>;
  const auto& grid = system.grid;
  const double a = system.flip_fraction, dt = system.dt;
  // Largest particle speed of the step, for the time step and the guard:
  // per block, then combined (max is exact, so any order gives the same).
  std::atomic<double> max_speed_sq{0.0};
  // Grid coordinates where a particle's stencil has nodes: [g_lo, g_hi).
  Vec<D> g_lo, g_hi;
  for (int d = 0; d < D; ++d) {
    g_lo[d] = Shape::reach_below;
    g_hi[d] = grid.cells[d] - Shape::reach_above + 1;
  }
  gather_by_block(system, [&](ParticleBatch<D>& b, std::uint32_t first, std::uint32_t last, std::uint32_t block) {
    // The cells the block's particles may reach before a re-sort is due:
    // fewer than drift_limit cells outside the block, per axis.
    const Index<D> bc = system.blocks.block_coords(block);
    Index<D> stay_lo, stay_hi;
    for (int d = 0; d < D; ++d) {
      stay_lo[d] = bc[d] * Layout::block_cells - Layout::drift_limit + 1;
      stay_hi[d] = bc[d] * Layout::block_cells + Layout::block_cells - 2 + Layout::drift_limit;
    }
    if (system.is_rigid(b)) {
      if constexpr (Motion) move_rigid<D, Shape>(system, b, first, last, stay_lo, stay_hi, max_speed_sq);
      return;
    }
    double block_max_sq = 0.0;
    BlockEnergy energy;  // this segment's sums
    const NodalField<D>& field = system.field(b.field);  // the batch's velocity field
    auto particles = [&](auto&& update_stress) {
      // The field's arrays as locals of the loop, whose address no store
      // of the loop can reach (as arrays of the enclosing lambda they cost
      // 3 % of the step rate).
      const double* velocity[D];
      const double* velocity_change[D];
      [[maybe_unused]] const double* momentum[D];
      [[maybe_unused]] const double* field_velocity[D];
      [[maybe_unused]] const double* const mass = field.mass.data();
      for (int d = 0; d < D; ++d) {
        if constexpr (apic_from_momentum || held_share) momentum[d] = field.momentum[d].data();
        if constexpr (held_share) field_velocity[d] = field.velocity[d].data();
        // XPIC: the filtered velocity u = v^L+ - w, and w.
        velocity[d] = xpic_filtered ? system.xpic[b.field].iterate.velocity[d].data() : field.velocity[d].data();
        velocity_change[d] = xpic ? system.xpic[b.field].correction[d].data() : field.velocity_change[d].data();
      }
      using Affine = Stencil<D, Shape, true, StencilFactor::affine>;
      for (std::uint32_t p = first; p < last; ++p) {
        const Stencil<D, Shape, Stress || (apic && affine_is_gradient)> s(grid, b.x[p], b.half_width);
        [[maybe_unused]] const auto affine = [&] {
          if constexpr (apic && !affine_is_gradient) return Affine(grid, b.x[p], b.half_width);
          else return 0;
        }();
        // Sums over the stencil, two nodes per lane pair, then the lanes
        // added. v_sum and L: of v^L+, or of XPIC's u; dv_sum: FLIP's
        // velocity change, or XPIC's correction w.
        NodePair v_sum[D] = {}, dv_sum[D] = {}, L_sum[D][D] = {}, C_sum[D][D] = {};
        [[maybe_unused]] NodePair held_sum[D] = {};  // the held nodes' share
        [[maybe_unused]] NodePair hoop_sum = {};  // v_r at the particle, with L's velocities
        s.for_each_node_pair([&]<int Count>(int line, int k, std::size_t n) {
          const auto w = s.template pair_weights<Count>(line, k);
          const NodePair N = w.N;
          // APIC's affine weights G_Ip on these nodes.
          [[maybe_unused]] const auto G = [&] {
            if constexpr (!apic || affine_is_gradient) return w;
            else return affine.template pair_weights<Count>(line, k);
          }();
          for (int i = 0; i < D; ++i) {
            const NodePair v = load_nodes<Count>(velocity[i] + n);
            if constexpr (Motion) {
              if constexpr (apic_from_momentum) {
                v_sum[i] += N * momentum_velocity<Count>(momentum[i] + n, mass + n);
              } else {
                v_sum[i] += N * v;
              }
              if constexpr (held_share)
                held_sum[i] += N * (momentum_velocity<Count>(momentum[i] + n, mass + n) -
                                    load_nodes<Count>(field_velocity[i] + n));
              if constexpr (!apic) dv_sum[i] += N * load_nodes<Count>(velocity_change[i] + n);
            }
            if constexpr (Stress)
              for (int j = 0; j < D; ++j) L_sum[i][j] += v * w.dN[j];
            if constexpr (Hoop && Stress)
              if (i == 0) hoop_sum += N * v;
            if constexpr (apic)
              for (int j = 0; j < D; ++j) C_sum[i][j] += v * G.dN[j];
          }
        });
        Vec<D> v_grid, dv;
        [[maybe_unused]] Vec<D> held;
        double L[D][D];  // velocity gradient
        for (int i = 0; i < D; ++i) {
          v_grid[i] = sum(v_sum[i]);
          dv[i] = sum(dv_sum[i]);
          if constexpr (held_share) held[i] = sum(held_sum[i]);
          for (int j = 0; j < D; ++j) L[i][j] = sum(L_sum[i][j]);
        }
        [[maybe_unused]] double hoop = 0.0;  // v_r / r
        if constexpr (Hoop && Stress) hoop = sum(hoop_sum) / b.x[p][0];
        if constexpr (Stress) energy.expansion_work += update_stress(p, L, hoop);
        if constexpr (Motion) {
          // The grid velocity a particle carries away, with the held nodes' share.
          Vec<D> v_carried = v_grid;
          if constexpr (held_share) v_carried += held;
          // XPIC moves the particles with v^L+ = u + w.
          const Vec<D> x_new = b.x[p] + dt * (xpic_filtered ? Vec<D>(v_grid + dv) : v_grid);
          // A particle must stay where its stencil has nodes and may cross at
          // most one cell per step; otherwise it is not moved and the step
          // fails. (The range is checked on the grid coordinate before it
          // becomes an int.)
          bool inside = true, one_cell = true, stays = true;
          Index<D> c_new{};
          for (int d = 0; d < D; ++d) {
            const double g_new = grid.coordinate(x_new, d);
            inside = inside && g_new >= g_lo[d] && g_new < g_hi[d];
            c_new[d] = inside ? floor_nonnegative(g_new) : 0;
          }
          if (inside) {
            for (int d = 0; d < D; ++d) {
              const int c_old = floor_nonnegative(grid.coordinate(b.x[p], d));
              one_cell = one_cell && std::abs(c_new[d] - c_old) <= 1;
              stays = stays && c_new[d] >= stay_lo[d] && c_new[d] <= stay_hi[d];
            }
          }
          if constexpr (Hoop) inside = inside && x_new[0] > 0.0;  // r > 0: off the axis
          Vec<D> v_new;
          if constexpr (apic) {
            v_new = v_carried;
          } else if (xpic) {
            v_new = xpic_filtered ? v_carried : Vec<D>(v_carried - dv);
          } else {
            // Component by component: as one Eigen expression GCC called it out of line.
            for (int d = 0; d < D; ++d) v_new[d] = a * (b.v[p][d] + dv[d]) + (1.0 - a) * v_carried[d];
          }
          if (!inside || !one_cell || !v_new.allFinite()) {
            system.flags.fail("a particle at " + position_text<D>(b.x[p]) + " would move to " +
                             position_text<D>(x_new) +
                             (!v_new.allFinite()          ? ", its velocity not finite"
                              : Hoop && !(x_new[0] > 0.0) ? ", onto or across the axis (r <= 0)"
                              : !inside                   ? ", outside the grid"
                                                 : ", more than one cell in one step"));
            continue;
          }
          energy.gravity_work += b.mass[p] * b.acceleration.dot(x_new - b.x[p]);
          energy.kinetic += 0.5 * b.mass[p] * v_new.squaredNorm();
          b.v[p] = v_new;
          b.x[p] = x_new;
          if constexpr (apic)
            for (int i = 0; i < D; ++i)
              for (int j = 0; j < D; ++j) b.affine[p][D * i + j] = sum(C_sum[i][j]);
          block_max_sq = std::max(block_max_sq, v_new.squaredNorm());
          if (!stays) system.flags.resort_needed.store(true, std::memory_order_relaxed);
        }
      }
    };
    if constexpr (Stress) {
      with_stress_update<Hoop>(system, b, particles);
    } else {
      particles([](std::size_t, const double(&)[D][D], double) { return 0.0; });
    }
    // Only this task touches the block: its segments add up in batch order.
    BlockEnergy& sums = system.block_energy[block];
    if constexpr (Motion) {
      sums.kinetic += energy.kinetic;
      sums.gravity_work += energy.gravity_work;
    }
    if constexpr (Stress) sums.expansion_work += energy.expansion_work;
    raise_to(max_speed_sq, block_max_sq);
  });
  if constexpr (Motion) system.max_speed_sq = max_speed_sq.load();
}

// g2p_motion (with g2p_stress under USL) for the scene's velocity update;
// XPIC's correction first, while the particles are still where the step
// found them.
template <int D, class Shape, bool Stress, bool Hoop>
void g2p_with_motion(DiscreteSystem<D, Shape>& system) {
  if (system.velocity_update == VelocityUpdate::apic) {
    g2p<D, Shape, true, Stress, true, Hoop>(system);
    return;
  }
  if (system.velocity_update == VelocityUpdate::xpic) xpic_correction(system);
  if constexpr (Shape::gradient_jumps) {
    if (system.velocity_update != VelocityUpdate::flip && !system.field(0).stiffness.empty()) {  // nodes may be held
      g2p<D, Shape, true, Stress, false, Hoop, true>(system);
      return;
    }
  }
  g2p<D, Shape, true, Stress, false, Hoop>(system);
}

// The pass, with the hoop rate where the analysis is axisymmetric.
template <int D, class Shape, bool Motion, bool Stress>
void g2p_of_state(DiscreteSystem<D, Shape>& system) {
  with_hoop(system, [&]<bool Hoop>() {
    if constexpr (Motion) {
      g2p_with_motion<D, Shape, Stress, Hoop>(system);
    } else {
      g2p<D, Shape, false, Stress, false, Hoop>(system);
    }
  });
}

}  // namespace detail

template <int D, class Shape>
void g2p_motion(DiscreteSystem<D, Shape>& system) {
  detail::g2p_of_state<D, Shape, true, false>(system);
}

template <int D, class Shape>
void g2p_stress(DiscreteSystem<D, Shape>& system) {
  detail::g2p_of_state<D, Shape, false, true>(system);
}

// USL: both stages in one pass, N and dN at the start-of-step positions.
template <int D, class Shape>
void g2p_motion_and_stress(DiscreteSystem<D, Shape>& system) {
  detail::g2p_of_state<D, Shape, true, true>(system);
}

}  // namespace flowmpm
