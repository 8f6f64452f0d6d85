// The collapse of a granular column in plane strain: a column of width L0
// (`width`) and height H0 (`height`), a = H0 / L0, against a wall at
// x = `wall` on a base at y = `base`, released at t = 0, spreads along +x
// and comes to rest. Measured at the last sample: the run-out L (the
// farthest particle's distance from the wall plus half a particle, among
// the particles whose top stands at least `front_thickness` above the base:
// 0 by default, every particle) and the final height H (the highest
// particle above the base plus half a particle), as (L - L0) / L0 and
// H / L0. A continuum deposit thins without end: its tail, below a cell or
// two thick, lengthens as the cells shrink, while the front where it is
// thicker converges (docs/validation/soil_scenes.md); front_thickness
// measures there.
// Reference: the fits of Lube, Huppert, Sparks and Freundt (2005) to
// quasi-2D collapses in a channel of several dry granular materials (sand,
// rice, sugar), which they found independent of the material
// ([Lube 2005], as consolidated by [Lagree 2011], eqs. 3.1-3.2):
//   (L - L0) / L0 = 1.2 a for a < 1.8,  1.9 a^(2/3) for a > 2.8,
//   H / L0 = a for a < 1.15 (the top stays),  a^(2/5) above;
// between a = 1.8 and 2.8 the run-out lies between the two fits. Glass
// beads run farther: 1.8 a for a < 3 ([Lajeunesse 2005], via [Lagree 2011]).
// Error: runout = the distance of (L - L0) / L0 from Lube's value (or from
// the band between the fits) over that value; height = |H / L0 - Lube's| /
// Lube's. Measures: runout, runout_farthest (every particle), height (-),
// their references, glass_beads
// (Lajeunesse's run-out, a < 3 only), and at_rest: the kinetic energy at
// the last sample over its largest (a deposit at rest: below 1e-3).
#pragma once
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <utility>

#include "verification/reference_context.hpp"

namespace flowmpm {

struct ColumnCollapse {
  static constexpr const char* type_name = "column_collapse";
  double wall = 0.0, base = 0.0;     // m
  double width = 0.0, height0 = 0.0;  // L0, H0 (m)
  double front_thickness = 0.0;       // m
  double runout = 0.0, height = 0.0;  // (L - L0) / L0 and H / L0 at the last sample
  double runout_farthest = 0.0;       // the same to the farthest particle
  double kinetic = 0.0, kinetic_peak = 0.0;  // J per unit thickness

  static ColumnCollapse read(ParameterTable& t, const ReferenceContext& context) {
    const SystemSpec& s = context.system;
    t.require(s.dimension == 2 && !s.plane_stress && !s.axisymmetric, "type",
              "a 2D plane-strain case for column_collapse (the fits are for two-dimensional collapses)");
    ColumnCollapse r;
    r.wall = t.number("wall");
    r.base = t.number("base");
    r.width = t.positive("width", "the column's width L0 in m");
    r.height0 = t.positive("height", "the column's height H0 in m");
    r.front_thickness = t.number_or("front_thickness", 0.0);
    t.require(r.front_thickness >= 0.0 && r.front_thickness < r.height0, "front_thickness",
              "a deposit thickness in m from 0 to below the column's height");
    return r;
  }

  double aspect_ratio() const { return height0 / width; }

  // Lube's run-out (L - L0) / L0: the lower and upper ends of its band
  // (equal outside 1.8 < a < 2.8).
  std::pair<double, double> runout_band() const {
    const double a = aspect_ratio(), linear = 1.2 * a, power = 1.9 * std::cbrt(a * a);
    if (a < 1.8) return {linear, linear};
    if (a > 2.8) return {power, power};
    return {std::min(linear, power), std::max(linear, power)};
  }
  double height_reference() const {
    const double a = aspect_ratio();
    return a < 1.15 ? a : std::pow(a, 0.4);
  }

  template <int D, class Shape>
  void initialise(DiscreteSystem<D, Shape>&) const {}

  template <int D, class Shape>
  void sample(const DiscreteSystem<D, Shape>& system) {
    if constexpr (D == 2) {
      double farthest = -std::numeric_limits<double>::infinity(), front = farthest, top = farthest, energy = 0.0;
      for (const auto& b : system.batches) {
        if (system.is_rigid(b)) continue;  // a rigid obstacle is no part of the deposit
        const double half = 0.5 * b.particle_length;
        for (std::size_t p = 0; p < b.size(); ++p) {
          const double x = b.x[p][0] - wall + half, y = b.x[p][1] - base + half;
          farthest = std::max(farthest, x);
          if (y >= front_thickness) front = std::max(front, x);
          top = std::max(top, y);
          energy += 0.5 * b.mass[p] * (b.v[p][0] * b.v[p][0] + b.v[p][1] * b.v[p][1]);
        }
      }
      runout = (front - width) / width;
      runout_farthest = (farthest - width) / width;
      height = top / width;
      kinetic = energy;
      kinetic_peak = std::max(kinetic_peak, energy);
    }
  }

  template <class F>
  void visit_state(F&& f) {
    f("runout", runout);
    f("runout_farthest", runout_farthest);
    f("height", height);
    f("kinetic", kinetic);
    f("kinetic_peak", kinetic_peak);
  }

  std::map<std::string, double> errors() const {
    const auto [low, high] = runout_band();
    const double miss = runout < low ? (low - runout) / low : runout > high ? (runout - high) / high : 0.0;
    const double h = height_reference();
    return {{"runout", miss}, {"height", std::abs(height - h) / h}};
  }
  std::map<std::string, double> measures() const {
    const auto [low, high] = runout_band();
    std::map<std::string, double> m{{"aspect_ratio", aspect_ratio()},
                                    {"runout", runout},
                                    {"runout_farthest", runout_farthest},
                                    {"runout_low", low},
                                    {"runout_high", high},
                                    {"height", height},
                                    {"height_reference", height_reference()},
                                    {"at_rest", kinetic_peak > 0.0 ? kinetic / kinetic_peak : 0.0}};
    if (aspect_ratio() < 3.0) m["glass_beads"] = 1.8 * aspect_ratio();
    return m;
  }
};

}  // namespace flowmpm
