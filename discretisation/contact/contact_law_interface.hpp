// Contact law "interface": an imperfect interface, the two bodies bonded by
// linear springs per unit area ([Nairn 2013]; NairnMPM's "Linear Imperfect
// Interface"): the traction on the first body is
//   t = D_n [u]_n n + D_t [u]_t,   [u] = u_b - u_a,
// [u]_n = [u] . n and [u]_t = [u] - [u]_n n, n the unit normal out of the
// first body, u each body's displacement since t = 0; it stores the energy
// (D_n [u]_n^2 + D_t |[u]_t|^2) / 2 per unit area. Bonded: it acts
// wherever both bodies carry mass at a node, in tension and in compression
// alike (NairnMPM hands the normal in compression to contact instead),
// never lets go, and changes no velocity by itself: it is a force added to
// the nodal forces (tasks/contact_bonds.hpp). D = 0 is no bond; a large D
// approaches a perfect one while D h stays below the bodies' stiffness
// (docs/theory/contact.md).
#pragma once
#include "core/parameter_table.hpp"
#include "core/vec.hpp"

namespace flowmpm {

struct InterfaceLaw {
  static constexpr const char* type_name = "interface";
  static constexpr bool detects_contact = false;
  double normal_stiffness = 0.0;      // D_n (Pa/m)
  double tangential_stiffness = 0.0;  // D_t (Pa/m)

  static InterfaceLaw read(ParameterTable& t) {
    InterfaceLaw law;
    law.normal_stiffness = t.number("normal_stiffness");
    t.require(law.normal_stiffness >= 0.0, "normal_stiffness", "an interface stiffness D_n >= 0 in Pa/m");
    law.tangential_stiffness = t.number("tangential_stiffness");
    t.require(law.tangential_stiffness >= 0.0, "tangential_stiffness", "an interface stiffness D_t >= 0 in Pa/m");
    return law;
  }

  // The traction on the first body (Pa) for the jump [u] (m) and the unit
  // normal n out of it.
  template <int D>
  Vec<D> traction(const Vec<D>& jump, const Vec<D>& n) const {
    const double jn = jump.dot(n);
    return normal_stiffness * jn * n + tangential_stiffness * (jump - jn * n);
  }

  // The energy stored per unit area (J/m^2).
  template <int D>
  double energy(const Vec<D>& jump, const Vec<D>& n) const {
    const double jn = jump.dot(n);
    return 0.5 * (normal_stiffness * jn * jn + tangential_stiffness * (jump - jn * n).squaredNorm());
  }
};

}  // namespace flowmpm
