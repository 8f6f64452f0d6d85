// [[contact_groups]]: bodies that share one contact field; [[contacts]]:
// pairs of bodies or groups in contact and the law between them
// (discretisation/contact/contact_fields.hpp, docs/guide/contact.md).
#include <algorithm>
#include <string>
#include <vector>

#include "core/registry.hpp"
#include "discretisation/nonlocal/nonlocal_average.hpp"
#include "io/case/case_reader.hpp"
#include "io/case/case_sections.hpp"

namespace flowmpm {

void read_contact_group(TableReader t, SystemSpec& c) {
  const std::string name = t.string("name");
  std::vector<std::string> known;
  for (const BodySpec& b : c.bodies) known.push_back(b.name);
  if (std::ranges::find(known, name) != known.end() || std::ranges::find(c.contact_groups, name) != c.contact_groups.end())
    t.fail("name", "a name no body and no other contact group has");
  const std::vector<std::string> names = t.strings("bodies");
  if (names.size() < 2) t.fail("bodies", "the names of two or more bodies");
  const int group = static_cast<int>(c.contact_groups.size());
  for (const std::string& n : names) {
    const auto it = std::ranges::find(known, n);
    if (it == known.end()) t.fail("bodies", "names of bodies among " + quoted_list(known) + " (\"" + n + "\" is none)");
    BodySpec& body = c.bodies[static_cast<std::size_t>(it - known.begin())];
    if (body.rigid()) t.fail("bodies", "bodies that are not rigid (\"" + n + "\" is: it moves on its own)");
    if (body.contact_group >= 0) {
      t.fail("bodies", "bodies in no other contact group (\"" + n + "\" is in \"" +
                           c.contact_groups[static_cast<std::size_t>(body.contact_group)] + "\")");
    }
    body.contact_group = group;
  }
  t.reject_unknown_keys();
  c.contact_groups.push_back(name);
}

void read_contact(TableReader t, SystemSpec& c) {
  ContactSpec contact;
  contact.where = t.where("");
  std::vector<std::string> known;
  for (const BodySpec& b : c.bodies) known.push_back(b.name);
  std::vector<std::string> choices = known;
  choices.insert(choices.end(), c.contact_groups.begin(), c.contact_groups.end());
  const std::vector<std::string> names = t.strings("bodies");
  if (names.size() != 2) t.fail("bodies", "the names of two bodies or contact groups, [\"a\", \"b\"]");
  int index[2];
  for (int i = 0; i < 2; ++i) {
    const std::string& n = names[static_cast<std::size_t>(i)];
    const auto body = std::ranges::find(known, n);
    if (body != known.end()) {
      index[i] = static_cast<int>(body - known.begin());
      const int group = c.bodies[static_cast<std::size_t>(index[i])].contact_group;
      if (group >= 0) {
        t.fail("bodies", "the name of its contact group, \"" + c.contact_groups[static_cast<std::size_t>(group)] +
                             "\", for a body of a group (\"" + n + "\")");
      }
      continue;
    }
    const auto group = std::ranges::find(c.contact_groups, n);
    if (group == c.contact_groups.end())
      t.fail("bodies", "names of bodies or contact groups among " + quoted_list(choices) + " (\"" + n + "\" is none)");
    // A group is named by its first body (build_contact gives its bodies one field).
    const int g = static_cast<int>(group - c.contact_groups.begin());
    index[i] = static_cast<int>(std::ranges::find_if(c.bodies, [&](const BodySpec& b) { return b.contact_group == g; }) -
                                c.bodies.begin());
  }
  if (index[0] == index[1]) t.fail("bodies", "two different bodies or groups");
  if (c.bodies[index[0]].rigid() && c.bodies[index[1]].rigid())
    t.fail("bodies", "at least one body that is not rigid (two rigid bodies do not act on each other)");
  for (const ContactSpec& other : c.contacts) {
    if (std::minmax(other.first, other.second) == std::minmax(index[0], index[1]))
      t.fail("bodies", "a pair of bodies not already in contact (" + other.where + ")");
  }
  contact.first = index[0];
  contact.second = index[1];
  contact.names = {names[0], names[1]};
  contact.law = ContactLaws::read(t, "law");
  if (is_interface(contact.law)) {
    for (int i = 0; i < 2; ++i) {
      if (c.bodies[static_cast<std::size_t>(index[i])].rigid()) {
        t.fail("law", "\"stick\", \"frictionless\" or \"coulomb\" against a rigid body (\"" + names[static_cast<std::size_t>(i)] +
                          "\"): an interface bonds two deformable bodies");
      }
    }
    // Its displacement jump is measured from the particles' initial positions.
    c.keep_initial_positions = true;
  }
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
