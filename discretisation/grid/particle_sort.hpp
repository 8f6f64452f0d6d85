// Sorting particles by block (and by cell inside a block) with a stable
// counting sort, so that a block's particles are contiguous and in a fixed
// order; then the occupied blocks per colour and the active node box.
#pragma once
#include <algorithm>
#include <numeric>

#include <tbb/parallel_for.h>

#include "discretisation/discrete_system.hpp"

namespace flowmpm {

namespace detail {

template <class T>
void permute(std::vector<T>& field, const std::vector<std::uint32_t>& order) {
  if (field.empty()) return;
  std::vector<T> sorted(field.size());
  tbb::parallel_for(std::size_t{0}, order.size(), [&](std::size_t i) { sorted[i] = field[order[i]]; });
  field.swap(sorted);
}

// Loaded faces follow their particles through a sort of batch `batch`
// (the particle at index order[i] moves to i).
template <int D>
void renumber_loaded_faces(std::vector<SurfaceLoad<D>>& loads, int batch, const std::vector<std::uint32_t>& order) {
  std::vector<std::uint32_t> moved_to;
  for (SurfaceLoad<D>& load : loads) {
    if (load.batch != batch) continue;
    if (moved_to.empty()) {
      moved_to.resize(order.size());
      for (std::uint32_t i = 0; i < order.size(); ++i) moved_to[order[i]] = i;
    }
    for (LoadedFace<D>& face : load.faces) face.particle = moved_to[face.particle];
  }
}

}  // namespace detail

template <int D, class Shape>
void sort_particles(DiscreteSystem<D, Shape>& system) {
  using Layout = BlockLayout<D, Shape>;
  auto& layout = system.blocks;
  const auto& grid = system.grid;
  constexpr int B = Layout::block_cells;
  std::size_t cells_per_block = 1;
  for (int d = 0; d < D; ++d) cells_per_block *= B;
  const std::size_t key_count = layout.block_count * cells_per_block;

  std::vector<char> occupied(layout.block_count, 0);
  for (std::size_t bi = 0; bi < system.batches.size(); ++bi) {
    auto& batch = system.batches[bi];
    const std::size_t n = batch.size();
    // key = block * B^D + cell inside the block (x fastest)
    std::vector<std::uint32_t> key(n);
    tbb::parallel_for(std::size_t{0}, n, [&](std::size_t p) {
      const Index<D> c = grid.cell_of(batch.x[p]);
      std::size_t block = 0, local = 0;
      for (int d = D - 1; d >= 0; --d) {
        block = block * layout.blocks[d] + c[d] / B;
        local = local * B + c[d] % B;
      }
      key[p] = static_cast<std::uint32_t>(block * cells_per_block + local);
    });
    std::vector<std::uint32_t> start(key_count + 1, 0);
    for (std::uint32_t k : key) ++start[k + 1];
    std::partial_sum(start.begin(), start.end(), start.begin());
    std::vector<std::uint32_t> order(n);
    {
      std::vector<std::uint32_t> next(start.begin(), start.end() - 1);
      for (std::uint32_t p = 0; p < n; ++p) order[next[key[p]]++] = p;
    }
    batch.block_begin.resize(layout.block_count + 1);
    for (std::size_t b = 0; b <= layout.block_count; ++b) {
      batch.block_begin[b] = start[b * cells_per_block];
      if (b < layout.block_count && start[(b + 1) * cells_per_block] > start[b * cells_per_block]) {
        occupied[b] = 1;
      }
    }
    batch.for_each_column([&](const char*, auto& column) { detail::permute(column, order); });
    detail::renumber_loaded_faces(system.loads.surface, static_cast<int>(bi), order);
  }

  layout.occupied.clear();
  for (auto& list : layout.occupied_by_colour) list.clear();
  Index<D> lo, hi;
  lo.fill(std::numeric_limits<int>::max());
  hi.fill(std::numeric_limits<int>::min());
  for (std::uint32_t b = 0; b < layout.block_count; ++b) {
    if (!occupied[b]) continue;
    const Index<D> bc = layout.block_coords(b);
    layout.occupied.push_back(b);
    layout.occupied_by_colour[Layout::colour(bc)].push_back(b);
    for (int d = 0; d < D; ++d) {
      lo[d] = std::min(lo[d], bc[d]);
      hi[d] = std::max(hi[d], bc[d]);
    }
  }
  // Nodes that particles of the occupied blocks can reach before the next sort.
  for (int d = 0; d < D; ++d) {
    system.grid.active_lo[d] = std::max(0, lo[d] * B - Layout::drift_limit - Shape::reach_below);
    system.grid.active_hi[d] =
        std::min(grid.cells[d], (hi[d] + 1) * B - 1 + Layout::drift_limit + Shape::reach_above);
  }
  system.flags.resort_needed = false;
  ++system.sorts;
}

}  // namespace flowmpm
