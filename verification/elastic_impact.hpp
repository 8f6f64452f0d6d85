// Two elastic bodies colliding ([Sulsky 1995]: two disks): no closed form
// for the motion, but no external work is done, so kinetic plus stored
// energy E is conserved in the continuum. Error, over the samples:
//   energy: max |E(t) - E(0)| / E(0);
//   restitution: |e - e_exact|, where the case gives e_exact (`restitution`;
//     1 for two equal elastic bars meeting end on, whose stress waves
//     return to the contact face together after 2 L / c [Graff 1975]).
// Measures: separation_min and separation_final (m), the distance between
// the two bodies' centres of mass, smallest over the samples and at the
// end; kinetic_final (E_kinetic at the end over E(0)); restitution, the
// coefficient of restitution of the centres of mass at the end,
//   e = -(V_2 - V_1) . u0 / |u0|^2,  u0 = V_2(0) - V_1(0),
// V_k body k's mass-weighted mean velocity.
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <string>

#include "engine/diagnostics.hpp"
#include "verification/reference_context.hpp"

namespace flowmpm {

struct ElasticImpact {
  static constexpr const char* type_name = "elastic_impact";
  double energy0 = std::numeric_limits<double>::quiet_NaN();
  double energy_error = 0.0, separation_min = std::numeric_limits<double>::infinity(), separation = 0.0;
  double kinetic = 0.0;
  double expected_restitution = std::numeric_limits<double>::quiet_NaN();  // NaN: none given
  std::array<double, 3> u0{};  // u0 (m/s), from the first sample
  double restitution = 0.0;

  static ElasticImpact read(ParameterTable& t, const ReferenceContext& context) {
    t.require(context.system.bodies.size() == 2, "type", "a case of two bodies for elastic_impact");
    ElasticImpact r;
    if (t.has("restitution")) {
      r.expected_restitution = t.number("restitution");
      t.require(r.expected_restitution >= 0.0 && r.expected_restitution <= 1.0, "restitution",
                "the exact coefficient of restitution, from 0 to 1");
    }
    return r;
  }

  template <int D, class Shape>
  void initialise(DiscreteSystem<D, Shape>&) const {}

  template <int D, class Shape>
  void sample(const DiscreteSystem<D, Shape>& system) {
    const Diagnostics d = diagnostics(system, 2);
    const double energy = d.kinetic_energy + d.stored_energy;
    const bool first = std::isnan(energy0);
    if (first) energy0 = energy;
    energy_error = std::max(energy_error, std::abs(energy - energy0) / energy0);
    kinetic = d.kinetic_energy / energy0;
    Vec<D> centre[2] = {Vec<D>::Zero(), Vec<D>::Zero()}, momentum[2] = {Vec<D>::Zero(), Vec<D>::Zero()};
    double mass[2] = {0.0, 0.0};
    for (const auto& b : system.batches) {
      for (std::size_t p = 0; p < b.size(); ++p) {
        centre[b.body] += b.mass[p] * b.x[p];
        momentum[b.body] += b.mass[p] * b.v[p];
        mass[b.body] += b.mass[p];
      }
    }
    separation = (centre[0] / mass[0] - centre[1] / mass[1]).norm();
    separation_min = std::min(separation_min, separation);
    const Vec<D> u = momentum[1] / mass[1] - momentum[0] / mass[0];
    if (first)
      for (int d = 0; d < D; ++d) u0[d] = u[d];
    double along = 0.0, approach = 0.0;  // u . u0, |u0|^2
    for (int d = 0; d < D; ++d) {
      along += u[d] * u0[d];
      approach += u0[d] * u0[d];
    }
    restitution = approach > 0.0 ? -along / approach : 0.0;
  }

  // The energy at the first sample, the extremes so far and the last sample (Reference::visit_state).
  template <class F>
  void visit_state(F&& f) {
    f("energy0", energy0);
    f("energy_error", energy_error);
    f("separation_min", separation_min);
    f("separation", separation);
    f("kinetic", kinetic);
    f("u0_x", u0[0]);
    f("u0_y", u0[1]);
    f("u0_z", u0[2]);
    f("restitution", restitution);
  }

  std::map<std::string, double> errors() const {
    std::map<std::string, double> e{{"energy", energy_error}};
    if (!std::isnan(expected_restitution)) e["restitution"] = std::abs(restitution - expected_restitution);
    return e;
  }
  std::map<std::string, double> measures() const {
    return {{"separation_min", separation_min},
            {"separation_final", separation},
            {"kinetic_final", kinetic},
            {"restitution", restitution}};
  }
};

}  // namespace flowmpm
