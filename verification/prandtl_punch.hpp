// A rigid flat punch (a strip footing) of width B pressed into a perfectly
// plastic body in plane strain: Prandtl's limit pressure on a weightless
// rigid-plastic half-space under a smooth punch,
//   p = c N_c,  N_c = (N_q - 1) cot phi,  N_q = exp(pi tan phi) tan^2(pi/4 + phi/2)
// ([Prandtl 1921] for N_c, [Reissner 1924] for N_q; N_c -> 2 + pi as phi -> 0,
// [Hill 1950] ch. VIII), with the body's cohesion c and friction angle phi:
//   - von_mises, perfectly plastic: phi = 0, c = k = sigma_Y / sqrt(3);
//   - mohr_coulomb with associated flow (dilation_angle = friction_angle);
//   - drucker_prager with the plane-strain fit and associated flow, which
//     in plane strain has Mohr-Coulomb's strength and flow.
// Prandtl's mechanism and its limit are the associated flow rule's. The
// pressure is the vertical force of the body on the punch per unit
// thickness (its reaction) over B, at the last sample (the case ends at the
// travel it measures), or its mean over the samples from `average_from`
// (s) on, where it wanders about its limit as particles cross cells.
// Error: pressure = |p_h - p| / p. Measures: pressure (Pa), limit (Pa)
// and N_c (-).
#pragma once
#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <string>

#include "materials/drucker_prager.hpp"
#include "materials/mohr_coulomb.hpp"
#include "materials/von_mises.hpp"
#include "verification/reference_context.hpp"

namespace flowmpm {

struct PrandtlPunch {
  static constexpr const char* type_name = "prandtl_punch";
  std::string punch;      // the rigid body's name
  double width = 0.0;     // B (m)
  double bearing = 0.0;   // N_c (-)
  double limit = 0.0;     // c N_c (Pa)
  double average_from = -1.0;  // s; < 0: the last sample alone
  double pressure = 0.0;       // at the last sample, or the mean since average_from (Pa)
  double sum = 0.0;            // of the pressures since average_from (Pa)
  double count = 0.0;          // of those samples

  static PrandtlPunch read(ParameterTable& t, const ReferenceContext& context) {
    const SystemSpec& s = context.system;
    PrandtlPunch r;
    std::vector<std::string> rigid;
    for (const BodySpec& b : s.bodies)
      if (b.rigid()) rigid.push_back(b.name);
    t.require(s.dimension == 2 && !s.plane_stress && !rigid.empty(), "type",
              "a 2D plane strain case with a rigid punch for prandtl_punch");
    r.punch = t.choice("punch", rigid);
    r.width = t.positive("width", "the punch's width B in m");
    if (t.has("average_from")) {
      r.average_from = t.number("average_from");
      t.require(r.average_from >= 0.0 && r.average_from < context.end_time, "average_from",
                "a time in s from 0 to before analysis.end_time");
    }
    const auto contact = std::ranges::find_if(s.contacts, [&](const ContactSpec& c) {
      return s.bodies[c.first].name == r.punch || s.bodies[c.second].name == r.punch;
    });
    const int body = s.bodies[contact->first].name == r.punch ? contact->second : contact->first;
    const auto& model = s.materials.at(s.bodies.at(body).material).model;
    double phi = -1.0, c = 0.0;  // phi < 0: no material the limit holds for
    if (const auto* m = std::get_if<VonMises>(&model)) {
      if (m->parameters.hardening == VonMises::Hardening::linear && m->parameters.hardening_modulus == 0.0)
        phi = 0.0, c = m->parameters.yield_stress / std::sqrt(3.0);
    } else if (const auto* m = std::get_if<MohrCoulomb>(&model)) {
      if (m->parameters.dilation_angle == m->parameters.friction_angle && !m->parameters.softening.on)
        phi = m->parameters.friction_angle, c = m->parameters.cohesion;
    } else if (const auto* m = std::get_if<DruckerPrager>(&model)) {
      if (m->parameters.dilation_angle == m->parameters.friction_angle &&
          m->parameters.fit == DruckerPrager::Fit::plane_strain)
        phi = m->parameters.friction_angle, c = m->parameters.cohesion;
    }
    t.require(phi >= 0.0 && c > 0.0, "punch",
              "a punch in contact with a perfectly plastic von_mises body (hardening_modulus = 0), or a mohr_coulomb "
              "body without softening or a plane_strain-fit drucker_prager body with cohesion > 0 and dilation_angle = friction_angle");
    r.bearing = bearing_capacity_factor(phi);
    r.limit = c * r.bearing;
    return r;
  }

  // N_c of friction angle phi (rad): (N_q - 1) cot phi, and 2 + pi at phi = 0.
  static double bearing_capacity_factor(double phi) {
    if (phi == 0.0) return 2.0 + std::numbers::pi;
    const double t = std::tan(std::numbers::pi / 4.0 + phi / 2.0);
    return (std::exp(std::numbers::pi * std::tan(phi)) * t * t - 1.0) / std::tan(phi);
  }

  template <int D, class Shape>
  void initialise(DiscreteSystem<D, Shape>&) const {}

  template <int D, class Shape>
  void sample(const DiscreteSystem<D, Shape>& system) {
    if constexpr (D == 2) {
      for (const RigidMotion<D>& r : system.contact->rigid) {
        if (r.name != punch) continue;
        pressure = r.force[1] / width;
        if (average_from >= 0.0 && system.t >= average_from) {
          sum += pressure, count += 1.0;
          pressure = sum / count;
        }
      }
    }
  }

  template <class F>
  void visit_state(F&& f) {
    f("pressure", pressure);
    f("pressure_sum", sum);
    f("pressure_count", count);
  }

  std::map<std::string, double> errors() const { return {{"pressure", std::abs(pressure - limit) / limit}}; }
  std::map<std::string, double> measures() const { return {{"pressure", pressure}, {"limit", limit}, {"N_c", bearing}}; }
};

}  // namespace flowmpm
