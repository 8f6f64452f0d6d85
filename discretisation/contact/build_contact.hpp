// The contact component of a system (contact_fields.hpp) from the spec's
// contacts: field 0 for the bodies in no contact, then one field per
// deformable body in a contact (per contact group: its bodies share it),
// in body order, then one per rigid body.
#pragma once
#include <algorithm>

#include "discretisation/discrete_system.hpp"
#include "discretisation/system_spec.hpp"

namespace flowmpm {

template <int D, class Shape>
void build_contact(const SystemSpec& spec, DiscreteSystem<D, Shape>& system) {
  ContactFields<D>& contact = system.contact.emplace();
  std::vector<int> field_of(spec.bodies.size(), 0);
  std::vector<bool> in_contact(spec.bodies.size(), false);
  const auto group_of = [&](int b) { return spec.bodies[static_cast<std::size_t>(b)].contact_group; };
  for (const ContactSpec& c : spec.contacts) {
    for (int named : {c.first, c.second}) {
      for (std::size_t b = 0; b < spec.bodies.size(); ++b) {
        const bool same_group = group_of(named) >= 0 && group_of(static_cast<int>(b)) == group_of(named);
        if (static_cast<int>(b) == named || same_group) in_contact[b] = true;
      }
    }
  }
  int next = 1;
  std::vector<int> group_field(spec.contact_groups.size(), 0);
  for (std::size_t b = 0; b < spec.bodies.size(); ++b) {
    if (!in_contact[b] || spec.bodies[b].rigid()) continue;
    const int g = group_of(static_cast<int>(b));
    if (g < 0) {
      field_of[b] = next++;
    } else {
      if (group_field[static_cast<std::size_t>(g)] == 0) group_field[static_cast<std::size_t>(g)] = next++;
      field_of[b] = group_field[static_cast<std::size_t>(g)];
    }
  }
  const std::size_t nodes = system.grid.node_count();
  contact.deformable.resize(static_cast<std::size_t>(next - 1));
  for (NodalField<D>& f : contact.deformable) f.allocate(nodes);
  for (std::size_t b = 0; b < spec.bodies.size(); ++b) {
    if (!spec.bodies[b].rigid()) continue;
    field_of[b] = next++;
    contact.rigid.push_back({spec.bodies[b].name, *spec.bodies[b].rigid_velocity});
  }
  contact.fields = next;
  contact.volume.assign(static_cast<std::size_t>(next - 1), std::vector<double>(nodes, 0.0));
  contact.volume_gradient.resize(static_cast<std::size_t>(next - 1));
  for (auto& g : contact.volume_gradient)
    for (auto& component : g) component.assign(nodes, 0.0);
  contact.spread.resize(static_cast<std::size_t>(next - 1));
  for (auto& s : contact.spread) s.allocate(nodes);
  contact.spread_floor = 0.01 * system.grid.h.minCoeff() * system.grid.h.minCoeff();
  contact.pair_of.assign(static_cast<std::size_t>(next * next), -1);
  for (const ContactSpec& c : spec.contacts) {
    // The deformable body first (the second may be rigid).
    const bool swap = spec.bodies[c.first].rigid();
    const int first = field_of[swap ? c.second : c.first], second = field_of[swap ? c.first : c.second];
    ContactPair pair;
    pair.name = c.names[swap ? 1 : 0] + "~" + c.names[swap ? 0 : 1];
    pair.first = std::min(first, second);
    pair.second = std::max(first, second);
    pair.law = c.law;
    pair.touch_fraction = c.touch_fraction;
    contact.pair_of[static_cast<std::size_t>(pair.first * next + pair.second)] = static_cast<int>(contact.pairs.size());
    contact.pairs.push_back(std::move(pair));
  }
  contact.projected = contact.no_impulses();
  // The nodal displacements of the fields an interface bonds (both deformable).
  contact.displacement.resize(contact.deformable.size());
  for (const ContactPair& pair : contact.pairs) {
    if (!is_interface(pair.law)) continue;
    for (const int field : {pair.first, pair.second}) contact.displacement[static_cast<std::size_t>(field - 1)].allocate(nodes);
  }
  for (auto& batch : system.batches) batch.field = field_of[static_cast<std::size_t>(batch.body)];
}

}  // namespace flowmpm
