// Solvent diffusing into a slab from its two faces (held at the
// concentration u_b(t), node sets of the case) and the swelling strain
// beta c it causes, in a linear_elastic material with an isotropic beta
// ([Crank 1975] ch. 4 for c; verification/slab_series.hpp). Quasi-static
// closed forms with the exact c(X, t), X = x0_axis - from:
//  - support = "free": a 1D bar with free ends (uniaxial stress): it swells
//    without stress, eps_xx = beta c, sigma_xx = 0;
//  - support = "lateral": a 2D layer in plane strain whose faces across the
//    axis are held on rollers (eps_yy = eps_zz = 0), free along it
//    (sigma_aa = 0): every particle carries
//    sigma_other = sigma_zz = -E beta c / (1 - nu) ([Timoshenko 1970],
//    thermal stress in a plate held at its edges, with beta c for alpha dT).
// Errors, mass-weighted RMS over the particles and the samples:
// `concentration` relative to the largest |u_b - u0|; `stress` (sigma_aa,
// and sigma_other against its closed form) relative to E beta |u_b - u0|
// (divided by 1 - nu for "lateral"); `strain` ("free": eps_aa - beta c)
// relative to beta |u_b - u0|.
#pragma once
#include <algorithm>
#include <cmath>
#include <map>
#include <string>

#include "discretisation/discrete_system.hpp"
#include "verification/error_norm.hpp"
#include "verification/reference_context.hpp"
#include "verification/slab_transport.hpp"

namespace flowmpm {

struct SwellingSlab {
  static constexpr const char* type_name = "swelling_slab";
  bool lateral = false;
  int axis = 0;
  double from = 0.0;
  SlabSeries exact;
  double E = 0.0, nu = 0.0, beta = 0.0, amplitude = 0.0;
  RmsError concentration, stress, strain;

  static SwellingSlab read(ParameterTable& t, const ReferenceContext& context) {
    const SystemSpec& s = context.system;
    SwellingSlab r;
    r.lateral = t.choice("support", {"free", "lateral"}) == "lateral";
    if (r.lateral) {
      t.require(s.dimension == 2 && !s.plane_stress, "support", "\"free\" outside 2D plane strain");
    } else {
      t.require(s.dimension == 1, "support", "\"lateral\" outside 1D (a free bar is 1D, uniaxial stress)");
    }
    r.axis = read_axis(t, "axis", s.dimension);
    r.from = t.number("from");
    r.exact.length = t.positive("length", "the slab thickness along the axis in m");
    r.exact.initial = t.number("initial");
    r.exact.boundary = t.time_function("boundary", "the concentration the faces are held at");
    for (const auto& [time, value] : r.exact.boundary.points)
      r.amplitude = std::max(r.amplitude, std::abs(value - r.exact.initial));
    t.require(r.amplitude > 0.0, "boundary", "a face concentration other than the initial one");
    r.exact.kappa = diffusivity_along(t, context, false, r.axis);
    const LinearElastic& m = elastic_material(t, context);
    const Expansion& e = m.parameters.expansion;
    if (!e.solvent || e.concentration) {
      t.fail("type", "a first body whose linear_elastic material swells with the diffused solvent (beta)");
    }
    r.E = m.parameters.youngs_modulus;
    r.nu = m.parameters.poisson_ratio;
    r.beta = e.beta[0];
    return r;
  }

  template <int D, class Shape>
  void initialise(DiscreteSystem<D, Shape>&) const {}

  template <int D, class Shape>
  void sample(const DiscreteSystem<D, Shape>& system) {
    if (system.step == 0) return;  // the initial state is exact by construction
    const int other = 1 - axis;
    std::map<double, double> c_at;  // the series at each initial position X (a lattice)
    for (const auto& b : system.batches) {
      for (std::size_t p = 0; p < b.size(); ++p) {
        const double X = b.x0[p][axis] - from;
        auto [at, missing] = c_at.try_emplace(X, 0.0);
        if (missing) at->second = exact(X, system.t);
        const double c = at->second;
        concentration.add(b.mass[p], b.concentration[p] - c);
        stress.add(b.mass[p], b.stress[p][axis]);
        if (lateral) {
          stress.add(b.mass[p], b.stress[p][other] + E * beta * c / (1.0 - nu));
        } else {
          strain.add(b.mass[p], b.strain[p][axis] - beta * c);
        }
      }
    }
  }

  // What the samples have summed so far (Reference::visit_state).
  template <class F>
  void visit_state(F&& f) {
    f("concentration", concentration);
    f("stress", stress);
    f("strain", strain);
  }

  std::map<std::string, double> errors() const {
    std::map<std::string, double> e = {
        {"concentration", concentration.relative_to(amplitude)},
        {"stress", stress.relative_to(E * beta * amplitude / (lateral ? 1.0 - nu : 1.0))}};
    if (!lateral) e["strain"] = strain.relative_to(beta * amplitude);
    return e;
  }
};

}  // namespace flowmpm
