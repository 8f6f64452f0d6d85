// Thermal stress at the end of a run, against steady-state closed forms
// ([Timoshenko 1970], thermal stress): a linear_elastic body with an
// isotropic alpha whose temperature is conducted from two faces along
// `axis`, X = x_axis - from in [0, L], held at T_a (X = 0) and T_b (X = L)
// (node sets of the case, ramped slowly so that the mechanics stays
// quasi-static). At steady state T = T_a + (T_b - T_a) X / L at the
// particles' current positions (the held planes are grid planes, the body
// expands across them) and
//  - ends = "held": a 1D bar (uniaxial stress) whose ends do not move:
//    sigma_xx = -E alpha ((T_a + T_b) / 2 - T_ref), uniform;
//  - ends = "free": a free body; a linear temperature field gives a
//    compatible thermal strain, so the body is stress free (in 2D plane
//    stress or 3D; a free bar heated on one side bends without stress).
// Errors at the last sample, over the particles (mass-weighted RMS):
// `stress` (every component against the closed form, relative to
// E alpha dT) and `temperature` (relative to dT), with dT the largest of
// |T_a - T_ref|, |T_b - T_ref| and |T_b - T_a|.
#pragma once
#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "discretisation/discrete_system.hpp"
#include "verification/error_norm.hpp"
#include "verification/reference_context.hpp"

namespace flowmpm {

// The first body's linear_elastic material, which must expand with the
// conducted temperature (alpha with reference_temperature and a conductivity).
inline const LinearElastic& thermoelastic_material(ParameterTable& t, const ReferenceContext& context) {
  const LinearElastic& m = elastic_material(t, context);
  const Expansion& e = m.parameters.expansion;
  if (!e.thermal || e.temperature_change || !m.transport().conducts()) {
    t.fail("type", "a first body whose linear_elastic material conducts heat and expands with it "
                   "(conductivity, alpha, reference_temperature)");
  }
  return m;
}

struct ThermalStress {
  static constexpr const char* type_name = "thermal_stress";
  bool held = true;
  int axis = 0;
  double from = 0.0, length = 0.0, T_a = 0.0, T_b = 0.0;
  double E = 0.0, alpha = 0.0, T_ref = 0.0;
  RmsError stress, temperature;

  static ThermalStress read(ParameterTable& t, const ReferenceContext& context) {
    const SystemSpec& s = context.system;
    ThermalStress r;
    r.held = t.choice("ends", {"held", "free"}) == "held";
    if (r.held) t.require(s.dimension == 1, "ends", "\"free\" outside 1D (a held bar is 1D, uniaxial stress)");
    if (!r.held) {
      t.require(s.dimension != 2 || s.plane_stress, "ends",
                "\"held\" in plane strain (a free body is stress free only in plane stress, 1D or 3D)");
    }
    r.axis = read_axis(t, "axis", s.dimension);
    r.from = t.number("from");
    r.length = t.positive("length", "the distance between the held faces in m");
    const std::vector<double> faces = t.numbers("face_temperatures", 2);
    r.T_a = faces[0];
    r.T_b = faces[1];
    const LinearElastic& m = thermoelastic_material(t, context);
    r.E = m.parameters.youngs_modulus;
    r.alpha = m.parameters.expansion.alpha[0];
    r.T_ref = *m.transport().reference_temperature;
    t.require(r.temperature_scale() > 0.0, "face_temperatures", "face temperatures other than reference_temperature");
    return r;
  }

  double temperature_scale() const {
    return std::max({std::abs(T_a - T_ref), std::abs(T_b - T_ref), std::abs(T_b - T_a)});
  }

  template <int D, class Shape>
  void initialise(DiscreteSystem<D, Shape>&) const {}

  // Keeps the last sample only.
  template <int D, class Shape>
  void sample(const DiscreteSystem<D, Shape>& system) {
    stress = {};
    temperature = {};
    const double sigma_held = -E * alpha * (0.5 * (T_a + T_b) - T_ref);
    for (const auto& b : system.batches) {
      for (std::size_t p = 0; p < b.size(); ++p) {
        const double X = b.x[p][axis] - from;
        temperature.add(b.mass[p], b.temperature[p] - (T_a + (T_b - T_a) * X / length));
        double squares = 0.0;
        for (int i = 0; i < 6; ++i) {
          const double exact = held && i == 0 ? sigma_held : 0.0;
          squares += (b.stress[p][i] - exact) * (b.stress[p][i] - exact);
        }
        stress.add(b.mass[p], std::sqrt(squares));
      }
    }
  }

  // The last sample (Reference::visit_state).
  template <class F>
  void visit_state(F&& f) {
    f("stress", stress);
    f("temperature", temperature);
  }

  std::map<std::string, double> errors() const {
    return {{"stress", stress.relative_to(E * alpha * temperature_scale())},
            {"temperature", temperature.relative_to(temperature_scale())}};
  }
};

}  // namespace flowmpm
