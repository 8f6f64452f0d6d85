// Thermal and solvent expansion ([NairnMPM] "Orthotropic Material"): along
// the material axes the expansion strain is
//   eps_expansion = alpha (T - T_ref) + beta c,
// and it takes no stress. What drives it: either a uniform function of time
// (temperature_change dT(t), concentration c(t): the shortcut), or, when the
// material conducts heat (diffuses solvent), each particle's own T - T_ref
// (c), which the engine passes in MaterialInput (tasks/transport.hpp).
#pragma once
#include <array>
#include <optional>

#include <Eigen/Core>

#include "core/time_function.hpp"
#include "core/voigt.hpp"
#include "materials/axis_values.hpp"
#include "materials/material_input.hpp"
#include "materials/transport_properties.hpp"

namespace flowmpm {

class ParameterTable;

struct Expansion {
  std::array<double, 3> alpha{};  // thermal expansion along material x, y, z (1/K)
  std::array<double, 3> beta{};   // solvent expansion (per unit weight fraction)
  bool thermal = false;           // alpha is given
  bool solvent = false;           // beta is given
  std::optional<TimeFunction> temperature_change;  // uniform dT(t) (K); absent: the particle's own
  std::optional<TimeFunction> concentration;       // uniform c(t); absent: the particle's own

  bool any() const { return thermal || solvent; }

  // T - T_ref and c at the end of the increment.
  double temperature_change_at(const MaterialInput& in) const {
    return temperature_change ? (*temperature_change)(in.t) : in.temperature_change;
  }
  double concentration_at(const MaterialInput& in) const {
    return concentration ? (*concentration)(in.t) : in.concentration;
  }

  // alpha dT + beta c along the material axes.
  Eigen::Vector3d strain_for(double dT, double c) const {
    Eigen::Vector3d th = Eigen::Vector3d::Zero();
    if (thermal)
      for (int i = 0; i < 3; ++i) th[i] += alpha[i] * dT;
    if (solvent)
      for (int i = 0; i < 3; ++i) th[i] += beta[i] * c;
    return th;
  }

  // The expansion strain at the end of the increment.
  Eigen::Vector3d strain(const MaterialInput& in) const {
    return strain_for(temperature_change_at(in), concentration_at(in));
  }

  // At its start. The first increment starts from the stress-free state
  // (T_ref, c = 0), as the total form does: a uniform function then counts
  // its value at t = 0, a particle its initial offset (MaterialInput).
  Eigen::Vector3d strain_at_start(const MaterialInput& in) const {
    return strain_for(temperature_change ? at_start(*temperature_change, in) : in.temperature_change - in.temperature_step,
                      concentration ? at_start(*concentration, in) : in.concentration - in.concentration_step);
  }

  // The isotropic increment alpha d(T - T_ref) + beta dc over the increment,
  // for the rate-form isotropic models.
  double isotropic_step(const MaterialInput& in) const {
    const double dT = temperature_change ? (*temperature_change)(in.t) - at_start(*temperature_change, in)
                                         : in.temperature_step;
    const double dc = concentration ? (*concentration)(in.t) - at_start(*concentration, in) : in.concentration_step;
    return strain_for(dT, dc)[0];
  }

  // Calls update() with deps the mechanical increment d eps - th I of an
  // isotropic rate-form model, th = isotropic_step (the expansion takes no
  // stress), and restores the total increment after it.
  template <class Update>
  [[gnu::always_inline]] void with_mechanical_increment(Voigt& deps, const MaterialInput& in, Update&& update) const {
    if (!any()) return update();
    const double th = isotropic_step(in);
    for (int i = 0; i < 3; ++i) deps[i] -= th;
    update();
    for (int i = 0; i < 3; ++i) deps[i] += th;
  }

  // The work done per unit volume by the isotropic expansion over the
  // increment against the stress sigma (J/m^3): -tr(sigma) th.
  double isotropic_work(const Voigt& sigma, const MaterialInput& in) const {
    if (!any()) return 0.0;
    return -(sigma[0] + sigma[1] + sigma[2]) * isotropic_step(in);
  }

  // A uniform function's value at the start of the increment; 0, the
  // stress-free state, before the first.
  static double at_start(const TimeFunction& f, const MaterialInput& in) {
    const double start = in.t - in.dt;
    return start > 0.0 ? f(start) : 0.0;
  }

  // Reads `alpha` with its driver and `beta` with its, laid out per
  // `layout`. Each coefficient needs exactly one driver: the uniform
  // function (temperature_change, concentration) or the material's own
  // transport (a conductivity with reference_temperature; a diffusivity).
  static Expansion read(ParameterTable& t, const AxisLayout& layout, const TransportProperties& transport);
};

}  // namespace flowmpm
