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
    for (std::uint32_t p = first; p < last; ++p) {
      const Stencil<D, Shape, Force> s(grid, b.x[p], b.half_width);
      const double m = b.mass[p];
      const Vec<D> mv = m * b.v[p], mg = m * g;
      // APIC: N_Ip (x_I - x_p) on the same nodes, and m_p C_p.
      using Offsets = Stencil<D, Shape, true, StencilFactor::offset>;
      [[maybe_unused]] const auto offsets = [&] {
        if constexpr (Affine) return Offsets(grid, b.x[p], b.half_width);
        else return 0;
      }();
      [[maybe_unused]] double mC[D][D];
      if constexpr (Affine)
        for (int i = 0; i < D; ++i)
          for (int j = 0; j < D; ++j) mC[i][j] = m * b.affine[p][D * i + j];
      double Vsigma[D][D];
      if constexpr (Force) {
        const Voigt& sigma = b.stress[p];
        for (int i = 0; i < D; ++i)
          for (int j = 0; j < D; ++j) Vsigma[i][j] = b.volume[p] * sigma[voigt_slot(i, j)];
      }
      [[maybe_unused]] double VM = 0.0;
      if constexpr (Stiffness) VM = b.volume[p] * modulus[b.material];
      [[maybe_unused]] double hoop = 0.0, inv_r = 0.0;  // V sigma_tt / r, 1 / r
      if constexpr (Hoop) {
        inv_r = 1.0 / b.x[p][0];
        hoop = b.volume[p] * b.stress[p][2] * inv_r;
      }
      s.for_each_node_pair([&]<int Count>(int line, int k, std::size_t n) {
        const auto w = s.template pair_weights<Count>(line, k);
        const NodePair N = w.N;
        if constexpr (Momentum) {
          store_nodes<Count>(to_mass + n, load_nodes<Count>(to_mass + n) + N * m);
          for (int i = 0; i < D; ++i) {
            NodePair mom = N * mv[i];
            if constexpr (Affine) {
              const auto X = offsets.template pair_weights<Count>(line, k);
              for (int j = 0; j < D; ++j) mom += mC[i][j] * X.dN[j];
            }
            store_nodes<Count>(to_momentum[i] + n, load_nodes<Count>(to_momentum[i] + n) + mom);
          }
        }
        if constexpr (Force) {
          for (int i = 0; i < D; ++i) {
            NodePair f = N * mg[i];
            for (int j = 0; j < D; ++j) f -= Vsigma[i][j] * w.dN[j];
            if constexpr (Hoop)
              if (i == 0) f -= hoop * N;
            store_nodes<Count>(to_force[i] + n, load_nodes<Count>(to_force[i] + n) + f);
          }
          if constexpr (Stiffness) {
            NodePair dN2 = w.dN[0] * w.dN[0];
            for (int j = 1; j < D; ++j) dN2 += w.dN[j] * w.dN[j];
            if constexpr (Hoop) dN2 += (inv_r * inv_r) * (N * N);
            store_nodes<Count>(to_stiffness + n, load_nodes<Count>(to_stiffness + n) + VM * dN2);
          }
        }
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
