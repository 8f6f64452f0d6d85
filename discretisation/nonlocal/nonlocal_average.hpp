// Nonlocal averages for the models that ask for one
// (materials/nonlocal_model.hpp), in the integral form of
// [Pijaudier-Cabot 1987]:
//   avg_p = sum_q alpha_pq V_q s_q / sum_q alpha_pq V_q,
//   alpha_pq = exp(-r_pq^2 / (2 l^2)) for r_pq < 4 l, else 0,
// l the nonlocal length of p's model, s_q the source of particle q (0 for
// particles of models without one: they count in the volume only), V_q and
// r_pq the initial volumes and the distance between the initial positions
// (the models that ask are small-strain ones, and a particle keeps its
// neighbours whatever the motion). The Gaussian is the product of its 1D
// factors, so across a planar band that spans the window the average is the
// 1D one whatever the dimension and the particles per cell. Each particle
// gets the average without itself,
//   nonlocal_others = sum_{q != p} alpha_pq V_q s_q / sum_q alpha_pq V_q,
// and its own weight, nonlocal_self_weight = V_p / sum_q alpha_pq V_q, so
// that its model can solve for its own source within the step. The sums run
// serially in a fixed order (the same for any thread count); a step whose
// sources are all 0 costs one pass over the particles. Each source's
// neighbours and weights are found once and kept (the sources are the few
// softening particles, their neighbours those within 4 l).
#pragma once
#include <algorithm>
#include <cmath>
#include <vector>

#include "discretisation/discrete_system.hpp"
#include "discretisation/system_spec.hpp"

namespace flowmpm {

// Cut-off radius of the Gaussian weight, in nonlocal lengths: the weight is
// exp(-8) = 3.4e-4 there.
inline constexpr double nonlocal_cutoff = 4.0;

// Whether a model of a body of `spec` asks for nonlocal averages.
inline bool asks_nonlocal(const SystemSpec& spec) {
  return std::ranges::any_of(spec.bodies,
                             [&](const BodySpec& b) { return !b.rigid() && nonlocal_length(spec.materials[b.material].model) > 0.0; });
}

namespace detail {

// The initial volume of particle p of batch b (m^3; volumes change with the strain).
template <int D>
double initial_volume(const ParticleBatch<D>& b, std::size_t p, const std::vector<Material>& materials) {
  return b.mass[p] / density(materials[b.material]);
}

template <int D, class Shape>
double largest_nonlocal_length(const DiscreteSystem<D, Shape>& system) {
  double l = 0.0;
  for (const auto& b : system.batches)
    if (b.material >= 0) l = std::max(l, nonlocal_length(system.materials[b.material]));
  return l;
}

}  // namespace detail

// Set-up, after the particles are built and sorted, if a model asks for
// averages (else nothing is stored): every particle keeps its initial
// position, and each particle of a model that asks gets its weight and room
// for its start of step.
template <int D, class Shape>
void nonlocal_setup(DiscreteSystem<D, Shape>& system) {
  const double l_max = detail::largest_nonlocal_length(system);
  if (l_max <= 0.0) return;
  system.nonlocal.emplace();
  for (auto& b : system.batches) {
    if (b.x0.empty()) b.x0 = b.x;
    if (nonlocal_length(system.materials[b.material]) <= 0.0) continue;
    b.nonlocal_others.assign(b.size(), 0.0);
    b.nonlocal_self_weight.assign(b.size(), 0.0);
    b.step_start.states = b.states;
    b.step_start.stress.resize(b.size());
    b.step_start.strain.resize(b.size());
    b.step_start.volume.resize(b.size());
    b.step_start.L.resize(b.size());
  }
  system.nonlocal->bins = NonlocalBins<D>(system.batches, nonlocal_cutoff * l_max, system.sorts);
  for (auto& b : system.batches) {
    const double l = nonlocal_length(system.materials[b.material]);
    if (l <= 0.0) continue;
    const double cut2 = nonlocal_cutoff * nonlocal_cutoff * l * l;
    for (std::size_t p = 0; p < b.size(); ++p) {
      double sum = 0.0;
      system.nonlocal->bins.for_each_near(b.x0[p], [&](int qb, std::uint32_t q) {
        const auto& bq = system.batches[qb];
        const double r2 = (bq.x0[q] - b.x0[p]).squaredNorm();
        if (r2 < cut2) sum += std::exp(-0.5 * r2 / (l * l)) * detail::initial_volume(bq, q, system.materials);
      });
      b.nonlocal_self_weight[p] = detail::initial_volume(b, p, system.materials) / sum;
    }
  }
}

// The averages of the particles' current sources without the particle
// itself (nonlocal_others), per batch (empty for batches that ask for none).
template <int D, class Shape>
void nonlocal_average(DiscreteSystem<D, Shape>& system, std::vector<std::vector<double>>& average) {
  auto& bins = system.nonlocal->bins;
  auto& neighbours = system.nonlocal->neighbours;
  if (bins.sorts != system.sorts) {  // the particles were re-sorted
    bins = NonlocalBins<D>(system.batches, bins.size, system.sorts);
    neighbours.clear();
  }
  struct Source {
    int batch;
    std::uint32_t particle;
    double volume_source;  // V_q s_q
  };
  std::vector<Source> sources;
  average.resize(system.batches.size());
  for (int bi = 0; bi < static_cast<int>(system.batches.size()); ++bi) {
    const auto& b = system.batches[bi];
    average[bi].assign(b.nonlocal_others.size(), 0.0);
    std::visit(
        [&](const auto& m) {
          using M = std::decay_t<decltype(m)>;
          if constexpr (NonlocalModel<M>) {
            if (m.nonlocal_length() <= 0.0) return;
            const auto& states = std::get<StateArray<M>>(b.states);
            for (std::uint32_t p = 0; p < b.size(); ++p) {
              const double s = m.nonlocal_source(states[p]);
              if (s != 0.0) sources.push_back({bi, p, detail::initial_volume(b, p, system.materials) * s});
            }
          }
        },
        system.materials[b.material]);
  }
  if (sources.empty()) return;
  std::vector<double> length(system.batches.size());
  for (std::size_t bi = 0; bi < system.batches.size(); ++bi)
    length[bi] = nonlocal_length(system.materials[system.batches[bi].material]);
  for (const Source& s : sources) {
    // The source's neighbours and their weights, found once.
    auto [found, fresh] = neighbours.try_emplace(std::uint64_t{static_cast<std::uint32_t>(s.batch)} << 32 | s.particle);
    std::vector<NonlocalNeighbour>& near = found->second;
    if (fresh) {
      const Vec<D>& xq = system.batches[s.batch].x0[s.particle];
      bins.for_each_near(xq, [&](int pb, std::uint32_t p) {
        const auto& b = system.batches[pb];
        if (b.nonlocal_others.empty() || (pb == s.batch && p == s.particle)) return;
        const double l = length[pb];
        const double r2 = (b.x0[p] - xq).squaredNorm();
        if (r2 < nonlocal_cutoff * nonlocal_cutoff * l * l) near.push_back({pb, p, std::exp(-0.5 * r2 / (l * l))});
      });
    }
    for (const NonlocalNeighbour& n : near) average[n.batch][n.particle] += n.alpha * s.volume_source;
  }
  // Divided by the weight sum, V_p / self_weight.
  for (std::size_t bi = 0; bi < system.batches.size(); ++bi) {
    const auto& b = system.batches[bi];
    for (std::size_t p = 0; p < average[bi].size(); ++p)
      if (average[bi][p] != 0.0) average[bi][p] *= b.nonlocal_self_weight[p] / detail::initial_volume(b, p, system.materials);
  }
}

}  // namespace flowmpm
