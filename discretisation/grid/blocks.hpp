// Blocks of cells for race-free, deterministic particle-to-grid transfer.
//
// Cells are grouped into cubic blocks of B cells per axis and each block is
// coloured by the parity of its block index along each axis (2^D colours).
// A particle of block i along an axis touches nodes from
// i B - k - reach_below to (i + 1) B - 1 + k + reach_above, where k is how
// many cells it has drifted out of its block since the last sort. Blocks of
// one colour are one block apart, so they share no node as long as
//   2 k < B + 1 - reach_below - reach_above.
// Blocks of one colour are processed in parallel, colours one after another,
// and the particles of a block in their fixed sorted order: every nodal sum
// is taken in the same order whatever the thread count (bit-identical
// results). Particles are re-sorted before any can drift past `drift_limit`.
#pragma once
#include <array>
#include <vector>

#include "discretisation/grid/grid.hpp"

namespace flowmpm {

template <int D, class Shape>
struct BlockLayout {
  static constexpr int colours = 1 << D;
  // Block edge in cells: the smallest that allows a drift of two cells.
  static constexpr int block_cells = 4 + Shape::reach_below + Shape::reach_above;
  // Largest drift (cells) for which same-coloured blocks stay disjoint.
  static constexpr int drift_limit = (block_cells - Shape::reach_below - Shape::reach_above) / 2;
  static_assert(2 * drift_limit < block_cells + 1 - Shape::reach_below - Shape::reach_above);
  static_assert(drift_limit >= 2, "a particle may move one cell per step after a re-sort trigger");

  Index<D> blocks{};  // block count per axis
  std::size_t block_count = 0;
  // Blocks holding particles, by colour and all together, in increasing order.
  std::array<std::vector<std::uint32_t>, colours> occupied_by_colour;
  std::vector<std::uint32_t> occupied;

  explicit BlockLayout(const Index<D>& cells = {}) {
    block_count = 1;
    for (int d = 0; d < D; ++d) {
      blocks[d] = (cells[d] + block_cells - 1) / block_cells;
      block_count *= static_cast<std::size_t>(blocks[d]);
    }
  }

  Index<D> block_coords(std::uint32_t b) const {
    Index<D> c{};
    for (int d = 0; d < D; ++d) {
      c[d] = static_cast<int>(b % static_cast<std::uint32_t>(blocks[d]));
      b /= static_cast<std::uint32_t>(blocks[d]);
    }
    return c;
  }

  static int colour(const Index<D>& block) {
    int c = 0;
    for (int d = 0; d < D; ++d) c |= (block[d] & 1) << d;
    return c;
  }
};

}  // namespace flowmpm
