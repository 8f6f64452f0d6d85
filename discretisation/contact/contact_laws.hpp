// The registry of contact laws, chosen by the `law` of a [[contacts]] table
// (docs/guide/contact.md). Each law has
//   static constexpr const char* type_name;
//   static constexpr bool detects_contact;  // false: applied wherever both fields have mass
//   static Law read(ParameterTable&);
//   template <int D> Vec<D> velocity_change(r, n) const;
// the velocity change of the first field of a pair at a node where they
// touch and approach (tasks/contact.hpp). Adding one is one new file and
// one line in the variant below.
#pragma once
#include <variant>

#include "core/registry.hpp"
#include "discretisation/contact/contact_law_coulomb.hpp"
#include "discretisation/contact/contact_law_frictionless.hpp"
#include "discretisation/contact/contact_law_stick.hpp"

namespace flowmpm {

using ContactLaw = std::variant<StickLaw, FrictionlessLaw, CoulombLaw>;
using ContactLaws = Registry<ContactLaw>;

}  // namespace flowmpm
