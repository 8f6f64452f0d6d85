// Everything one explicit step reads and writes: the grid, the particle
// batches and their block layout, the materials, velocity constraints,
// gravity and the clock. Built from a SystemSpec by build_system().
#pragma once
#include <atomic>
#include <mutex>
#include <optional>
#include <sstream>
#include <string>
#include <unordered_map>
#include <vector>

#include "core/time_function.hpp"
#include "discretisation/blocks.hpp"
#include "discretisation/grid.hpp"
#include "discretisation/nonlocal_bins.hpp"
#include "discretisation/particles.hpp"
#include "materials/material.hpp"
#include "materials/stress_state.hpp"

namespace flowmpm {

// Prescribed velocity of one axis on a set of nodes, and the reaction: the
// force the constraint applied on the body along that axis in the last
// step (N; per unit thickness in 2D, N/m, and per unit cross-section in 1D,
// N/m^2).
struct NodeConstraint {
  std::string name;
  std::vector<std::size_t> nodes;
  int axis = 0;
  TimeFunction velocity;  // m/s
  int mirror_plane = -1;  // index into mirror_planes when the set is one
  double reaction = 0.0;
};

// A constrained plane at the edge of the material, for shape functions that
// reach past it (uGIMP, B-splines): nodes outside it would otherwise move
// freely and spoil the boundary condition. The plane acts as a mirror: the
// material's image beyond it moves with the prescribed velocity V reflected
// (antisymmetric: v_image = 2 V - v) along constrained axes and with the
// same velocity (symmetric) along free axes. So each ghost node outside
// (i) hands the mass, momentum and force it received to its mirror node
// inside, with the sign of the symmetry, as the image particles would, and
// (ii) takes its mirror's velocity, reflected. For a symmetric kernel this
// gives v = V on the plane and keeps second-order accuracy (README).
struct MirrorPlane {
  std::string name;
  std::vector<std::pair<std::size_t, std::size_t>> pairs;  // (ghost, mirror)
  std::array<std::optional<TimeFunction>, 3> velocity;     // prescribed per axis
};

// "(x, y, z) m" with 6 significant digits, for messages about a particle.
template <int D>
std::string position_text(const Vec<D>& x) {
  std::ostringstream s;
  s.precision(6);
  s << "(";
  for (int d = 0; d < D; ++d) s << (d ? ", " : "") << x[d];
  s << ") m";
  return s.str();
}

// Problems found by a stage, reported after the step by the time loop.
struct StepFlags {
  std::atomic<bool> resort_needed{false};
  std::atomic<bool> failed{false};
  std::mutex mutex;
  std::string problem;  // first problem found, for the error message

  void fail(const std::string& what) {
    std::lock_guard lock(mutex);
    if (!failed.exchange(true)) problem = what;
  }
};

template <int D, class Shape>
struct DiscreteSystem {
  // 3D, plane strain or plane stress (2D), uniaxial stress (1D).
  StressState stress_state =
      D == 3 ? StressState::three_d : D == 2 ? StressState::plane_strain : StressState::uniaxial_stress;

  Grid<D> grid;
  BlockLayout<D, Shape> blocks;
  std::vector<ParticleBatch<D>> batches;
  std::vector<Material> materials;
  std::vector<NodeConstraint> constraints;
  std::vector<MirrorPlane> mirror_planes;
  Vec<D> gravity = Vec<D>::Zero();
  double flip_fraction = 1.0;
  // Nonlocal averages, only when a model asks for them
  // (discretisation/nonlocal_average.hpp, tasks/nonlocal_settle.hpp).
  struct Nonlocal {
    bool active = false;
    NonlocalBins<D> bins;
    // Per particle that has been a source, (batch << 32 | particle): the
    // particles within the cut-off and their weights alpha, in a fixed
    // order; dropped with the bins when the particles are re-sorted.
    std::unordered_map<std::uint64_t, std::vector<NonlocalNeighbour>> neighbours;
    std::int64_t unsettled_steps = 0;  // steps whose averages did not settle
  } nonlocal;

  double t = 0.0, dt = 0.0;  // time at the start of the step, time step (s)
  double max_speed_sq = 0.0;  // largest |v_p|^2 after the last step (m^2/s^2)
  std::int64_t step = 0;
  std::int64_t sorts = 0;  // particle sorts so far (the first at set-up)
  StepFlags flags;

  std::size_t particle_count() const {
    std::size_t n = 0;
    for (const auto& b : batches) n += b.size();
    return n;
  }
};

}  // namespace flowmpm
