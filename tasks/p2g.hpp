// Particle-to-grid stages (docs/theory/step.md): p2g_momentum maps mass and momentum,
// p2g_force the internal and body forces, to the nodes:
//   m_I = sum_p N_Ip m_p,  p_I = sum_p N_Ip m_p v_p
//   (APIC: p_I = sum_p N_Ip m_p (v_p + C_p (x_I - x_p)) [Jiang 2015],
//   C_p = B_p D_p^-1 the particle's affine velocity; docs/theory/transfers.md),
//   f_I = sum_p ( -V_p sigma_p . dN_Ip + N_Ip m_p g_p ),
// g_p gravity plus the body force of the particle's body (loads, at the
// start of the step), and with linear shape functions under USL the nodal stiffness
//   k_I = sum_p V_p M_p |dN_Ip|^2  (M the P-wave modulus; tasks/grid_update.hpp held_node).
// In 1D and 2D only the in-plane block of sigma enters the force.
// Axisymmetric (x = r, per radian, V_p = r_p A_p): the hoop stress adds
//   f_I,r -= V_p sigma_tt N_Ip / r_p
// ([Sulsky 1996]; the divergence of the stress in cylindrical coordinates),
// and to the nodal stiffness V_p M_p (N_Ip / r_p)^2.
// USL and MUSL map both from the same particle state, in one pass.
#pragma once
#include "discretisation/grid/stencil.hpp"
#include "tasks/parallel_blocks.hpp"

namespace flowmpm {

namespace detail {

// Each batch's acceleration: gravity plus its body's body forces at t.
template <int D, class Shape>
void set_accelerations(DiscreteSystem<D, Shape>& system) {
  for (auto& b : system.batches) b.acceleration = system.gravity;
  for (const BodyForce& f : system.loads.body) {
    for (int d = 0; d < D; ++d)
      if (f.acceleration[d]) system.batches[f.batch].acceleration[d] += (*f.acceleration[d])(system.t);
  }
}

// One pass over the particles: p2g_momentum, p2g_force or both, from one
// stencil per particle. Each node sums its particles in the same order
// whichever is mapped, so the results do not depend on the grouping.
// `Stiffness`: also the nodal stiffness of held_node (tasks/grid_update.hpp).
// `Affine`: APIC's momentum, with the particles' affine velocities.
// `Hoop`: axisymmetric, the hoop term of the force.
template <int D, class Shape, bool Momentum, bool Force, bool Stiffness = false, bool Affine = false, bool Hoop = false>
void p2g(DiscreteSystem<D, Shape>& system) {
  auto& grid = system.grid;
  for (int k = 0; k < system.field_count(); ++k) {
    NodalField<D>& field = system.field(k);
    for_each_active_node(grid, [&](std::size_t n, const Index<D>&) {
      if constexpr (Momentum) field.mass[n] = 0.0;
      for (int d = 0; d < D; ++d) {
        if constexpr (Momentum) field.momentum[d][n] = 0.0;
        if constexpr (Force) field.force[d][n] = 0.0;
      }
      if constexpr (Stiffness) field.stiffness[n] = 0.0;
    });
  }
  if constexpr (Force) set_accelerations(system);
  // P-wave modulus rho c^2 of each material, for the nodal stiffness.
  std::vector<double> modulus;
  if constexpr (Stiffness)
    for (const Material& m : system.materials) modulus.push_back(density(m) * wave_speed(m) * wave_speed(m));
  scatter_by_colour(system, [&](ParticleBatch<D>& b, std::uint32_t first, std::uint32_t last, std::uint32_t) {
    // A rigid body's particles map only their volume (tasks/contact.hpp).
    if (system.is_rigid(b)) return;
    // The nodal arrays of the batch's field as locals of this task:
    // store_nodes writes through memcpy, which may alias any memory, so
    // pointers read through the lambda's captures were loaded again at
    // every node pair (about 20 instructions per particle-step with linear
    // shape functions in 3D).
    NodalField<D>& field = system.field(b.field);
    double* const to_mass = field.mass.data();
    double* const to_stiffness = field.stiffness.data();
    double* to_momentum[D];
    double* to_force[D];
    for (int d = 0; d < D; ++d) {
      to_momentum[d] = field.momentum[d].data();
      to_force[d] = field.force[d].data();
    }
    const Vec<D> g = b.acceleration;
    using OneStencil = Stencil<D, Shape, Force>;
    using Offsets = Stencil<D, Shape, true, StencilFactor::offset>;
    // The particles in runs of up to run_length that share their stencil's
    // nodes (particles of one cell, in their sorted order): each node of the
    // run is loaded once, takes its particles' terms one after another in
    // particle order (the same sums, rounded the same, as one particle at a
    // time) and is stored once, instead of a load and a store per particle
    // whose next particle waits on it. Only linear shape functions, whose
    // stencil is the particle's cell: a quadratic B-spline's first node
    // depends on which half of the cell a particle is in, so runs are rare
    // and looking for them cost 0.73 of its rate (the other shape functions
    // were not measured with runs). APIC (its offset stencil) maps one
    // particle at a time.
    // The stencil of the particle that ended a run (another cell's) is
    // the next run's first: s[run_length] carries it over.
    constexpr int run_length = Shape::support == 2 && !Affine ? 8 : 1;
    OneStencil s[run_length + 1];
    bool next_known = false;
    for (std::uint32_t first_in_run = first, count; first_in_run < last; first_in_run += count) {
      s[0] = next_known ? s[run_length] : OneStencil(grid, b.x[first_in_run], b.half_width);
      next_known = false;
      count = 1;
      if constexpr (run_length > 1) {
        while (count < run_length && first_in_run + count < last) {
          s[count] = OneStencil(grid, b.x[first_in_run + count], b.half_width);
          if (s[count].line_node[0] != s[0].line_node[0]) {
            s[run_length] = s[count];
            next_known = true;
            break;
          }
          ++count;
        }
      }
      // Each particle's factors.
      double m[run_length], mv[run_length][D], mg[run_length][D];
      [[maybe_unused]] double Vsigma[run_length][D][D], VM[run_length], hoop[run_length], inv_r[run_length];
      for (std::uint32_t q = 0; q < count; ++q) {
        const std::uint32_t p = first_in_run + q;
        m[q] = b.mass[p];
        for (int i = 0; i < D; ++i) {
          mv[q][i] = m[q] * b.v[p][i];
          mg[q][i] = m[q] * g[i];
        }
        if constexpr (Force) {
          const Voigt& sigma = b.stress[p];
          for (int i = 0; i < D; ++i)
            for (int j = 0; j < D; ++j) Vsigma[q][i][j] = b.volume[p] * sigma[voigt_slot(i, j)];
        }
        if constexpr (Stiffness) VM[q] = b.volume[p] * modulus[b.material];
        if constexpr (Hoop) {  // V sigma_tt / r, 1 / r
          inv_r[q] = 1.0 / b.x[p][0];
          hoop[q] = b.volume[p] * b.stress[p][2] * inv_r[q];
        }
      }
      // APIC: N_Ip (x_I - x_p) on the same nodes, and m_p C_p (a run of one).
      [[maybe_unused]] const auto offsets = [&] {
        if constexpr (Affine) return Offsets(grid, b.x[first_in_run], b.half_width);
        else return 0;
      }();
      [[maybe_unused]] double mC[D][D];
      if constexpr (Affine)
        for (int i = 0; i < D; ++i)
          for (int j = 0; j < D; ++j) mC[i][j] = m[0] * b.affine[first_in_run][D * i + j];
      s[0].for_each_node_pair([&]<int Count>(int line, int k, std::size_t n) __attribute__((always_inline)) {
        NodePair mass = {}, momentum[D] = {}, force[D] = {}, stiffness = {};
        if constexpr (Momentum) {
          mass = load_nodes<Count>(to_mass + n);
          for (int i = 0; i < D; ++i) momentum[i] = load_nodes<Count>(to_momentum[i] + n);
        }
        if constexpr (Force)
          for (int i = 0; i < D; ++i) force[i] = load_nodes<Count>(to_force[i] + n);
        if constexpr (Stiffness) stiffness = load_nodes<Count>(to_stiffness + n);
        for (std::uint32_t q = 0; q < count; ++q) {
          const auto w = s[q].template pair_weights<Count>(line, k);
          const NodePair N = w.N;
          if constexpr (Momentum) {
            mass = mass + N * m[q];
            for (int i = 0; i < D; ++i) {
              NodePair mom = N * mv[q][i];
              if constexpr (Affine) {
                const auto X = offsets.template pair_weights<Count>(line, k);
                for (int j = 0; j < D; ++j) mom += mC[i][j] * X.dN[j];
              }
              momentum[i] = momentum[i] + mom;
            }
          }
          if constexpr (Force) {
            for (int i = 0; i < D; ++i) {
              NodePair f = N * mg[q][i];
              for (int j = 0; j < D; ++j) f -= Vsigma[q][i][j] * w.dN[j];
              if constexpr (Hoop)
                if (i == 0) f -= hoop[q] * N;
              force[i] = force[i] + f;
            }
            if constexpr (Stiffness) {
              NodePair dN2 = w.dN[0] * w.dN[0];
              for (int j = 1; j < D; ++j) dN2 += w.dN[j] * w.dN[j];
              if constexpr (Hoop) dN2 += (inv_r[q] * inv_r[q]) * (N * N);
              stiffness = stiffness + VM[q] * dN2;
            }
          }
        }
        if constexpr (Momentum) {
          store_nodes<Count>(to_mass + n, mass);
          for (int i = 0; i < D; ++i) store_nodes<Count>(to_momentum[i] + n, momentum[i]);
        }
        if constexpr (Force)
          for (int i = 0; i < D; ++i) store_nodes<Count>(to_force[i] + n, force[i]);
        if constexpr (Stiffness) store_nodes<Count>(to_stiffness + n, stiffness);
      });
    }
  });
}

// The momentum pass, APIC's where the scene uses it.
template <int D, class Shape, bool Force, bool Stiffness, bool Hoop = false>
void p2g_with_momentum(DiscreteSystem<D, Shape>& system) {
  if (system.velocity_update == VelocityUpdate::apic) {
    p2g<D, Shape, true, Force, Stiffness, true, Hoop>(system);
  } else {
    p2g<D, Shape, true, Force, Stiffness, false, Hoop>(system);
  }
}

// The force pass, with the nodal stiffness where the grid keeps it (USL
// with linear shape functions), and the hoop term in axisymmetric.
template <int D, class Shape, bool Momentum>
void p2g_with_force(DiscreteSystem<D, Shape>& system) {
  with_hoop(system, [&]<bool Hoop>() {
    constexpr bool jumps = Shape::gradient_jumps;
    if (jumps && !system.grid.stiffness.empty()) {  // every field has it then
      if constexpr (Momentum) p2g_with_momentum<D, Shape, true, jumps, Hoop>(system);
      else p2g<D, Shape, false, true, jumps, false, Hoop>(system);
    } else {
      if constexpr (Momentum) p2g_with_momentum<D, Shape, true, false, Hoop>(system);
      else p2g<D, Shape, false, true, false, false, Hoop>(system);
    }
  });
}

}  // namespace detail

template <int D, class Shape>
void p2g_momentum(DiscreteSystem<D, Shape>& system) {
  detail::p2g_with_momentum<D, Shape, false, false>(system);
}

template <int D, class Shape>
void p2g_force(DiscreteSystem<D, Shape>& system) {
  detail::p2g_with_force<D, Shape, false>(system);
}

template <int D, class Shape>
void p2g_momentum_and_force(DiscreteSystem<D, Shape>& system) {
  detail::p2g_with_force<D, Shape, true>(system);
}

}  // namespace flowmpm
