// The stages of one explicit step (README "How a step runs"). A scheme
// (engine/schemes.hpp) wires graph nodes, each running one stage or a
// group of stages in one pass over the particles.
#pragma once
#include <array>
#include <string>
#include <vector>

namespace flowmpm {

// nonlocal_settle is wired after g2p_stress only in a scene whose models ask
// for nonlocal averages (tasks/nonlocal_settle.hpp).
enum class Stage {
  p2g_momentum,
  p2g_force,
  grid_velocity,
  grid_integrate,
  g2p_motion,
  g2p_stress,
  remap,
  // Heat and solvent (tasks/transport.hpp), only in scenes that carry them.
  transport_p2g,
  transport_flux,
  transport_update,
  transport_g2p,
  nonlocal_settle,
};

inline constexpr std::array<const char*, 12> stage_names = {
    "p2g_momentum",  "p2g_force",      "grid_velocity",    "grid_integrate", "g2p_motion",     "g2p_stress",
    "remap",         "transport_p2g",  "transport_flux",   "transport_update", "transport_g2p", "nonlocal_settle"};

inline const char* stage_name(Stage s) { return stage_names[static_cast<std::size_t>(s)]; }

// The stages one graph node runs, in order, in one pass.
using StageGroup = std::vector<Stage>;

// "p2g_momentum & p2g_force".
inline std::string group_name(const StageGroup& group) {
  std::string name;
  for (Stage s : group) name += (name.empty() ? "" : " & ") + std::string(stage_name(s));
  return name;
}

}  // namespace flowmpm
