// The registry of contact laws, chosen by the `law` of a [[contacts]] table
// (docs/guide/contact.md). Each law has
//   static constexpr const char* type_name;
//   static constexpr bool detects_contact;  // false: applied wherever both fields have mass
//   static Law read(ParameterTable&);
//   template <int D> Vec<D> velocity_change(r, n) const;
// the velocity change of the first field of a pair at a node where they
// touch and approach (tasks/contact.hpp); a law that acts by a force
// instead (the interface) has
//   template <int D> Vec<D> traction(jump, n) const;
//   template <int D> double energy(jump, n) const;
// and no velocity change. Adding one is one new file and one line in the
// variant below.
#pragma once
#include <type_traits>
#include <variant>

#include "core/registry.hpp"
#include "discretisation/contact/contact_law_coulomb.hpp"
#include "discretisation/contact/contact_law_frictionless.hpp"
#include "discretisation/contact/contact_law_interface.hpp"
#include "discretisation/contact/contact_law_stick.hpp"

namespace flowmpm {

using ContactLaw = std::variant<StickLaw, FrictionlessLaw, CoulombLaw, InterfaceLaw>;
using ContactLaws = Registry<ContactLaw>;

// Whether `law` acts only where the bodies touch and approach.
inline bool detects_contact(const ContactLaw& law) {
  return std::visit([](const auto& l) { return std::decay_t<decltype(l)>::detects_contact; }, law);
}

// Whether `law` is the interface, which acts by a force from the
// displacement jump (tasks/contact_bonds.hpp) and changes no velocity itself.
inline bool is_interface(const ContactLaw& law) { return std::holds_alternative<InterfaceLaw>(law); }

// The first body's velocity change by `law` for its relative velocity r
// and the unit normal n out of it (tasks/contact.hpp, tasks/wall.hpp): a
// law that detects contact acts only on approach, r . n > 0 (separating
// or sliding apart is free); stick acts everywhere; the interface gives
// none (its force is applied by tasks/contact_bonds.hpp).
template <int D>
Vec<D> contact_velocity_change(const ContactLaw& law, const Vec<D>& r, const Vec<D>& n) {
  return std::visit(
      [&](const auto& l) -> Vec<D> {
        using Law = std::decay_t<decltype(l)>;
        if constexpr (std::is_same_v<Law, InterfaceLaw>) {
          return Vec<D>::Zero();
        } else {
          if constexpr (Law::detects_contact)
            if (!(r.dot(n) > 0.0)) return Vec<D>::Zero();
          return l.velocity_change(r, n);
        }
      },
      law);
}

}  // namespace flowmpm
