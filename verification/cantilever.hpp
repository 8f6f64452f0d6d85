// A slender cantilever (Euler-Bernoulli beam; [Timoshenko 1970]), 2D,
// clamped at `fixed_end` along `axis`, of length L and height H, bending
// along `deflection_axis` under its own weight (q = rho g H per unit
// length and thickness, from analysis.gravity) and a tip force P
// (`tip_force`, N/m per unit thickness, optional). With E' = E in plane
// stress and E / (1 - nu^2) in plane strain, I = H^3 / 12:
//   w(x) = q x^2 (6 L^2 - 4 L x + x^2) / (24 E' I) + P x^2 (3 L - x) / (6 E' I),
// so w(L) = q L^4 / (8 E' I) + P L^3 / (3 E' I). Shear deformation adds
// about (E / G)(H / L)^2 / 3 of that (0.9 % at L = 10 H, nu = 0.3).
// Errors at the last sample (a quasi-static run, with damping), relative
// to |w(L)|:
//   deflection:     mass-weighted RMS over the particles of u - w(X);
//   tip_deflection: the mean u of the particles of the free end's column
//                   against the mean w there.
// Measures: tip_deflection (m, the particles' mean) and
// tip_deflection_exact (m).
#pragma once
#include <cmath>
#include <map>
#include <string>

#include "discretisation/discrete_system.hpp"
#include "verification/error_norm.hpp"
#include "verification/reference_context.hpp"

namespace flowmpm {

struct Cantilever {
  static constexpr const char* type_name = "cantilever";
  int axis = 0, deflection_axis = 1;
  double fixed_end = 0.0, L = 0.0, H = 0.0;
  double q = 0.0, P = 0.0, EI = 0.0;  // N/m^2, N/m, N m
  double deflection_error = 0.0, tip = 0.0, tip_exact = 0.0;

  static Cantilever read(ParameterTable& t, const ReferenceContext& context) {
    const SystemSpec& s = context.system;
    t.require(s.dimension == 2, "type", "a 2D case for cantilever");
    Cantilever r;
    r.axis = read_axis(t, "axis", 2);
    r.deflection_axis = 1 - r.axis;
    r.fixed_end = t.number("fixed_end");
    r.L = t.positive("length", "the beam's length in m");
    r.H = t.positive("height", "the beam's height in m");
    r.P = t.number_or("tip_force", 0.0);
    const LinearElastic& m = elastic_material(t, context);
    const double E = m.parameters.youngs_modulus, nu = m.parameters.poisson_ratio;
    r.EI = (s.plane_stress ? E : E / (1.0 - nu * nu)) * r.H * r.H * r.H / 12.0;
    r.q = m.parameters.density * s.gravity[r.deflection_axis] * r.H;
    t.require(r.q != 0.0 || r.P != 0.0, "tip_force", "a tip force in N/m, or gravity across the beam");
    return r;
  }

  // Euler-Bernoulli deflection at distance x from the clamp (m).
  double w(double x) const {
    return q * x * x * (6 * L * L - 4 * L * x + x * x) / (24 * EI) + P * x * x * (3 * L - x) / (6 * EI);
  }

  template <int D, class Shape>
  void initialise(DiscreteSystem<D, Shape>&) const {}

  template <int D, class Shape>
  void sample(const DiscreteSystem<D, Shape>& system) {
    RmsError error;
    double last = -std::numeric_limits<double>::infinity();
    for (const auto& b : system.batches)
      for (const auto& x0 : b.x0) last = std::max(last, x0[axis]);
    double tip_sum = 0.0, exact_sum = 0.0, mass = 0.0;
    for (const auto& b : system.batches) {
      for (std::size_t p = 0; p < b.size(); ++p) {
        const double X = b.x0[p][axis] - fixed_end;
        const double u = b.x[p][deflection_axis] - b.x0[p][deflection_axis];
        error.add(b.mass[p], u - w(X));
        if (b.x0[p][axis] >= last - 1e-9 * L) {
          tip_sum += b.mass[p] * u;
          exact_sum += b.mass[p] * w(X);
          mass += b.mass[p];
        }
      }
    }
    deflection_error = error.relative_to(std::abs(w(L)));
    tip = tip_sum / mass;
    tip_exact = exact_sum / mass;
  }

  // The last sample (Reference::visit_state).
  template <class F>
  void visit_state(F&& f) {
    f("deflection_error", deflection_error);
    f("tip", tip);
    f("tip_exact", tip_exact);
  }

  std::map<std::string, double> errors() const {
    return {{"deflection", deflection_error}, {"tip_deflection", std::abs(tip - tip_exact) / std::abs(w(L))}};
  }
  std::map<std::string, double> measures() const { return {{"tip_deflection", tip}, {"tip_deflection_exact", tip_exact}}; }
};

}  // namespace flowmpm
