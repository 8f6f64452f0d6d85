// Heat conduction and solvent diffusion on the grid: explicit, in the same
// particle-to-grid / nodal update / grid-to-particle pattern as the momentum
// ([NairnMPM], conduction and diffusion calculations). Heat,
// rho C dT/dt = div(k grad T), weak form with the particles as quadrature
// points and lumped capacities:
//   transport_p2g:    (mC)_I = sum_p N_Ip m_p C_p,
//                     P_I = T_I = sum_p N_Ip m_p C_p T_p / (mC)_I, then the
//                     prescribed T_I = T_b(t);
//   transport_flux:   grad T_p = sum_I T_I dN_Ip, and the heat flow into node I
//                     Q_I = -sum_p V_p (k_p grad T_p) . dN_Ip + sum_p N_Ip q_s A_p
//                     (k_p = R_p diag(k) R_p^T, the particle's material axes;
//                     q_s a surface flux through the face area A_p the particle
//                     carries; no flux elsewhere: insulated);
//   transport_update: T_I' = T_I + dt Q_I / (mC)_I, then the prescribed
//                     T_I' = T_b(t + dt), and the increment dT_I = T_I' - P_I;
//   transport_g2p:    T_p += sum_I N_Ip dT_I (the increment, as FLIP); the
//                     particle's step (its change since the last stress
//                     update, which g2p_stress takes and clears) grows by
//                     the same.
// Prescribed nodes (our choice, checked by the slab's convergence rate in
// tests/test_transport.cpp): there the increment is
//   dT_I = T_b(t + dt) - T_b(t) + (R_I - P_I),
// R_I = sum_p N_Ip m_p C_p (sum_J N_Jp T_J) / (mC)_I the nodal values mapped
// to the particles and back. Particles that carry the grid's field have
// R_I = P_I, and the node follows the prescribed change (as the mirror image
// of the particles beyond the face would make it); what the grid cannot see
// (the step of a face held at another value than the body starts at) is
// relaxed away. The increment T_b(t + dt) - P_I pins the one-sided map P_I
// to T_b, which on the particle lattice is 0.375 h dT/dx away from it:
// first order at the face; T_b(t + dt) - T_b(t) alone keeps the step
// forever. The rates each gives on the slab: docs/theory/transport.md.
// Solvent, rho dc/dt = div(rho D grad c) for a weight fraction c: the same
// with m_p for m_p C_p and m_p D (= V_p rho D) for V_p k, so that
// sum_p m_p c_p, the solvent mass, changes only through the boundaries.
// One pass carries both fields when the scene has both. The passes read the
// particles' positions, masses, volumes and material axes, which the
// momentum stages running beside them (engine/schemes.cpp) leave alone
// until the stress update, and write only the transport fields.
#pragma once
#include <array>
#include <type_traits>

#include "discretisation/grid/stencil.hpp"
#include "tasks/parallel_blocks.hpp"

namespace flowmpm {

namespace detail {

template <int Count>
[[gnu::always_inline]] inline void add_to_nodes(double* at_n, NodePair v) {
  store_nodes<Count>(at_n, load_nodes<Count>(at_n) + v);
}

// Sets the prescribed values at `time` on their nodes.
inline void apply_prescribed(const TransportField& field, std::vector<double>& value, double time) {
  for (const PrescribedValue& c : field.prescribed) {
    const double v = c.value(time);
    for (std::size_t n : c.nodes) value[n] = v;
  }
}

template <int D, class Shape, bool Heat, bool Solvent>
void transport_p2g(DiscreteSystem<D, Shape>& system) {
  auto& grid = system.grid;
  TransportNodes &heat = grid.heat, &solvent = grid.solvent;
  for_each_active_node(grid, [&](std::size_t n, const Index<D>&) {
    if constexpr (Heat) heat.capacity[n] = heat.value[n] = 0.0;
    if constexpr (Solvent) solvent.capacity[n] = solvent.value[n] = 0.0;
  });
  double *heat_capacity = heat.capacity.data(), *heat_value = heat.value.data();
  double *solvent_capacity = solvent.capacity.data(), *solvent_value = solvent.value.data();
  scatter_by_colour(system, [&](ParticleBatch<D>& b, std::uint32_t first, std::uint32_t last, std::uint32_t) {
    const double C = transport(system.materials[b.material]).heat_capacity;
    for (std::uint32_t p = first; p < last; ++p) {
      const Stencil<D, Shape, false> s(grid, b.x[p], b.half_width);
      const double m = b.mass[p], mC = m * C;
      const double mCT = Heat ? mC * b.temperature[p] : 0.0, mc = Solvent ? m * b.concentration[p] : 0.0;
      s.for_each_node_pair([&]<int Count>(int line, int k, std::size_t n) {
        const NodePair N = s.template pair_weights<Count>(line, k).N;
        if constexpr (Heat) {
          add_to_nodes<Count>(heat_capacity + n, N * mC);
          add_to_nodes<Count>(heat_value + n, N * mCT);
        }
        if constexpr (Solvent) {
          add_to_nodes<Count>(solvent_capacity + n, N * m);
          add_to_nodes<Count>(solvent_value + n, N * mc);
        }
      });
    }
  });
  // The nodal values; `change` keeps them as mapped, P_I, for transport_update.
  auto nodal_value = [](TransportNodes& f, std::size_t n) {
    f.value[n] = f.capacity[n] > 0.0 ? f.value[n] / f.capacity[n] : 0.0;
    f.change[n] = f.value[n];
  };
  for_each_active_node(grid, [&](std::size_t n, const Index<D>&) {
    if constexpr (Heat) nodal_value(heat, n);
    if constexpr (Solvent) nodal_value(solvent, n);
  });
  if constexpr (Heat) apply_prescribed(*system.heat, heat.value, system.t);
  if constexpr (Solvent) apply_prescribed(*system.solvent, solvent.value, system.t);
}

// k_p (heat) or D_p (solvent) in global axes, the D x D block of
// R diag(along_axes) R^T; a scalar times I for a model without axes.
template <int D, class Model>
[[gnu::always_inline]] inline Eigen::Matrix<double, D, D> in_global_axes(const Model& model,
                                                                          const typename Model::State& state,
                                                                          const Eigen::Vector3d& along_axes) {
  if constexpr (HasMaterialAxes<Model>) {
    const Eigen::Matrix3d R = model.material_axes(state).toRotationMatrix();
    return (R * along_axes.asDiagonal() * R.transpose()).template topLeftCorner<D, D>();
  } else {
    return along_axes[0] * Eigen::Matrix<double, D, D>::Identity();
  }
}

template <int D, class Shape, bool Heat, bool Solvent>
void transport_flux(DiscreteSystem<D, Shape>& system) {
  auto& grid = system.grid;
  TransportNodes &heat = grid.heat, &solvent = grid.solvent;
  for_each_active_node(grid, [&](std::size_t n, const Index<D>&) {
    if constexpr (Heat) heat.flow[n] = heat.reprojected[n] = 0.0;
    if constexpr (Solvent) solvent.flow[n] = solvent.reprojected[n] = 0.0;
  });
  double *heat_reprojected = heat.reprojected.data(), *solvent_reprojected = solvent.reprojected.data();
  const double *heat_value = heat.value.data(), *solvent_value = solvent.value.data();
  double *heat_flow = heat.flow.data(), *solvent_flow = solvent.flow.data();
  // The surface fluxes at t times the face area per particle (W, kg/s).
  std::vector<double> heat_through_face, solvent_through_face;
  for (const SurfaceFlux& f : system.surface_fluxes) {
    heat_through_face.push_back(f.heat ? (*f.heat)(system.t) * f.area : 0.0);
    solvent_through_face.push_back(f.solvent ? (*f.solvent)(system.t) * f.area : 0.0);
  }
  scatter_by_colour(system, [&](ParticleBatch<D>& b, std::uint32_t first, std::uint32_t last, std::uint32_t) {
    std::visit(
        [&](const auto& model) {
          using M = std::decay_t<decltype(model)>;
          const auto& states = std::get<StateArray<M>>(b.states);
          const typename M::State no_state{};
          const TransportProperties& properties = model.transport();
          const double C = properties.heat_capacity;
          for (std::uint32_t p = first; p < last; ++p) {
            const Stencil<D, Shape, true> s(grid, b.x[p], b.half_width);
            NodePair dT[D] = {}, dc[D] = {}, T_sum = {}, c_sum = {};
            s.for_each_node_pair([&]<int Count>(int line, int k, std::size_t n) {
              const auto w = s.template pair_weights<Count>(line, k);
              if constexpr (Heat) {
                const NodePair T = load_nodes<Count>(heat_value + n);
                T_sum += T * w.N;
                for (int d = 0; d < D; ++d) dT[d] += T * w.dN[d];
              }
              if constexpr (Solvent) {
                const NodePair c = load_nodes<Count>(solvent_value + n);
                c_sum += c * w.N;
                for (int d = 0; d < D; ++d) dc[d] += c * w.dN[d];
              }
            });
            const double mCT = Heat ? b.mass[p] * C * sum(T_sum) : 0.0;
            const double mc = Solvent ? b.mass[p] * sum(c_sum) : 0.0;
            const typename M::State& state = states.empty() ? no_state : states[p];
            // Q_I += a . dN_I + N_I s: a = -V k grad T (heat), -m D grad c (solvent);
            // R_I += N_I m C (sum_J N_J T_J), N_I m (sum_J N_J c_J).
            Vec<D> a_heat = Vec<D>::Zero(), a_solvent = Vec<D>::Zero();
            double s_heat = 0.0, s_solvent = 0.0;
            if constexpr (Heat) {
              Vec<D> grad;
              for (int d = 0; d < D; ++d) grad[d] = sum(dT[d]);
              a_heat = -b.volume[p] * (in_global_axes<D>(model, state, properties.conductivity) * grad);
            }
            if constexpr (Solvent) {
              Vec<D> grad;
              for (int d = 0; d < D; ++d) grad[d] = sum(dc[d]);
              a_solvent = -b.mass[p] * (in_global_axes<D>(model, state, properties.diffusivity) * grad);
            }
            if (!b.flux_faces.empty() && b.flux_faces[p] != 0) {
              for (int f = 0; f < 6; ++f) {
                if (!(b.flux_faces[p] & (1u << f))) continue;
                // Axisymmetric: per radian, the face's area times its radius
                // (a face normal to r sits half a particle from its centre).
                double r = 1.0;
                if (system.stress_state == StressState::axisymmetric)
                  r = b.x[p][0] + (f / 2 == 0 ? (f % 2 ? 1.0 : -1.0) * b.half_width[0] * grid.h[0] : 0.0);
                s_heat += r * heat_through_face[b.surface_flux[f]];
                s_solvent += r * solvent_through_face[b.surface_flux[f]];
              }
            }
            s.for_each_node_pair([&]<int Count>(int line, int k, std::size_t n) {
              const auto w = s.template pair_weights<Count>(line, k);
              if constexpr (Heat) {
                NodePair q = w.N * s_heat;
                for (int d = 0; d < D; ++d) q += a_heat[d] * w.dN[d];
                add_to_nodes<Count>(heat_flow + n, q);
                add_to_nodes<Count>(heat_reprojected + n, w.N * mCT);
              }
              if constexpr (Solvent) {
                NodePair q = w.N * s_solvent;
                for (int d = 0; d < D; ++d) q += a_solvent[d] * w.dN[d];
                add_to_nodes<Count>(solvent_flow + n, q);
                add_to_nodes<Count>(solvent_reprojected + n, w.N * mc);
              }
            });
          }
        },
        system.materials[b.material]);
  });
}

template <int D, class Shape, bool Heat, bool Solvent>
void transport_update(DiscreteSystem<D, Shape>& system) {
  auto& grid = system.grid;
  const double dt = system.dt;
  auto advance = [dt](TransportNodes& f, double threshold, std::size_t n) {
    if (f.capacity[n] > threshold) f.value[n] += dt * f.flow[n] / f.capacity[n];
  };
  for_each_active_node(grid, [&](std::size_t n, const Index<D>&) {
    if constexpr (Heat) advance(grid.heat, system.heat->capacity_threshold, n);
    if constexpr (Solvent) advance(grid.solvent, system.solvent->capacity_threshold, n);
  });
  // At a prescribed node the increment becomes u_b(t + dt) - u_b(t) + R_I - P_I
  // (see the top of this file): `change` holds P_I, it takes u_b(t) - R_I.
  auto prescribed_start = [&](const TransportField& field, TransportNodes& f) {
    for (const PrescribedValue& c : field.prescribed) {
      const double start = c.value(system.t);
      for (std::size_t n : c.nodes)
        if (f.capacity[n] > 0.0) f.change[n] += start - f.reprojected[n] / f.capacity[n];
    }
  };
  if constexpr (Heat) prescribed_start(*system.heat, grid.heat);
  if constexpr (Solvent) prescribed_start(*system.solvent, grid.solvent);
  if constexpr (Heat) apply_prescribed(*system.heat, grid.heat.value, system.t + dt);
  if constexpr (Solvent) apply_prescribed(*system.solvent, grid.solvent.value, system.t + dt);
  for_each_active_node(grid, [&](std::size_t n, const Index<D>&) {
    if constexpr (Heat) grid.heat.change[n] = grid.heat.value[n] - grid.heat.change[n];
    if constexpr (Solvent) grid.solvent.change[n] = grid.solvent.value[n] - grid.solvent.change[n];
  });
}

template <int D, class Shape, bool Heat, bool Solvent>
void transport_g2p(DiscreteSystem<D, Shape>& system) {
  const auto& grid = system.grid;
  const double *heat_change = grid.heat.change.data(), *solvent_change = grid.solvent.change.data();
  gather_by_block(system, [&](ParticleBatch<D>& b, std::uint32_t first, std::uint32_t last, std::uint32_t) {
    for (std::uint32_t p = first; p < last; ++p) {
      const Stencil<D, Shape, false> s(grid, b.x[p], b.half_width);
      NodePair dT = {}, dc = {};
      s.for_each_node_pair([&]<int Count>(int line, int k, std::size_t n) {
        const NodePair N = s.template pair_weights<Count>(line, k).N;
        if constexpr (Heat) dT += N * load_nodes<Count>(heat_change + n);
        if constexpr (Solvent) dc += N * load_nodes<Count>(solvent_change + n);
      });
      if constexpr (Heat) {
        b.temperature_step[p] += sum(dT);
        b.temperature[p] += sum(dT);
      }
      if constexpr (Solvent) {
        b.concentration_step[p] += sum(dc);
        b.concentration[p] += sum(dc);
      }
    }
  });
}

// Calls f.template operator()<Heat, Solvent>() for the fields the scene
// carries: one dispatch per pass.
template <int D, class Shape, class F>
void with_transported_fields(const DiscreteSystem<D, Shape>& system, F&& f) {
  if (system.heat && system.solvent) {
    f.template operator()<true, true>();
  } else if (system.heat) {
    f.template operator()<true, false>();
  } else if (system.solvent) {
    f.template operator()<false, true>();
  }
}

}  // namespace detail

template <int D, class Shape>
void transport_p2g(DiscreteSystem<D, Shape>& system) {
  detail::with_transported_fields(system, [&]<bool H, bool S>() { detail::transport_p2g<D, Shape, H, S>(system); });
}

template <int D, class Shape>
void transport_flux(DiscreteSystem<D, Shape>& system) {
  detail::with_transported_fields(system, [&]<bool H, bool S>() { detail::transport_flux<D, Shape, H, S>(system); });
}

template <int D, class Shape>
void transport_update(DiscreteSystem<D, Shape>& system) {
  detail::with_transported_fields(system,
                                  [&]<bool H, bool S>() { detail::transport_update<D, Shape, H, S>(system); });
}

template <int D, class Shape>
void transport_g2p(DiscreteSystem<D, Shape>& system) {
  detail::with_transported_fields(system, [&]<bool H, bool S>() { detail::transport_g2p<D, Shape, H, S>(system); });
}

}  // namespace flowmpm
