// Loops over occupied blocks: by colour for scatters to the grid (blocks of
// one colour share no node, so they run in parallel without locks or
// atomics), or all at once for particle-only updates.
#pragma once
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>

#include "discretisation/discrete_system.hpp"
#include "discretisation/grid/stencil.hpp"

namespace flowmpm {

// The least work worth a task of its own, in particle-node pairs (a
// particle's stencil nodes, or grid nodes): below it, waking a second
// thread costs more than the work. A small 1D bar ran slower on 2 threads
// than on 1 when every loop was split; a 3D block of 10^4 particles (8
// nodes each) gains from 2 threads (measured: docs/performance.md).
constexpr std::size_t min_pairs_per_task = 2048;

// Blocks per task for the particle loops: enough for min_pairs_per_task at
// the mean occupancy.
template <int D, class Shape>
std::size_t blocks_per_task(const DiscreteSystem<D, Shape>& system) {
  constexpr std::size_t nodes_per_particle = Stencil<D, Shape, false>::size;
  const std::size_t blocks = std::max<std::size_t>(1, system.blocks.occupied.size());
  const std::size_t pairs_per_block = std::max<std::size_t>(1, system.particle_count() * nodes_per_particle / blocks);
  return std::max<std::size_t>(1, min_pairs_per_task / pairs_per_block);
}

// f(batch, first, last, block): the particles [first, last) of `batch`
// in `block`, batches in their fixed order.
template <int D, class Shape, class F>
void for_each_block_segment(DiscreteSystem<D, Shape>& system, std::uint32_t block, F&& f) {
  for (auto& batch : system.batches) {
    const std::uint32_t first = batch.block_begin[block], last = batch.block_begin[block + 1];
    if (first < last) f(batch, first, last, block);
  }
}

// Scatter loop: colours in order, the blocks of one colour in parallel.
template <int D, class Shape, class F>
void scatter_by_colour(DiscreteSystem<D, Shape>& system, F&& f) {
  const std::size_t grain = blocks_per_task(system);
  for (const auto& blocks : system.blocks.occupied_by_colour) {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, blocks.size(), grain),
                      [&](const tbb::blocked_range<std::size_t>& r) {
                        for (std::size_t i = r.begin(); i != r.end(); ++i)
                          for_each_block_segment(system, blocks[i], f);
                      });
  }
}

// Gather loop: every occupied block in parallel.
template <int D, class Shape, class F>
void gather_by_block(DiscreteSystem<D, Shape>& system, F&& f) {
  const auto& blocks = system.blocks.occupied;
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, blocks.size(), blocks_per_task(system)),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      for (std::size_t i = r.begin(); i != r.end(); ++i)
                        for_each_block_segment(system, blocks[i], f);
                    });
}

// Parallel loop over the slabs (last axis) of the grid's active node box:
// f(node_index, node_ijk).
template <int D, class F>
void for_each_active_node(const Grid<D>& grid, F&& f) {
  std::size_t nodes_per_slab = 1;
  for (int d = 0; d < D - 1; ++d) nodes_per_slab *= static_cast<std::size_t>(grid.active_hi[d] - grid.active_lo[d] + 1);
  const int grain = static_cast<int>(std::max<std::size_t>(1, min_pairs_per_task / nodes_per_slab));
  tbb::parallel_for(tbb::blocked_range<int>(grid.active_lo[D - 1], grid.active_hi[D - 1] + 1, grain),
                    [&](const tbb::blocked_range<int>& slabs) {
                      for (int slab = slabs.begin(); slab != slabs.end(); ++slab)
                        grid.for_each_active_node_in_slab(slab, f);
                    });
}

}  // namespace flowmpm
