// The stress a body's particles start with (Pa, Voigt order, compression
// negative), chosen by the `type` of a body's initial_stress table:
//   uniform:   `stress`, six components listed xx, yy, zz, xy, yz, xz
//              (as results.h5 writes them);
//   geostatic: from gravity and the depth below the body's top,
//              sigma_v = -rho |g_z| (top - z) along the vertical z (the
//              axis of gravity's largest component), each horizontal normal
//              stress K0 sigma_v (`k0`). The out-of-plane stress of 2D
//              plane strain is horizontal too (K0 = nu / (1 - nu) is then
//              the elastic at-rest state); plane stress and 1D keep their
//              zero components. Gravity tilted towards a horizontal axis h
//              (a body on a slope) adds the shear of the infinite slope,
//              sigma_hz = rho g_h (top - z), which with sigma_v balances
//              gravity and leaves the top free ([Lambe 1969], the infinite
//              slope); no shear otherwise. A `surcharge` q (Pa, default 0):
//              the weight per unit area of what rests on the top (a
//              footing, a block on a slope), sigma_v = -(q + rho |g_z|
//              (top - z)), and on a slope its shear q g_h / |g_z| too: the
//              top carries that load from t = 0 instead of taking it as an
//              impact.
// Adding one is one new type and one line in the variant below.
#pragma once
#include <algorithm>
#include <cmath>
#include <variant>

#include "core/registry.hpp"
#include "core/vec.hpp"
#include "core/voigt.hpp"

namespace flowmpm {

struct InitialStressContext {
  int dimension = 3;
  bool plane_stress = false;
  Vec3 gravity{};  // m/s^2
};

struct UniformStress {
  static constexpr const char* type_name = "uniform";
  Voigt stress{};  // Pa

  static UniformStress read(ParameterTable& t, const InitialStressContext& c) {
    UniformStress u;
    const std::vector<double> s = t.numbers("stress", 6);
    for (int k = 0; k < 6; ++k) u.stress[voigt_slot_of_listed[k]] = s[k];
    // The components the stress state of the analysis does not carry must be 0
    // (Voigt slots: xx, yy, zz, yz, xz, xy).
    const bool allowed[3][6] = {{true, false, false, false, false, false},
                                {true, true, !c.plane_stress, false, false, true},
                                {true, true, true, true, true, true}};
    for (int i = 0; i < 6; ++i) {
      t.require(allowed[c.dimension - 1][i] || u.stress[i] == 0.0, "stress",
                c.dimension == 1 ? "only sigma_xx nonzero in 1D (uniaxial stress), in Pa"
                : c.plane_stress ? "sigma_zz, sigma_yz and sigma_xz zero in plane stress, in Pa"
                                 : "sigma_yz and sigma_xz zero in 2D, in Pa");
    }
    return u;
  }
  Voigt at(const Vec3&, double, double) const { return stress; }
};

struct GeostaticStress {
  static constexpr const char* type_name = "geostatic";
  double k0 = 0.0;
  double surcharge = 0.0;     // Pa, the vertical load on the top
  int vertical = 1;           // the axis of gravity's largest component
  double weight = 0.0;        // |g_vertical| (m/s^2)
  Vec3 gravity{};             // m/s^2, for the slope's shear
  int dimension = 3;
  bool plane_stress = false;

  static GeostaticStress read(ParameterTable& t, const InitialStressContext& c) {
    GeostaticStress g;
    g.k0 = t.number("k0");
    t.require(g.k0 >= 0.0, "k0", "a coefficient of earth pressure at rest K0 >= 0");
    g.surcharge = t.number_or("surcharge", 0.0);
    t.require(g.surcharge >= 0.0, "surcharge", "a load on the body's top >= 0 in Pa (the weight per unit area resting on it)");
    for (int d = 0; d < c.dimension; ++d) {
      if (std::abs(c.gravity[d]) > g.weight) g.vertical = d, g.weight = std::abs(c.gravity[d]);
    }
    t.require(g.weight > 0.0, "type", "a case with gravity (analysis.gravity) for a geostatic stress");
    g.gravity = c.gravity;
    g.dimension = c.dimension;
    g.plane_stress = c.plane_stress;
    return g;
  }

  // At x, for density rho (kg/m^3) and the body's top (m, along the vertical).
  Voigt at(const Vec3& x, double rho, double top) const {
    Voigt s{};
    const double vertical_stress = -(rho * weight * (top - x[vertical]) + surcharge);
    for (int d = 0; d < 3; ++d) {
      const bool carried = d < dimension || (dimension == 2 && !plane_stress);
      if (d == vertical) {
        s[d] = vertical_stress;
      } else if (carried && dimension > 1) {
        s[d] = k0 * vertical_stress;
      }
      if (d != vertical && d < dimension && gravity[d] != 0.0)
        s[voigt_slot(d, vertical)] = rho * gravity[d] * (top - x[vertical]) + surcharge * gravity[d] / weight;
    }
    return s;
  }
};

using InitialStressVariant = std::variant<UniformStress, GeostaticStress>;
using InitialStresses = Registry<InitialStressVariant>;

}  // namespace flowmpm
