// External loads and damping as the step applies them (tasks/external_forces.hpp,
// tasks/grid_update.hpp), attached by the loads of a case (loads.hpp) when
// the system is built. Each is a function of time, evaluated at the start
// of the step. Empty for a scene without loads: the step is then exactly
// what it was without them.
#pragma once
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/time_function.hpp"
#include "core/vec.hpp"

namespace flowmpm {

// Per axis, a function of time; absent axes are 0.
using AxisFunctions = std::array<std::optional<TimeFunction>, 3>;

// The vector of f's values at time t (0 along an absent axis).
template <int D>
Vec<D> axis_values(const AxisFunctions& f, double t) {
  Vec<D> v = Vec<D>::Zero();
  for (int d = 0; d < D; ++d)
    if (f[d]) v[d] = (*f[d])(t);
  return v;
}

// A lattice face of a particle on the surface of its body, where a
// traction or pressure acts: at the face's centre, x_p + offset, mapped
// to the nodes with the shape functions there.
template <int D>
struct LoadedFace {
  std::uint32_t particle = 0;  // index in the batch (kept through sorts)
  Vec<D> offset = Vec<D>::Zero();  // from the particle's centre to the face's centre (m)
  int axis = 0;         // the face's outward normal is sign e_axis
  double sign = 1.0;
  double area = 0.0;    // m^2 (3D), m per unit thickness (2D), 1 (1D)
  // The force on the face over the current step and where its centre was
  // at the start of it: the load's work is force . (its displacement).
  Vec<D> force = Vec<D>::Zero();
  Vec<D> at = Vec<D>::Zero();
};

// A traction (Pa per axis) or a pressure (Pa, along the inward normal) on
// faces of one batch.
template <int D>
struct SurfaceLoad {
  std::string description;  // for the log
  int batch = 0;
  std::vector<LoadedFace<D>> faces;
  AxisFunctions traction;             // traction: force = t area
  std::optional<TimeFunction> pressure;  // pressure: force = -p area n
};

// A force on each node of a node set (N in 3D, N/m in 2D, N/m^2 in 1D).
struct NodalLoad {
  std::string description;
  std::vector<std::size_t> nodes;
  AxisFunctions force;
};

// A body force per unit mass (m/s^2) on one batch, added to gravity.
struct BodyForce {
  std::string description;
  int batch = 0;
  AxisFunctions acceleration;
};

template <int D>
struct ExternalLoads {
  std::vector<SurfaceLoad<D>> surface;
  std::vector<NodalLoad> nodal;
  std::vector<BodyForce> body;
  bool empty() const { return surface.empty() && nodal.empty() && body.empty(); }
};

// Damping for quasi-static solutions, applied to the nodal forces of the
// grid update (tasks/grid_update.hpp), each coefficient a function of time
// (0 switches it off):
//   local (Cundall, non-viscous): f_d = -alpha |f| sign(v), per axis;
//   viscous (mass-proportional):  f_d = -c m v.
// Nodes whose velocity is prescribed along an axis (constraints, mirror
// ghosts) are not damped along it.
struct Damping {
  TimeFunction local{{{0.0, 0.0}}};    // alpha, in [0, 1)
  TimeFunction viscous{{{0.0, 0.0}}};  // c (1/s)
  std::vector<std::uint8_t> undamped;  // per node, bit d: no damping along axis d (set when built)
};

}  // namespace flowmpm
