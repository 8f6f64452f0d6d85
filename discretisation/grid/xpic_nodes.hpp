// The nodal fields of XPIC(m) for one velocity field (tasks/xpic.hpp),
// allocated only when the scene uses it: the iterate u_k = Q^(k-1) u_1 of
// the grid-particle-grid projection Q, and the correction w = v^L - v* that
// g2p takes off the grid's velocity. Rebuilt from the particles every step,
// so nothing of it carries in a checkpoint.
#pragma once
#include <vector>

#include "discretisation/grid/grid.hpp"

namespace flowmpm {

template <int D>
struct XpicNodes {
  // mass: the field's m_I (copied, so that the velocity constraints can
  // set the iterate's momentum); momentum: the pass's sum N_Ip m_p v_p;
  // velocity: u_k.
  NodalField<D> iterate;
  typename NodalField<D>::VectorField correction;  // w_I (m/s)

  void allocate(std::size_t nodes) {
    iterate.mass.assign(nodes, 0.0);
    for (auto* field : {&iterate.momentum, &iterate.velocity, &correction})
      for (auto& component : *field) component.assign(nodes, 0.0);
  }
};

}  // namespace flowmpm
