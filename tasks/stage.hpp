// The stages of one explicit step (docs/theory/step.md). A scheme
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
  // Contact (tasks/contact.hpp), only in scenes with contacts.
  contact_volumes,
  contact_projected,
  contact_updated,
  // The forces of imperfect interfaces (tasks/contact_bonds.hpp), only in
  // scenes with one.
  contact_bonds,
};

inline constexpr std::array<const char*, 16> stage_names = {
    "p2g_momentum",    "p2g_force",       "grid_velocity",   "grid_integrate",    "g2p_motion",
    "g2p_stress",      "remap",           "transport_p2g",   "transport_flux",    "transport_update",
    "transport_g2p",   "nonlocal_settle", "contact_volumes", "contact_projected", "contact_updated",
    "contact_bonds"};

inline const char* stage_name(Stage s) { return stage_names[static_cast<std::size_t>(s)]; }

// What a stage reads and writes, in groups coarse enough to state by hand
// and fine enough that two stages the graph may run at the same time can
// be checked to touch disjoint data (engine/step_graph.cpp).
namespace stage_data {
inline constexpr unsigned particle_motion = 1u << 0;     // x, v
inline constexpr unsigned particle_volume = 1u << 1;     // volume (mass and x0 are read only)
inline constexpr unsigned particle_stress = 1u << 2;     // stress, strain, the models' states
inline constexpr unsigned particle_transport = 1u << 3;  // temperature, concentration and their steps
inline constexpr unsigned grid_momentum = 1u << 4;       // nodal mass, momentum, stiffness
inline constexpr unsigned grid_force = 1u << 5;          // nodal force
inline constexpr unsigned grid_velocity = 1u << 6;       // nodal velocity and its change
inline constexpr unsigned grid_transport = 1u << 7;      // nodal heat and solvent fields
inline constexpr unsigned reaction_sums = 1u << 8;       // the constraints' reactions and work, load work, damping power
inline constexpr unsigned step_sums = 1u << 9;           // block energies, the largest particle speed
inline constexpr unsigned nonlocal_tables = 1u << 10;    // the nonlocal neighbours and their weights
inline constexpr unsigned contact_volumes = 1u << 11;    // the contact fields' nodal volumes, their gradients, the interfaces' displacement fits
}  // namespace stage_data
inline constexpr std::array<const char*, 12> stage_data_names = {
    "particle_motion", "particle_volume", "particle_stress", "particle_transport", "grid_momentum", "grid_force",
    "grid_velocity",   "grid_transport",  "reaction_sums",   "step_sums",          "nonlocal_tables", "contact_volumes"};

struct StageAccess {
  unsigned reads = 0, writes = 0;  // stage_data bits
};

// Each stage's access, from its kernel (tasks/p2g.hpp, grid_update.hpp,
// g2p.hpp, transport.hpp, nonlocal_settle.hpp, contact.hpp, contact_bonds.hpp). A new stage
// states its own.
inline StageAccess stage_access(Stage s) {
  using namespace stage_data;
  switch (s) {
    case Stage::p2g_momentum:
    case Stage::remap: return {particle_motion | particle_volume, grid_momentum};
    case Stage::p2g_force: return {particle_motion | particle_volume | particle_stress, grid_force};
    case Stage::grid_velocity: return {grid_momentum, grid_velocity};
    case Stage::grid_integrate: return {grid_momentum | grid_force, grid_velocity | reaction_sums};
    // XPIC's projections (tasks/xpic.hpp) read the nodal mass and write
    // nodal fields of their own, which no other stage touches.
    case Stage::g2p_motion: return {grid_momentum | grid_velocity | particle_motion, particle_motion | step_sums};
    case Stage::g2p_stress:
      return {grid_velocity | particle_motion | particle_transport,
              particle_stress | particle_volume | particle_transport | step_sums};
    case Stage::transport_p2g:
      return {particle_motion | particle_volume | particle_stress | particle_transport, grid_transport};
    case Stage::transport_flux: return {particle_motion | grid_transport, grid_transport};
    case Stage::transport_update: return {grid_transport, grid_transport};
    case Stage::transport_g2p: return {particle_motion | grid_transport, particle_transport};
    case Stage::nonlocal_settle: return {particle_motion | particle_stress, particle_stress | nonlocal_tables};
    case Stage::contact_volumes: return {particle_motion | particle_volume, contact_volumes};
    case Stage::contact_projected:
      return {grid_momentum | grid_velocity | contact_volumes, grid_momentum | grid_velocity};
    case Stage::contact_updated:
      return {grid_momentum | grid_force | grid_velocity | contact_volumes, grid_momentum | grid_velocity | reaction_sums};
    case Stage::contact_bonds: return {grid_momentum | grid_force | contact_volumes, grid_force | reaction_sums};
  }
  return {};
}

// "grid_momentum, grid_force" for the set bits of `data`.
inline std::string data_names(unsigned data) {
  std::string names;
  for (std::size_t i = 0; i < stage_data_names.size(); ++i)
    if (data & (1u << i)) names += (names.empty() ? "" : ", ") + std::string(stage_data_names[i]);
  return names;
}

// The stages one graph node runs, in order, in one pass.
using StageGroup = std::vector<Stage>;

// "p2g_momentum & p2g_force".
inline std::string group_name(const StageGroup& group) {
  std::string name;
  for (Stage s : group) name += (name.empty() ? "" : " & ") + std::string(stage_name(s));
  return name;
}

}  // namespace flowmpm
