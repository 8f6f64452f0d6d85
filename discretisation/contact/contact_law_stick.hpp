// Contact law "stick": the two bodies share one velocity wherever both carry
// mass at a node, as in a single velocity field (they never separate). The
// default between fields no [[contacts]] entry pairs.
#pragma once
#include "core/parameter_table.hpp"
#include "core/vec.hpp"

namespace flowmpm {

struct StickLaw {
  static constexpr const char* type_name = "stick";
  // Applied at every node both fields share, touching or not.
  static constexpr bool detects_contact = false;

  static StickLaw read(ParameterTable&) { return {}; }

  // The first field's velocity change at a shared node: r its velocity
  // relative to the pair's centre of mass (to a rigid body's), n the unit
  // normal out of it. Sticking takes the whole relative velocity.
  template <int D>
  Vec<D> velocity_change(const Vec<D>& r, const Vec<D>&) const {
    return -r;
  }
};

}  // namespace flowmpm
