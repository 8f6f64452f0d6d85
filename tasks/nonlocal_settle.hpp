// nonlocal_settle: the step's nonlocal averages made consistent with its end
// (discretisation/nonlocal/nonlocal_average.hpp), wired after g2p_stress only in a
// scene whose models ask for averages. g2p_stress updated each such particle
// with the average at the end of the last step and kept its start of step
// (tasks/g2p.hpp). Here the average of the new sources is taken; every
// particle whose average moved, and whose update used it, is put back to
// its start and updated again with the same velocity gradient and the new
// average; and so on until no
// average moves by more than nonlocal_tolerance of the largest, or
// nonlocal_passes passes (a softening band wider than its model allows may
// not settle: then the last pass stands and the step is counted in
// DiscreteSystem::nonlocal.unsettled_steps). Taking the neighbours' average
// from the last step instead lets a band that breaks in a few steps
// over-dissipate (docs/theory/materials.md, strain_softening). Serial, in a fixed
// order: the same for any thread count.
#pragma once
#include <algorithm>
#include <cmath>
#include <vector>

#include "discretisation/nonlocal/nonlocal_average.hpp"
#include "tasks/g2p.hpp"

namespace flowmpm {

inline constexpr double nonlocal_tolerance = 1e-9;
inline constexpr int nonlocal_passes = 50;

template <int D, class Shape>
void nonlocal_settle(DiscreteSystem<D, Shape>& system) {
  std::vector<std::vector<double>> average;
  for (int pass = 0; pass < nonlocal_passes; ++pass) {
    nonlocal_average(system, average);
    double largest = 0.0, moved = 0.0;
    for (std::size_t bi = 0; bi < system.batches.size(); ++bi) {
      const auto& used = system.batches[bi].nonlocal_others;
      for (std::size_t p = 0; p < used.size(); ++p) {
        largest = std::max(largest, std::abs(average[bi][p]));
        moved = std::max(moved, std::abs(average[bi][p] - used[p]));
      }
    }
    if (moved <= nonlocal_tolerance * largest) return;
    const double tolerance = nonlocal_tolerance * largest;
    for (std::size_t bi = 0; bi < system.batches.size(); ++bi) {
      auto& b = system.batches[bi];
      if (b.nonlocal_others.empty()) continue;
      std::visit(
          [&](const auto& model) {
            using M = std::decay_t<decltype(model)>;
            if constexpr (NonlocalModel<M>) {
              auto& states = std::get<StateArray<M>>(b.states);
              const auto& kept = b.step_start;
              const auto& kept_states = std::get<StateArray<M>>(kept.states);
              with_hoop(system, [&]<bool Hoop>() {
                detail::with_material_update<Hoop>(system, b, model, [&](auto&& update) {
                  for (std::size_t p = 0; p < b.size(); ++p) {
                    if (!(std::abs(average[bi][p] - b.nonlocal_others[p]) > tolerance)) continue;
                    b.nonlocal_others[p] = average[bi][p];
                    if (!model.nonlocal_read(states[p])) continue;  // the same update again: nothing to redo
                    states[p] = kept_states[p];
                    b.stress[p] = kept.stress[p];
                    b.strain[p] = kept.strain[p];
                    b.volume[p] = kept.volume[p];
                    double L[D][D];
                    for (int i = 0; i < D; ++i)
                      for (int j = 0; j < D; ++j) L[i][j] = kept.L[p][D * i + j];
                    update(p, L, kept.L[p][D * D]);  // (keeps the same start again)
                  }
                });
              });
            }
          },
          system.materials[b.material]);
    }
  }
  ++system.nonlocal->unsettled_steps;
}

}  // namespace flowmpm
