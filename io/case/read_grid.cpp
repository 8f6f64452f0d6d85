// [grid]: a regular grid of cells.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "core/number_text.hpp"
#include "io/case/case_limits.hpp"
#include "io/case/case_reader.hpp"
#include "io/case/case_sections.hpp"

namespace flowmpm {

void read_grid(TableReader t, SystemSpec& c) {
  c.grid.origin = vector_of(t, "origin", c.dimension);
  c.grid.cell_size = per_axis(t, "cell_size", c.dimension);
  if (!t.has("cell_size")) t.fail("cell_size", "the cell size in m (a number, or one per axis)");
  for (int d = 0; d < c.dimension; ++d) {
    t.require(c.grid.cell_size[d] > 0.0, "cell_size", "positive cell sizes in m");
  }
  const std::vector<double> cells = t.numbers("cells", static_cast<std::size_t>(c.dimension));
  c.grid.cells = {1, 1, 1};
  for (int d = 0; d < c.dimension; ++d) {
    t.require(cells[d] >= 1.0 && cells[d] == std::floor(cells[d]) && cells[d] < 1e6, "cells",
              "a whole number of cells (1 to 10^6) per axis");
    c.grid.cells[d] = static_cast<int>(cells[d]);
  }
  t.reject_unknown_keys();
}

double grid_max(const SystemSpec& c, int d) {
  return c.grid.origin[d] + c.grid.cell_size[d] * c.grid.cells[d];
}

}  // namespace flowmpm
