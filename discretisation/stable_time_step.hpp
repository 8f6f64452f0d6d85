// The largest stable time step of the explicit update: the time a P wave
// takes to cross the smallest cell, h_min / c_max (CFL number 1).
#pragma once
#include <algorithm>
#include <limits>
#include <string>

#include "discretisation/system_spec.hpp"

namespace flowmpm {

struct StableStep {
  double dt;             // s
  std::string material;  // the material with the fastest wave
};

inline StableStep stable_time_step(const SystemSpec& spec) {
  double h_min = std::numeric_limits<double>::infinity();
  for (int d = 0; d < spec.dimension; ++d) h_min = std::min(h_min, spec.grid.cell_size[d]);
  StableStep result{std::numeric_limits<double>::infinity(), ""};
  for (const auto& m : spec.materials) {
    const double dt = h_min / wave_speed(m.model);
    if (dt < result.dt) result = {dt, m.name};
  }
  return result;
}

}  // namespace flowmpm
