// The uniaxial stress benchmark (seed 000): a block of length L loaded along
// `axis` at velocity v0 on one face, the opposite face held. At time t:
//   eps_a = v0 t / L,  sigma_a = E eps_a,  eps_l = -nu eps_a,  sigma_l = 0.
// Errors at the last sample, from the first body's volume-weighted means,
// relative to |sigma_a| and |eps_a|, |eps_l|:
//   axial_stress, lateral_stress, axial_strain, lateral_strain.
#pragma once
#include <map>
#include <string>

#include "engine/diagnostics.hpp"
#include "engine/reference/error_norm.hpp"
#include "io/case_file.hpp"

namespace flowmpm {

struct UniaxialStress {
  int axis;
  double length, v0;
  double E = 0.0, nu = 0.0, t = 0.0;
  BodyMeans means;  // of the first body, at the last sample

  explicit UniaxialStress(const ReferenceSpec& r) : axis(r.axis), length(r.length), v0(r.velocity) {}

  template <int D, class Shape>
  void initialise(Model<D, Shape>& model, double /*end_time*/) {
    const LinearElastic& m = elastic_material(model, "uniaxial_stress");
    E = m.parameters.youngs_modulus;
    nu = m.parameters.poisson_ratio;
  }

  template <int D, class Shape>
  void sample(const Model<D, Shape>& model) {
    means = diagnostics(model, model.batches.size()).bodies.at(0);
    t = model.t;
  }

  std::map<std::string, double> errors() const {
    const int lateral = axis == 0 ? 1 : 0;
    const double eps_a = v0 * t / length, sigma_a = E * eps_a, eps_l = -nu * eps_a;
    return {{"axial_stress", std::abs(means.stress[axis] - sigma_a) / std::abs(sigma_a)},
            {"lateral_stress", std::abs(means.stress[lateral]) / std::abs(sigma_a)},
            {"axial_strain", std::abs(means.strain[axis] - eps_a) / std::abs(eps_a)},
            {"lateral_strain", std::abs(means.strain[lateral] - eps_l) / std::abs(eps_l)}};
  }
};

}  // namespace flowmpm
