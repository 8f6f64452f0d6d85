// A body force per unit mass on one body (m/s^2 = N/kg per axis, each a
// number or [[t, value], ...]), added to gravity for that body's particles:
// f_I += sum_p N_Ip m_p b(t).
#pragma once
#include "discretisation/loads/load_context.hpp"

namespace flowmpm {

struct BodyForceLoad {
  static constexpr const char* type_name = "body_force";
  int body = 0;
  AxisFunctions acceleration;  // m/s^2

  static BodyForceLoad read(ParameterTable& t, const LoadReadContext& c) {
    BodyForceLoad l;
    l.body = read_body_name(t, "body", c, false);
    l.acceleration = read_axis_functions(t, "acceleration", c.dimension, "a body force per unit mass in m/s^2");
    return l;
  }

  template <int D, class Shape>
  void attach(LoadSite<D, Shape>& site) const {
    const std::string& body_name = site.body_names[body];
    site.system.loads.body.push_back(
        {"body force " + axis_functions_text(acceleration, "m/s^2") + " on body '" + body_name + "'", body, acceleration});
  }
};

}  // namespace flowmpm
