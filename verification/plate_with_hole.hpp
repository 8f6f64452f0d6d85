// An infinite plate with a circular hole of radius a under a far-field
// tension sigma_0 along `axis` (Kirsch; [Timoshenko 1970]), 2D. With r and
// theta measured from the hole's centre and the load axis:
//   sigma_11 = s0 [1 - a^2/r^2 (3/2 cos 2t + cos 4t) + 3/2 a^4/r^4 cos 4t],
//   sigma_22 = s0 [-a^2/r^2 (1/2 cos 2t - cos 4t) - 3/2 a^4/r^4 cos 4t],
//   sigma_12 = s0 [-a^2/r^2 (1/2 sin 2t + sin 4t) + 3/2 a^4/r^4 sin 4t],
// (1 the load axis), so that sigma_11 = 3 s0 at the hole's edge across the
// load (theta = 90 degrees): the stress concentration. A finite plate of
// width W carries slightly more (about 1 % for W = 20 a, [Timoshenko 1970]).
// Errors at the last sample (a quasi-static run):
//   stress:        mass-weighted RMS over the particles within `extent` of
//                  the centre (default: all) of |sigma - sigma_Kirsch|
//                  (in-plane components, Frobenius norm), relative to s0;
//   concentration: at the particle nearest the hole's edge across the load,
//                  |sigma_11 - sigma_11,Kirsch| / sigma_11,Kirsch there.
// Measures: concentration (that particle's sigma_11 / s0, which tends to 3
// as the particle nears the edge) and concentration_kirsch (Kirsch's
// value at the particle).
#pragma once
#include <cmath>
#include <limits>
#include <map>
#include <string>

#include "discretisation/discrete_system.hpp"
#include "verification/error_norm.hpp"
#include "verification/reference_context.hpp"

namespace flowmpm {

struct PlateWithHole {
  static constexpr const char* type_name = "plate_with_hole";
  double cx = 0.0, cy = 0.0, a = 0.0, s0 = 0.0;
  int axis = 0;
  double extent = std::numeric_limits<double>::infinity();
  double stress_error = 0.0, edge_stress = 0.0, edge_kirsch = 0.0;

  static PlateWithHole read(ParameterTable& t, const ReferenceContext& context) {
    t.require(context.system.dimension == 2, "type", "a 2D case for plate_with_hole");
    PlateWithHole r;
    const std::vector<double> c = t.numbers("center", 2);
    r.cx = c[0];
    r.cy = c[1];
    r.a = t.positive("radius", "the hole's radius in m");
    r.axis = read_axis(t, "axis", 2);
    r.s0 = t.number("stress");
    t.require(r.s0 != 0.0, "stress", "the far-field stress along the axis in Pa, not 0");
    if (t.has("extent")) r.extent = t.positive("extent", "the radius in m within which the stress is compared");
    return r;
  }

  // Kirsch's (sigma_xx, sigma_yy, sigma_xy) at (x, y).
  std::array<double, 3> kirsch(double x, double y) const {
    // In the frame of the load axis (a reflection swapping x and y for "y").
    const double u = axis == 0 ? x - cx : y - cy, v = axis == 0 ? y - cy : x - cx;
    const double r2 = u * u + v * v, t = std::atan2(v, u);
    const double a2 = a * a / r2, a4 = a2 * a2;
    const double c2 = std::cos(2 * t), c4 = std::cos(4 * t), s2 = std::sin(2 * t), s4 = std::sin(4 * t);
    const double s11 = s0 * (1.0 - a2 * (1.5 * c2 + c4) + 1.5 * a4 * c4);
    const double s22 = s0 * (-a2 * (0.5 * c2 - c4) - 1.5 * a4 * c4);
    const double s12 = s0 * (-a2 * (0.5 * s2 + s4) + 1.5 * a4 * s4);
    return axis == 0 ? std::array{s11, s22, s12} : std::array{s22, s11, s12};
  }

  template <int D, class Shape>
  void initialise(DiscreteSystem<D, Shape>&) const {}

  template <int D, class Shape>
  void sample(const DiscreteSystem<D, Shape>& system) {
    if constexpr (D == 2) {
      RmsError error;
      // The hole's edge across the load.
      const double ex = axis == 0 ? cx : cx + a, ey = axis == 0 ? cy + a : cy;
      double nearest = std::numeric_limits<double>::infinity();
      for (const auto& b : system.batches) {
        for (std::size_t p = 0; p < b.size(); ++p) {
          const double x = b.x0[p][0], y = b.x0[p][1];
          const auto k = kirsch(x, y);
          const Voigt& s = b.stress[p];
          const double e2 = (s[0] - k[0]) * (s[0] - k[0]) + (s[1] - k[1]) * (s[1] - k[1]) + 2.0 * (s[5] - k[2]) * (s[5] - k[2]);
          if (std::hypot(x - cx, y - cy) <= extent) error.add(b.mass[p], std::sqrt(e2));
          const double d = std::hypot(x - ex, y - ey);
          if (d < nearest) {
            nearest = d;
            edge_stress = s[axis];
            edge_kirsch = k[axis];
          }
        }
      }
      stress_error = error.relative_to(std::abs(s0));
    }
  }

  // The last sample (Reference::visit_state).
  template <class F>
  void visit_state(F&& f) {
    f("stress_error", stress_error);
    f("edge_stress", edge_stress);
    f("edge_kirsch", edge_kirsch);
  }

  std::map<std::string, double> errors() const {
    return {{"stress", stress_error}, {"concentration", std::abs(edge_stress - edge_kirsch) / std::abs(edge_kirsch)}};
  }
  std::map<std::string, double> measures() const {
    return {{"concentration", edge_stress / s0}, {"concentration_kirsch", edge_kirsch / s0}};
  }
};

}  // namespace flowmpm
