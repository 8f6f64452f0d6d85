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

  // alpha (T - T_ref) + beta c along the material axes, at the end of the increment.
  Eigen::Vector3d strain(const MaterialInput& in) const {
    Eigen::Vector3d th = Eigen::Vector3d::Zero();
    if (thermal) {
      const double dT = temperature_change_at(in);
      for (int i = 0; i < 3; ++i) th[i] += alpha[i] * dT;
    }
    if (solvent) {
      const double c = concentration_at(in);
      for (int i = 0; i < 3; ++i) th[i] += beta[i] * c;
    }
    return th;
  }

  // The changes of T - T_ref and of c over the increment.
  double temperature_step_of(const MaterialInput& in) const {
    return temperature_change ? (*temperature_change)(in.t) - (*temperature_change)(in.t - in.dt)
                              : in.temperature_step;
  }
  double concentration_step_of(const MaterialInput& in) const {
    return concentration ? (*concentration)(in.t) - (*concentration)(in.t - in.dt) : in.concentration_step;
  }

  // The change of the expansion strain over the increment, alpha d(T - T_ref)
  // + beta dc along the material axes.
  Eigen::Vector3d strain_step(const MaterialInput& in) const {
    Eigen::Vector3d step = Eigen::Vector3d::Zero();
    if (thermal) {
      const double dT = temperature_step_of(in);
      for (int i = 0; i < 3; ++i) step[i] += alpha[i] * dT;
    }
    if (solvent) {
      const double dc = concentration_step_of(in);
      for (int i = 0; i < 3; ++i) step[i] += beta[i] * dc;
    }
    return step;
  }

  // Its isotropic value, for the rate-form isotropic models.
  double isotropic_step(const MaterialInput& in) const { return strain_step(in)[0]; }

  // The work done per unit volume by the isotropic expansion over the
  // increment against the stress sigma (J/m^3): -tr(sigma) th.
  double isotropic_work(const Voigt& sigma, const MaterialInput& in) const {
    if (!any()) return 0.0;
    return -(sigma[0] + sigma[1] + sigma[2]) * isotropic_step(in);
  }

  // Reads `alpha` with its driver and `beta` with its, laid out per
  // `layout`. Each coefficient needs exactly one driver: the uniform
  // function (temperature_change, concentration) or the material's own
  // transport (a conductivity with reference_temperature; a diffusivity).
  static Expansion read(ParameterTable& t, const AxisLayout& layout, const TransportProperties& transport);
};

}  // namespace flowmpm
