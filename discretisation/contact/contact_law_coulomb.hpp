// Contact law "coulomb": where the bodies touch and approach, the normal
// part of the relative velocity is taken away, and the tangential part as
// far as friction allows: the bodies stick while the tangential impulse
// needed stays within mu times the normal one, and slip otherwise with the
// tangential impulse mu times the normal one, against the slip
// (Bardenhagen, Brackbill and Sulsky 2000, eqs. 12-15). Separation is free.
#pragma once
#include <cmath>

#include "core/parameter_table.hpp"
#include "core/vec.hpp"

namespace flowmpm {

struct CoulombLaw {
  static constexpr const char* type_name = "coulomb";
  static constexpr bool detects_contact = true;
  double friction = 0.0;  // mu, the coefficient of friction (-)

  static CoulombLaw read(ParameterTable& t) {
    CoulombLaw law;
    law.friction = t.number("friction");
    t.require(law.friction >= 0.0, "friction", "a coefficient of friction mu >= 0");
    return law;
  }

  // r: the first field's velocity relative to the centre of mass, n the
  // unit normal out of it; called only where r . n > 0 (approach). The
  // impulse per unit mass is -dn n - min(|t|, mu dn) t / |t|, dn = r . n,
  // t = r - dn n.
  template <int D>
  Vec<D> velocity_change(const Vec<D>& r, const Vec<D>& n) const {
    const double dn = r.dot(n);
    const Vec<D> t = r - dn * n;
    const double slip = t.norm();
    if (slip <= friction * dn) return -r;  // sticks
    return -dn * n - (friction * dn / slip) * t;
  }
};

}  // namespace flowmpm
