// A body whose stress ends uniform: a block under a traction once its waves
// have died out (tests/test_loads.cpp), the uniaxial traction benchmark of
// [CB-Geo]. Component `component` ("xx", "yy", ...) of the stress of every
// particle of the first body should equal `value` (Pa). Errors at the last
// sample, relative to |value|:
//   stress:     mass-weighted RMS over the particles;
//   stress_max: the largest deviation of a particle.
#pragma once
#include <algorithm>
#include <cmath>
#include <map>
#include <string>

#include "discretisation/discrete_system.hpp"
#include "verification/error_norm.hpp"
#include "verification/reference_context.hpp"

namespace flowmpm {

struct UniformStressReference {
  static constexpr const char* type_name = "uniform_stress";
  int component = 0;
  double value = 0.0;  // Pa
  double rms = 0.0, max = 0.0;

  static UniformStressReference read(ParameterTable& t, const ReferenceContext&) {
    UniformStressReference r;
    const std::vector<std::string> names(voigt_component_names.begin(), voigt_component_names.end());
    const std::string component = t.choice("component", names);
    r.component = static_cast<int>(std::ranges::find(names, component) - names.begin());
    r.value = t.number("value");
    t.require(r.value != 0.0, "value", "the expected stress in Pa, not 0");
    return r;
  }

  template <int D, class Shape>
  void initialise(DiscreteSystem<D, Shape>&) const {}

  template <int D, class Shape>
  void sample(const DiscreteSystem<D, Shape>& system) {
    RmsError error;
    max = 0.0;
    for (const auto& b : system.batches) {
      if (b.body != 0) continue;
      for (std::size_t p = 0; p < b.size(); ++p) {
        const double e = b.stress[p][component] - value;
        error.add(b.mass[p], e);
        max = std::max(max, std::abs(e));
      }
    }
    rms = error.relative_to(std::abs(value));
  }

  // The last sample (Reference::visit_state).
  template <class F>
  void visit_state(F&& f) {
    f("rms", rms);
    f("max", max);
  }

  std::map<std::string, double> errors() const { return {{"stress", rms}, {"stress_max", max / std::abs(value)}}; }
};

}  // namespace flowmpm
