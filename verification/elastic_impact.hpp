// Two elastic bodies colliding ([Sulsky 1995]: two disks): no closed form
// for the motion, but no external work is done, so kinetic plus stored
// energy E is conserved in the continuum. Error, over the samples:
//   energy: max |E(t) - E(0)| / E(0).
// Measures: separation_min and separation_final (m), the distance between
// the two bodies' centres of mass, smallest over the samples and at the
// end; kinetic_final (E_kinetic at the end over E(0)).
#pragma once
#include <algorithm>
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

  static ElasticImpact read(ParameterTable& t, const ReferenceContext& context) {
    t.require(context.system.bodies.size() == 2, "type", "a case of two bodies for elastic_impact");
    return {};
  }

  template <int D, class Shape>
  void initialise(DiscreteSystem<D, Shape>&) const {}

  template <int D, class Shape>
  void sample(const DiscreteSystem<D, Shape>& system) {
    const Diagnostics d = diagnostics(system, 2);
    const double energy = d.kinetic_energy + d.stored_energy;
    if (std::isnan(energy0)) energy0 = energy;
    energy_error = std::max(energy_error, std::abs(energy - energy0) / energy0);
    kinetic = d.kinetic_energy / energy0;
    Vec<D> centre[2] = {Vec<D>::Zero(), Vec<D>::Zero()};
    double mass[2] = {0.0, 0.0};
    for (const auto& b : system.batches) {
      for (std::size_t p = 0; p < b.size(); ++p) {
        centre[b.body] += b.mass[p] * b.x[p];
        mass[b.body] += b.mass[p];
      }
    }
    separation = (centre[0] / mass[0] - centre[1] / mass[1]).norm();
    separation_min = std::min(separation_min, separation);
  }

  // The energy at the first sample, the extremes so far and the last sample (Reference::visit_state).
  template <class F>
  void visit_state(F&& f) {
    f("energy0", energy0);
    f("energy_error", energy_error);
    f("separation_min", separation_min);
    f("separation", separation);
    f("kinetic", kinetic);
  }

  std::map<std::string, double> errors() const { return {{"energy", energy_error}}; }
  std::map<std::string, double> measures() const {
    return {{"separation_min", separation_min}, {"separation_final", separation}, {"kinetic_final", kinetic}};
  }
};

}  // namespace flowmpm
