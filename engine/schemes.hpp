// The registry of schemes: each is a name and a wiring of the stage nodes
// (engine/step_graph.hpp). Adding a scheme is one entry in schemes.cpp.
//   USF:  p2g_momentum -> grid_velocity -> g2p_stress -> p2g_force -> grid_integrate -> g2p_motion
//   USL:  p2g_momentum & p2g_force -> grid_velocity -> grid_integrate -> g2p_motion & g2p_stress
//   MUSL: p2g_momentum & p2g_force -> grid_velocity -> grid_integrate -> g2p_motion -> remap
//         -> grid_velocity -> g2p_stress
// A scene with heat or solvent transport adds a branch (with_transport).
#pragma once
#include <algorithm>
#include <string>
#include <string_view>
#include <vector>

#include "discretisation/system_spec.hpp"
#include "engine/step_graph.hpp"

namespace flowmpm {

struct Scheme {
  std::string name;   // the case file's analysis.scheme, "usl"
  std::string label;  // for people, "USL"
  Wiring wiring;
};

const std::vector<Scheme>& schemes();
std::vector<std::string> scheme_names();
// The scheme called `name`; throws std::invalid_argument listing the known ones.
const Scheme& scheme_named(std::string_view name);

// Where the transport stages (tasks/transport.hpp) run in a step.
enum class TransportBranch {
  beside,  // a branch of the graph concurrent with the momentum stages
  before,  // one after the other: the transport chain, then the mechanics (for the bench)
};

// The wiring of a step that also conducts heat or diffuses solvent: the
// mechanical wiring plus the chain
//   transport_p2g -> transport_flux -> transport_update -> transport_g2p,
// which starts with the step and joins before the mechanical wiring's first
// node that writes particles (a g2p stage). The transport passes read the
// particles' positions, volumes and material axes, which only that node
// changes, and write transport fields that no momentum stage reads; the
// stress update then sees the new temperature and concentration.
Wiring with_transport(const Wiring& mechanical, TransportBranch branch = TransportBranch::beside);

// `wiring` with the contact stages (tasks/contact.hpp): contact_updated
// after each grid_integrate, contact_projected after each grid_velocity, with
// an interface (`bonded`) contact_bonds right before each grid_integrate
// (tasks/contact_bonds.hpp), and contact_volumes, with no predecessor,
// before every contact node.
Wiring with_contact(const Wiring& wiring, bool bonded = false);

// The wiring a system runs: the scheme's, with the contact stages only when
// the scene has contacts, and the transport branch only when it conducts
// heat or diffuses solvent.
inline Wiring step_wiring(const Wiring& mechanical, const SystemSpec& spec,
                          TransportBranch branch = TransportBranch::beside) {
  const bool bonded = std::ranges::any_of(spec.contacts, [](const ContactSpec& c) { return is_interface(c.law); });
  const Wiring w = spec.contacts.empty() ? mechanical : with_contact(mechanical, bonded);
  return spec.conducts_heat() || spec.diffuses_solvent() ? with_transport(w, branch) : w;
}

// `wiring` with a nonlocal_settle node right after the node that runs
// g2p_stress, before whatever followed it (tasks/nonlocal_settle.hpp): for
// a scene whose models ask for nonlocal averages.
Wiring with_nonlocal_settle(Wiring wiring);

}  // namespace flowmpm
