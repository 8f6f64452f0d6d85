// The stage table: which pass over the particles or the grid runs a group of
// stages. A scheme's wiring is resolved against it once, when the step graph
// is built; the step itself calls the passes found, with no look-up.
// A group two stages share runs them in one pass, each particle's stencil
// evaluated once: the two p2g stages (they read the same start-of-step
// particles), and USL's g2p_motion with g2p_stress.
#pragma once
#include <stdexcept>

#include "tasks/contact.hpp"
#include "tasks/contact_bonds.hpp"
#include "tasks/g2p.hpp"
#include "tasks/grid_update.hpp"
#include "tasks/nonlocal_settle.hpp"
#include "tasks/p2g.hpp"
#include "tasks/stage.hpp"
#include "tasks/transport.hpp"
#include "tasks/wall.hpp"

namespace flowmpm {

template <int D, class Shape>
using StagePass = void (*)(DiscreteSystem<D, Shape>&);

// The pass that runs `group`; throws std::invalid_argument if none does.
template <int D, class Shape>
StagePass<D, Shape> stage_pass(const StageGroup& group) {
  struct Entry {
    StageGroup stages;
    StagePass<D, Shape> pass;
  };
  static const Entry table[] = {
      {{Stage::p2g_momentum}, &p2g_momentum<D, Shape>},
      {{Stage::p2g_force}, &p2g_force<D, Shape>},
      {{Stage::p2g_momentum, Stage::p2g_force}, &p2g_momentum_and_force<D, Shape>},
      {{Stage::grid_velocity}, &grid_velocity<D, Shape>},
      {{Stage::grid_integrate}, &grid_integrate<D, Shape>},
      {{Stage::g2p_motion}, &g2p_motion<D, Shape>},
      {{Stage::g2p_stress}, &g2p_stress<D, Shape>},
      {{Stage::g2p_motion, Stage::g2p_stress}, &g2p_motion_and_stress<D, Shape>},
      // MUSL: mass and momentum mapped again from the updated particles.
      {{Stage::remap}, &p2g_momentum<D, Shape>},
      {{Stage::transport_p2g}, &transport_p2g<D, Shape>},
      {{Stage::transport_flux}, &transport_flux<D, Shape>},
      {{Stage::transport_update}, &transport_update<D, Shape>},
      {{Stage::transport_g2p}, &transport_g2p<D, Shape>},
      {{Stage::nonlocal_settle}, &nonlocal_settle<D, Shape>},
      {{Stage::contact_volumes}, &contact_volumes<D, Shape>},
      {{Stage::contact_projected}, &contact_projected<D, Shape>},
      {{Stage::contact_updated}, &contact_updated<D, Shape>},
      {{Stage::contact_bonds}, &contact_bonds<D, Shape>},
  };
  for (const Entry& e : table)
    if (e.stages == group) return e.pass;
  throw std::invalid_argument("no pass runs the stages " + group_name(group));
}

}  // namespace flowmpm
