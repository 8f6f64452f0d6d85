// The largest stable time step of a scheme and shape function, and the one
// accepted: dt <= f h_min / c_max with h_min the smallest cell, c_max the
// fastest P wave of the materials, and f the shape function's stable factor
// for the scheme and the particles per cell (docs/STABILITY.md: a von
// Neumann analysis of the update, checked on the vibrating bar and the 2D
// column), taken with a margin of 10 %. With dt = "auto" the particles'
// speed is added to c_max at every step.
#pragma once
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "discretisation/shape_functions.hpp"
#include "discretisation/system_spec.hpp"
#include "engine/schemes.hpp"

namespace flowmpm {

struct StableStep {
  double crossing = 0.0;  // h_min / c_max (s)
  std::string material;   // the material with the fastest wave
  double particles_per_cell = 1.0;  // along the densest axis of any body
  double factor = 0.0;    // f: the stable factor with its margin
  double dt() const { return factor * crossing; }  // the largest accepted dt (s)
};

inline constexpr double stability_margin = 0.9;

inline StableStep stable_time_step(const SystemSpec& spec, const Scheme& scheme) {
  StableStep s;
  double h_min = std::numeric_limits<double>::infinity();
  for (int d = 0; d < spec.dimension; ++d) h_min = std::min(h_min, spec.grid.cell_size[d]);
  s.crossing = std::numeric_limits<double>::infinity();
  for (const auto& m : spec.materials) {
    const double dt = h_min / wave_speed(m.model);
    if (dt < s.crossing) s.crossing = dt, s.material = m.name;
  }
  for (const BodySpec& body : spec.bodies) {
    // Particles from a file: the mean particle's size V^(1/D) as their spacing.
    double file_spacing = 0.0;
    if (body.particles) {
      for (const double v : body.particles->volume) file_spacing += v;
      file_spacing = std::pow(file_spacing / static_cast<double>(body.particles->size()), 1.0 / spec.dimension);
    }
    for (int d = 0; d < spec.dimension; ++d) {
      const double spacing = body.particles ? file_spacing : body.spacing[d];
      s.particles_per_cell = std::max(s.particles_per_cell, spec.grid.cell_size[d] / spacing);
    }
  }
  const int i = std::clamp(static_cast<int>(std::ceil(s.particles_per_cell - 1e-9)), 1, 4) - 1;
  s.factor = stability_margin * with_shape_function(spec.shape_function, [&]<class Shape>() {
               return scheme.stress_from_updated_grid ? Shape::stable_factor_usl[i] : Shape::stable_factor_remapped[i];
             });
  // Beyond 4 per cell, the trend of uGIMP's USL limit at a free surface
  // (|dN|^2 / N grows with the particles per cell); conservative for the others.
  if (s.particles_per_cell > 4.0) s.factor *= std::sqrt(4.0 / s.particles_per_cell);
  return s;
}

}  // namespace flowmpm
