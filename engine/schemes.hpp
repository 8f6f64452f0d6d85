// The registry of schemes: each is a name and a wiring of the stage nodes
// (engine/step_graph.hpp). Adding a scheme is one entry in schemes.cpp.
//   USF:  p2g_momentum -> grid_velocity -> g2p_stress -> p2g_force -> grid_integrate -> g2p_motion
//   USL:  p2g_momentum & p2g_force -> grid_velocity -> grid_integrate -> g2p_motion & g2p_stress
//   MUSL: p2g_momentum & p2g_force -> grid_velocity -> grid_integrate -> g2p_motion -> remap
//         -> grid_velocity -> g2p_stress
#pragma once
#include <string>
#include <string_view>
#include <vector>

#include "engine/step_graph.hpp"

namespace flowmpm {

struct Scheme {
  std::string name;   // the case file's analysis.scheme, "usl"
  std::string label;  // for people, "USL"
  Wiring wiring;
  // The stress update takes the grid velocity after its update (USL), not
  // one mapped from the particles (USF, MUSL): the shape functions' limit
  // stable_factor_usl applies, else stable_factor_remapped.
  bool stress_from_updated_grid;
};

const std::vector<Scheme>& schemes();
std::vector<std::string> scheme_names();
// The scheme called `name`; throws std::invalid_argument listing the known ones.
const Scheme& scheme_named(std::string_view name);

// `wiring` with a nonlocal_settle node right after the node that runs
// g2p_stress, before whatever followed it (tasks/nonlocal_settle.hpp): for
// a scene whose models ask for nonlocal averages.
Wiring with_nonlocal_settle(Wiring wiring);

}  // namespace flowmpm
