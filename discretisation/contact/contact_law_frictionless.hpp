// Contact law "frictionless": where the bodies touch and approach, the
// normal part of their relative velocity is taken away; the tangential
// part is free, and separation is free (Bardenhagen, Brackbill and Sulsky
// 2000).
#pragma once
#include "core/parameter_table.hpp"
#include "core/vec.hpp"

namespace flowmpm {

struct FrictionlessLaw {
  static constexpr const char* type_name = "frictionless";
  static constexpr bool detects_contact = true;

  static FrictionlessLaw read(ParameterTable&) { return {}; }

  // r: the first field's velocity relative to the centre of mass, n the
  // unit normal out of it; called only where r . n > 0 (approach).
  template <int D>
  Vec<D> velocity_change(const Vec<D>& r, const Vec<D>& n) const {
    return -r.dot(n) * n;
  }
};

}  // namespace flowmpm
