#include "engine/schemes.hpp"

#include <algorithm>
#include <stdexcept>

#include "core/registry.hpp"

namespace flowmpm {
namespace {

// A chain of nodes; `heads` all feed the first element of `chain`.
Wiring chain(std::vector<StageGroup> heads, std::vector<StageGroup> chain) {
  Wiring w;
  w.nodes = heads;
  const int first = static_cast<int>(w.nodes.size());
  w.nodes.insert(w.nodes.end(), chain.begin(), chain.end());
  for (int h = 0; h < first; ++h) w.edges.emplace_back(h, first);
  for (int i = first; i + 1 < static_cast<int>(w.nodes.size()); ++i) w.edges.emplace_back(i, i + 1);
  return w;
}

}  // namespace

const std::vector<Scheme>& schemes() {
  using enum Stage;
  static const std::vector<Scheme> table = {
      {"usf", "USF",
       chain({{p2g_momentum}}, {{grid_velocity}, {g2p_stress}, {p2g_force}, {grid_integrate}, {g2p_motion}})},
      {"usl", "USL", chain({{p2g_momentum, p2g_force}}, {{grid_velocity}, {grid_integrate}, {g2p_motion, g2p_stress}})},
      {"musl", "MUSL",
       chain({{p2g_momentum, p2g_force}},
             {{grid_velocity}, {grid_integrate}, {g2p_motion}, {remap}, {grid_velocity}, {g2p_stress}})},
  };
  return table;
}

Wiring with_transport(const Wiring& mechanical, TransportBranch branch) {
  using enum Stage;
  Wiring w = mechanical;
  const int first = static_cast<int>(w.nodes.size());
  for (Stage s : {transport_p2g, transport_flux, transport_update, transport_g2p}) w.nodes.push_back({s});
  for (int i = first; i + 1 < static_cast<int>(w.nodes.size()); ++i) w.edges.emplace_back(i, i + 1);
  const int last = static_cast<int>(w.nodes.size()) - 1;
  auto writes_particles = [](const StageGroup& g) {
    return std::ranges::any_of(g, [](Stage s) { return s == g2p_motion || s == g2p_stress; });
  };
  if (branch == TransportBranch::before) {
    // The transport chain first, then every node that starts the mechanics.
    std::vector<bool> has_predecessor(mechanical.nodes.size(), false);
    for (auto [from, to] : mechanical.edges) has_predecessor[to] = true;
    for (int i = 0; i < first; ++i)
      if (!has_predecessor[i]) w.edges.emplace_back(last, i);
    return w;
  }
  for (int i : mechanical.topological_order()) {
    if (writes_particles(mechanical.nodes[i])) {
      w.edges.emplace_back(last, i);
      return w;
    }
  }
  throw std::logic_error("the wiring has no g2p stage for the transport branch to join before");
}

namespace {

// Inserts a node running `stage` right after node `after`: it takes over
// `after`'s outgoing edges. Returns its index.
int insert_after(Wiring& w, int after, Stage stage) {
  const int node = static_cast<int>(w.nodes.size());
  w.nodes.push_back({stage});
  for (auto& [from, to] : w.edges)
    if (from == after) from = node;
  w.edges.emplace_back(after, node);
  return node;
}

// Inserts a node running `stage` right before node `before`: it takes over
// `before`'s incoming edges. Returns its index.
int insert_before(Wiring& w, int before, Stage stage) {
  const int node = static_cast<int>(w.nodes.size());
  w.nodes.push_back({stage});
  for (auto& [from, to] : w.edges)
    if (to == before) to = node;
  w.edges.emplace_back(node, before);
  return node;
}

bool runs(const StageGroup& g, Stage s) { return std::ranges::find(g, s) != g.end(); }

}  // namespace

Wiring with_contact(const Wiring& wiring, bool bonded) {
  using enum Stage;
  Wiring w = wiring;
  std::vector<int> contact_nodes;
  const int count = static_cast<int>(wiring.nodes.size());
  for (int i = 0; i < count; ++i) {
    if (runs(wiring.nodes[i], grid_integrate)) {
      contact_nodes.push_back(insert_after(w, i, contact_updated));
      if (bonded) contact_nodes.push_back(insert_before(w, i, contact_bonds));
    }
    if (runs(wiring.nodes[i], grid_velocity)) contact_nodes.push_back(insert_after(w, i, contact_projected));
  }
  const int volumes = static_cast<int>(w.nodes.size());
  w.nodes.push_back({contact_volumes});
  for (int node : contact_nodes) w.edges.emplace_back(volumes, node);
  return w;
}

std::vector<std::string> scheme_names() {
  std::vector<std::string> names;
  for (const Scheme& s : schemes()) names.push_back(s.name);
  return names;
}

const Scheme& scheme_named(std::string_view name) {
  for (const Scheme& s : schemes())
    if (s.name == name) return s;
  throw std::invalid_argument("unknown scheme \"" + std::string(name) + "\"; known: " + quoted_list(scheme_names()));
}

Wiring with_nonlocal_settle(Wiring wiring) {
  const auto stress = std::ranges::find_if(
      wiring.nodes, [](const StageGroup& g) { return std::ranges::find(g, Stage::g2p_stress) != g.end(); });
  if (stress == wiring.nodes.end()) throw std::logic_error("a wiring without g2p_stress");
  const int after = static_cast<int>(stress - wiring.nodes.begin());
  const int settle = static_cast<int>(wiring.nodes.size());
  wiring.nodes.push_back({Stage::nonlocal_settle});
  for (auto& [from, to] : wiring.edges)
    if (from == after) from = settle;
  wiring.edges.emplace_back(after, settle);
  return wiring;
}

}  // namespace flowmpm
