// Loops over occupied blocks: by colour for scatters to the grid (blocks of
// one colour share no node, so they run in parallel without locks or
// atomics), or all at once for particle-only updates.
#pragma once
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "engine/model.hpp"

namespace flowmpm {

// f(batch, first, last, block): the particles [first, last) of `batch`
// in `block`, batches in their fixed order.
template <int D, class Shape, class F>
void for_each_block_segment(Model<D, Shape>& model, std::uint32_t block, F&& f) {
  for (auto& batch : model.batches) {
    const std::uint32_t first = batch.block_begin[block], last = batch.block_begin[block + 1];
    if (first < last) f(batch, first, last, block);
  }
}

// Scatter loop: colours in order, the blocks of one colour in parallel.
template <int D, class Shape, class F>
void scatter_by_colour(Model<D, Shape>& model, F&& f) {
  for (const auto& blocks : model.blocks.occupied_by_colour) {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, blocks.size(), 1),
                      [&](const tbb::blocked_range<std::size_t>& r) {
                        for (std::size_t i = r.begin(); i != r.end(); ++i)
                          for_each_block_segment(model, blocks[i], f);
                      });
  }
}

// Gather loop: every occupied block in parallel.
template <int D, class Shape, class F>
void gather_by_block(Model<D, Shape>& model, F&& f) {
  const auto& blocks = model.blocks.occupied;
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, blocks.size(), 1),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      for (std::size_t i = r.begin(); i != r.end(); ++i)
                        for_each_block_segment(model, blocks[i], f);
                    });
}

// Parallel loop over the slabs (last axis) of the grid's active node box:
// f(node_index, node_ijk).
template <int D, class F>
void for_each_active_node(const Grid<D>& grid, F&& f) {
  tbb::parallel_for(grid.active_lo[D - 1], grid.active_hi[D - 1] + 1,
                    [&](int slab) { grid.for_each_active_node_in_slab(slab, f); });
}

}  // namespace flowmpm
