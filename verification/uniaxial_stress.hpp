// The uniaxial stress benchmark (CB-Geo's mpm-benchmarks, "Uniaxial
// stress"; docs/REFERENCES.md): a block of length L loaded along `axis` at
// velocity v0 on one face, the opposite face held. At time t:
//   eps_a = v0 t / L,  sigma_a = E eps_a,  eps_l = -nu eps_a,  sigma_l = 0.
// Errors at the last sample, from the first body's volume-weighted means,
// relative to |sigma_a| and |eps_a|, |eps_l|:
//   axial_stress, lateral_stress, axial_strain, lateral_strain.
// Amplitude: no small-strain floor. The loaded face is a grid node at a
// fixed place, so the material moves with the grid's affine velocity field
// at the constant rate of deformation v0 / L, and the engine's strain (the
// time integral of that rate, docs/theory/kinematics.md) is v0 t / L = eps_a at
// any amplitude (the material's stretch is exp(v0 t / L)); the stress of
// the linear elastic rate form follows it exactly.
#pragma once
#include <cmath>
#include <map>
#include <string>

#include "engine/diagnostics.hpp"
#include "verification/reference_context.hpp"

namespace flowmpm {

struct UniaxialStress {
  static constexpr const char* type_name = "uniaxial_stress";
  int axis = 0;
  double length = 0.0, v0 = 0.0;
  double E = 0.0, nu = 0.0, t = 0.0;
  BodyMeans means;  // of the first body, at the last sample

  static UniaxialStress read(ParameterTable& table, const ReferenceContext& context) {
    UniaxialStress r;
    r.axis = read_axis(table, "axis", context.system.dimension);
    r.length = table.positive("length", "the block length along the axis in m");
    r.v0 = table.number("velocity");
    table.require(r.v0 != 0.0, "velocity", "the loading velocity in m/s, not 0");
    const LinearElastic& m = elastic_material(table, context);
    r.E = m.parameters.youngs_modulus;
    r.nu = m.parameters.poisson_ratio;
    return r;
  }

  template <int D, class Shape>
  void initialise(DiscreteSystem<D, Shape>&) const {}

  template <int D, class Shape>
  void sample(const DiscreteSystem<D, Shape>& system) {
    means = diagnostics(system, system.batches.size()).bodies.at(0);
    t = system.t;
  }

  // The last sample (Reference::visit_state).
  template <class F>
  void visit_state(F&& f) {
    f("means", means);
    f("t", t);
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
