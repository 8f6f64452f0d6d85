// A rigid flat punch of width B pressed into a perfectly plastic von Mises
// body in plane strain: Prandtl's limit pressure on a weightless
// rigid-plastic half-space under a smooth punch,
//   p = (2 + pi) k,  k = sigma_Y / sqrt(3)  ([Hill 1950], ch. VIII),
// the body's yield stress sigma_Y. The pressure is the vertical force of
// the body on the punch per unit thickness (its reaction) over B, at the
// last sample (the case ends at the travel it measures). Error:
// pressure = |p_h - p| / p. Measures: pressure (Pa) and limit (Pa).
#pragma once
#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <string>

#include "materials/von_mises.hpp"
#include "verification/reference_context.hpp"

namespace flowmpm {

struct PrandtlPunch {
  static constexpr const char* type_name = "prandtl_punch";
  std::string punch;      // the rigid body's name
  double width = 0.0;     // B (m)
  double limit = 0.0;     // (2 + pi) k (Pa)
  double pressure = 0.0;  // at the last sample (Pa)

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
    const auto contact = std::ranges::find_if(s.contacts, [&](const ContactSpec& c) {
      return s.bodies[c.first].name == r.punch || s.bodies[c.second].name == r.punch;
    });
    const int body = s.bodies[contact->first].name == r.punch ? contact->second : contact->first;
    const auto* m = std::get_if<VonMises>(&s.materials.at(s.bodies.at(body).material).model);
    t.require(m && m->parameters.hardening == VonMises::Hardening::linear && m->parameters.hardening_modulus == 0.0,
              "punch", "a punch in contact with a perfectly plastic von_mises body (hardening_modulus = 0)");
    r.limit = (2.0 + std::numbers::pi) * m->parameters.yield_stress / std::sqrt(3.0);
    return r;
  }

  template <int D, class Shape>
  void initialise(DiscreteSystem<D, Shape>&) const {}

  template <int D, class Shape>
  void sample(const DiscreteSystem<D, Shape>& system) {
    if constexpr (D == 2) {
      for (const RigidMotion<D>& r : system.contact->rigid)
        if (r.name == punch) pressure = r.force[1] / width;
    }
  }

  template <class F>
  void visit_state(F&& f) {
    f("pressure", pressure);
  }

  std::map<std::string, double> errors() const { return {{"pressure", std::abs(pressure - limit) / limit}}; }
  std::map<std::string, double> measures() const { return {{"pressure", pressure}, {"limit", limit}}; }
};

}  // namespace flowmpm
