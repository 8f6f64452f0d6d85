// A thick-walled cylinder (inner radius a, outer radius b) under an
// internal pressure p, plane strain (Lame; [Timoshenko 1970]), 2D (a
// section across the axis about `center`, or, axisymmetric, the (r, z)
// section held along z: sigma_r = sigma_xx, sigma_theta = sigma_zz): with
// A = p a^2 / (b^2 - a^2),
//   sigma_r = A (1 - b^2 / r^2),  sigma_theta = A (1 + b^2 / r^2),
// so sigma_r = -p at r = a and 0 at r = b. Errors at the last sample (a
// quasi-static run), mass-weighted RMS over the particles farther than
// `margin` (m, default 0) from both surfaces, relative to p:
//   radial_stress, hoop_stress.
// (A lattice fills a curved surface as a staircase, whose first layer of
// particles carries a local error: a margin of a cell measures the rest.)
#pragma once
#include <cmath>
#include <map>
#include <string>

#include "discretisation/discrete_system.hpp"
#include "verification/error_norm.hpp"
#include "verification/reference_context.hpp"

namespace flowmpm {

struct ThickCylinder {
  static constexpr const char* type_name = "thick_cylinder";
  double cx = 0.0, cy = 0.0, a = 0.0, b = 0.0, p = 0.0, margin = 0.0;
  bool axisymmetric = false;
  double radial_error = 0.0, hoop_error = 0.0;

  static ThickCylinder read(ParameterTable& t, const ReferenceContext& context) {
    t.require(context.system.dimension == 2 && !context.system.plane_stress, "type",
              "a 2D plane strain case for thick_cylinder");
    ThickCylinder r;
    r.axisymmetric = context.system.axisymmetric;
    if (r.axisymmetric) {
      if (t.has("center")) t.fail("center", "no center in axisymmetric (the axis is r = 0)");
    } else {
      const std::vector<double> c = t.numbers("center", 2);
      r.cx = c[0];
      r.cy = c[1];
    }
    r.a = t.positive("inner_radius", "the inner radius in m");
    r.b = t.positive("outer_radius", "the outer radius in m");
    t.require(r.b > r.a, "outer_radius", "an outer radius above the inner radius");
    r.p = t.number("pressure");
    t.require(r.p != 0.0, "pressure", "the internal pressure in Pa, not 0");
    r.margin = t.number_or("margin", 0.0);
    t.require(r.margin >= 0.0 && 2.0 * r.margin < r.b - r.a, "margin",
              "a distance from the surfaces in m, >= 0 and less than half the wall");
    return r;
  }

  double A() const { return p * a * a / (b * b - a * a); }

  template <int D, class Shape>
  void initialise(DiscreteSystem<D, Shape>&) const {}

  template <int D, class Shape>
  void sample(const DiscreteSystem<D, Shape>& system) {
    if constexpr (D == 2) {
      RmsError radial, hoop;
      for (const auto& batch : system.batches) {
        for (std::size_t q = 0; q < batch.size(); ++q) {
          const double x = batch.x0[q][0] - cx, y = batch.x0[q][1] - cy;
          const double r = axisymmetric ? batch.x0[q][0] : std::hypot(x, y);
          if (r < a + margin || r > b - margin) continue;
          const double c = x / r, s = y / r;
          const Voigt& sigma = batch.stress[q];
          const double sr = axisymmetric ? sigma[0] : sigma[0] * c * c + sigma[1] * s * s + 2.0 * sigma[5] * s * c;
          const double st = axisymmetric ? sigma[2] : sigma[0] * s * s + sigma[1] * c * c - 2.0 * sigma[5] * s * c;
          const double sr_exact = A() * (1.0 - b * b / (r * r)), st_exact = A() * (1.0 + b * b / (r * r));
          radial.add(batch.mass[q], sr - sr_exact);
          hoop.add(batch.mass[q], st - st_exact);
        }
      }
      radial_error = radial.relative_to(std::abs(p));
      hoop_error = hoop.relative_to(std::abs(p));
    }
  }

  // The last sample (Reference::visit_state).
  template <class F>
  void visit_state(F&& f) {
    f("radial_error", radial_error);
    f("hoop_error", hoop_error);
  }

  std::map<std::string, double> errors() const { return {{"radial_stress", radial_error}, {"hoop_stress", hoop_error}}; }
};

}  // namespace flowmpm
