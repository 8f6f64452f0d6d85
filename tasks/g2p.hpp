// Grid-to-particle stages (DESIGN.md).
// g2p_motion: v_p <- a (v_p + sum_I N_Ip dv_I) + (1 - a) sum_I N_Ip v_I
//             (a = 1 FLIP, a = 0 PIC), x_p <- x_p + dt sum_I N_Ip v_I,
//             with v_I the velocity after grid_integrate.
// g2p_stress: L_p = sum_I v_I (x) dN_Ip, d eps = sym(L_p) dt, the material
//             update sigma(d eps), eps += d eps, V_p *= 1 + tr(d eps).
// Stages after g2p_motion in the same step (USL stress, MUSL remap)
// evaluate N and dN at the updated positions.
#pragma once
#include <atomic>
#include <cmath>

#include "engine/particle_sort.hpp"
#include "engine/stencil.hpp"
#include "tasks/parallel_blocks.hpp"

namespace flowmpm {

namespace detail {

// Cells a particle in cell c lies outside block `block` (0 inside).
template <int D, class Shape>
int drift_from_block(const Index<D>& c, const Index<D>& block) {
  constexpr int B = BlockLayout<D, Shape>::block_cells;
  int drift = 0;
  for (int d = 0; d < D; ++d) {
    drift = std::max(drift, block[d] * B - c[d]);
    drift = std::max(drift, c[d] - (block[d] * B + B - 1));
  }
  return drift;
}

}  // namespace detail

template <int D, class Shape>
void g2p_motion(Model<D, Shape>& model) {
  using Layout = BlockLayout<D, Shape>;
  const auto& grid = model.grid;
  const double a = model.flip_fraction, dt = model.dt;
  // Largest particle speed of the step, for the time step and the guard:
  // per block, then combined (max is exact, so any order gives the same).
  std::atomic<double> max_speed_sq{0.0};
  gather_by_block(model, [&](ParticleBatch<D>& b, std::uint32_t first, std::uint32_t last,
                             std::uint32_t block) {
    const Index<D> bc = model.blocks.block_coords(block);
    double block_max_sq = 0.0;
    const Vec<D>* velocity = grid.velocity.data();
    const Vec<D>* velocity_change = grid.velocity_change.data();
    for (std::uint32_t p = first; p < last; ++p) {
      const Stencil<D, Shape, false> s(grid, b.x[p], b.half_width);
      Vec<D> v_grid = Vec<D>::Zero(), dv = Vec<D>::Zero();
      for (int k = 0; k < s.size; ++k) {
        v_grid += s.N[k] * velocity[s.node[k]];
        dv += s.N[k] * velocity_change[s.node[k]];
      }
      const Vec<D> x_new = b.x[p] + dt * v_grid;
      // A particle must stay where its stencil has nodes and may cross at
      // most one cell per step; otherwise it is not moved and the step fails.
      // (The range is checked on the grid coordinate before it becomes an int.)
      bool inside = true, one_cell = true;
      for (int d = 0; d < D; ++d) {
        const double g_new = (x_new[d] - grid.origin[d]) * grid.inv_h[d];
        inside = inside && g_new >= Shape::reach_below && g_new < grid.cells[d] - Shape::reach_above + 1;
      }
      const Index<D> c_new = inside ? grid.cell_of(x_new) : Index<D>{};
      if (inside) {
        const Index<D> c_old = grid.cell_of(b.x[p]);
        for (int d = 0; d < D; ++d) one_cell = one_cell && std::abs(c_new[d] - c_old[d]) <= 1;
      }
      const Vec<D> v_new = a * (b.v[p] + dv) + (1.0 - a) * v_grid;
      if (!inside || !one_cell || !v_new.allFinite()) {
        model.flags.fail("a particle at " + position_text<D>(b.x[p]) + " would move to " + position_text<D>(x_new) +
                         (!v_new.allFinite() ? ", its velocity not finite"
                          : !inside          ? ", outside the grid"
                                             : ", more than one cell in one step"));
        continue;
      }
      b.v[p] = v_new;
      b.x[p] = x_new;
      block_max_sq = std::max(block_max_sq, v_new.squaredNorm());
      if (detail::drift_from_block<D, Shape>(c_new, bc) >= Layout::drift_limit) {
        model.flags.resort_needed.store(true, std::memory_order_relaxed);
      }
    }
    double seen = max_speed_sq.load(std::memory_order_relaxed);
    while (block_max_sq > seen && !max_speed_sq.compare_exchange_weak(seen, block_max_sq)) {
    }
  });
  model.max_speed_sq = max_speed_sq.load();
}

template <int D, class Shape, StressState S, class MaterialModel>
void update_stress(Model<D, Shape>& model, ParticleBatch<D>& b, const MaterialModel& material,
                   StateArray<MaterialModel>& states) {
  const auto& grid = model.grid;
  const Vec<D>* velocity = grid.velocity.data();
  const double dt = model.dt;
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, b.size(), 1024),
                    [&](const tbb::blocked_range<std::size_t>& r) {
    typename MaterialModel::State no_state{};
    for (std::size_t p = r.begin(); p != r.end(); ++p) {
      const Stencil<D, Shape> s(grid, b.x[p], b.half_width);
      double L[D][D] = {};  // velocity gradient, in registers
      for (int k = 0; k < s.size; ++k) {
        const Vec<D>& v = velocity[s.node[k]];
        for (int i = 0; i < D; ++i)
          for (int j = 0; j < D; ++j) L[i][j] += v[i] * s.dN[k][j];
      }
      Voigt deps{};
      for (int i = 0; i < D; ++i)
        for (int j = i; j < D; ++j) deps[voigt_slot(i, j)] = 0.5 * (L[i][j] + L[j][i]) * dt;
      MaterialInput input;
      input.t = model.t + dt;
      input.dt = dt;
      input.length = b.particle_length;
      for (int i = 0; i < D; ++i)
        for (int j = 0; j < D; ++j) input.dL(i, j) = L[i][j] * dt;
      auto& state = states.empty() ? no_state : states[p];
      material.template update<S>(state, b.stress[p], deps, input);
      if (!std::isfinite(b.stress[p][0] + b.stress[p][1] + b.stress[p][2] + b.stress[p][3] + b.stress[p][4] +
                         b.stress[p][5])) {
        model.flags.fail("a particle at " + position_text<D>(b.x[p]) + ": its stress is not finite");
      }
      for (int i = 0; i < 6; ++i) b.strain[p][i] += deps[i];
      b.volume[p] *= 1.0 + deps[0] + deps[1] + deps[2];
    }
  });
}

template <int D, class Shape>
void g2p_stress(Model<D, Shape>& model) {
  for (auto& batch : model.batches) {
    // One dispatch on the material per batch, none per particle.
    std::visit(
        [&](const auto& material) {
          using M = std::decay_t<decltype(material)>;
          auto& states = std::get<StateArray<M>>(batch.states);
          if constexpr (D == 3) {
            update_stress<D, Shape, StressState::three_d>(model, batch, material, states);
          } else if constexpr (D == 1) {
            update_stress<D, Shape, StressState::uniaxial_stress>(model, batch, material, states);
          } else if (model.stress_state == StressState::plane_stress) {
            update_stress<D, Shape, StressState::plane_stress>(model, batch, material, states);
          } else {
            update_stress<D, Shape, StressState::plane_strain>(model, batch, material, states);
          }
        },
        model.materials[batch.material]);
  }
}

}  // namespace flowmpm
