// [[contacts]]: pairs of bodies in contact and the law between them
// (discretisation/contact/contact_fields.hpp, docs/guide/contact.md).
#include <algorithm>
#include <string>
#include <vector>

#include "core/registry.hpp"
#include "discretisation/nonlocal/nonlocal_average.hpp"
#include "io/case/case_reader.hpp"
#include "io/case/case_sections.hpp"

namespace flowmpm {

void read_contact(TableReader t, SystemSpec& c) {
  ContactSpec contact;
  contact.where = t.where("");
  std::vector<std::string> known;
  for (const BodySpec& b : c.bodies) known.push_back(b.name);
  const std::vector<std::string> names = t.strings("bodies");
  if (names.size() != 2) t.fail("bodies", "the names of two bodies, [\"a\", \"b\"]");
  int index[2];
  for (int i = 0; i < 2; ++i) {
    const auto it = std::ranges::find(known, names[static_cast<std::size_t>(i)]);
    if (it == known.end())
      t.fail("bodies", "names of bodies among " + quoted_list(known) + " (\"" + names[static_cast<std::size_t>(i)] + "\" is none)");
    index[i] = static_cast<int>(it - known.begin());
  }
  if (index[0] == index[1]) t.fail("bodies", "two different bodies");
  if (c.bodies[index[0]].rigid() && c.bodies[index[1]].rigid())
    t.fail("bodies", "at least one body that is not rigid (two rigid bodies do not act on each other)");
  for (const ContactSpec& other : c.contacts) {
    if (std::minmax(other.first, other.second) == std::minmax(index[0], index[1]))
      t.fail("bodies", "a pair of bodies not already in contact (" + other.where + ")");
  }
  contact.first = index[0];
  contact.second = index[1];
  contact.law = ContactLaws::read(t, "law");
  contact.touch_fraction = t.number_or("touch_fraction", contact.touch_fraction);
  t.require(contact.touch_fraction > 0.0 && contact.touch_fraction <= 1.0, "touch_fraction",
            "a fraction of a node's volume in (0, 1]");
  t.reject_unknown_keys();
  c.contacts.push_back(std::move(contact));
}

void check_rigid_bodies(TableReader& root, const SystemSpec& c) {
  for (std::size_t b = 0; b < c.bodies.size(); ++b) {
    if (!c.bodies[b].rigid()) continue;
    const int i = static_cast<int>(b);
    const bool named = std::ranges::any_of(c.contacts, [&](const ContactSpec& s) { return s.first == i || s.second == i; });
    if (!named) {
      throw CaseError(c.bodies[b].where + ": a rigid body acts only on the bodies a [[contacts]] table pairs it with, "
                      "and no contact names \"" + c.bodies[b].name + "\"");
    }
  }
  if (asks_nonlocal(c) && std::ranges::any_of(c.bodies, [](const BodySpec& b) { return b.rigid(); }))
    root.fail("contacts", "no rigid body in a scene whose material asks for nonlocal averages (not supported yet)");
}

}  // namespace flowmpm
