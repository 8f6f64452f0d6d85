// Builds the DiscreteSystem of a SystemSpec: the grid, particles filling each
// body's box at its spacing (one batch per body, of one material), velocity
// constraints on node sets, then the first sort and, if a model asks for
// them, the nonlocal weights. Volumes are per unit
// thickness in 2D and per unit cross-section in 1D. Throws CaseError naming
// the spec's source and the body or node set for what only the built system
// can tell (a body in the outermost cells, a node set with no node).
#pragma once
#include <cmath>
#include <numeric>
#include <numbers>
#include <type_traits>

#include "core/errors.hpp"
#include "discretisation/nonlocal_average.hpp"
#include "discretisation/particle_sort.hpp"
#include "discretisation/system_spec.hpp"

namespace flowmpm {

// For a plane node set with material on one side only: the nodes outside
// within the shape function's reach, each paired with its mirror image
// inside (see MirrorPlane). `plane_nodes` are the set's nodes.
template <int D, class Shape>
std::vector<std::pair<std::size_t, std::size_t>> ghost_mirror_pairs(const DiscreteSystem<D, Shape>& system,
                                                                     const NodeSetSpec& set,
                                                                     const std::vector<std::size_t>& plane_nodes) {
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  if (!set.is_plane || Shape::reach_below == 0) return pairs;
  const auto& g = system.grid;
  const int a = set.axis;
  std::size_t below = 0, above = 0;
  for (const auto& b : system.batches) {
    for (const auto& x : b.x) (x[a] < set.at ? below : above) += 1;
  }
  if (below > 0 && above > 0) return pairs;  // inside the material: no ghosts
  const int outward = below == 0 ? -1 : 1;
  for (const std::size_t n : plane_nodes) {
    const Index<D> i = g.node_ijk(n);
    for (int j = 1; j <= Shape::reach_below; ++j) {
      Index<D> ghost = i, mirror = i;
      ghost[a] = i[a] + outward * j;
      mirror[a] = i[a] - outward * j;
      if (ghost[a] < 0 || ghost[a] > g.cells[a] || mirror[a] < 0 || mirror[a] > g.cells[a]) continue;
      pairs.emplace_back(g.node_index(ghost), g.node_index(mirror));
    }
  }
  return pairs;
}

template <int D, class Shape>
void build_system(const SystemSpec& spec, DiscreteSystem<D, Shape>& system) {
  Vec<D> origin, h;
  Index<D> cells;
  for (int d = 0; d < D; ++d) {
    origin[d] = spec.grid.origin[d];
    h[d] = spec.grid.cell_size[d];
    cells[d] = spec.grid.cells[d];
  }
  system.grid = Grid<D>(origin, h, cells);
  if constexpr (Shape::gradient_jumps) system.grid.stiffness.assign(system.grid.node_count(), 0.0);
  system.blocks = BlockLayout<D, Shape>(cells);
  for (const auto& m : spec.materials) system.materials.push_back(m.model);
  for (int d = 0; d < D; ++d) system.gravity[d] = spec.gravity[d];
  system.flip_fraction = spec.flip_fraction;
  if (D == 2 && spec.plane_stress) system.stress_state = StressState::plane_stress;
  system.dt = spec.dt;

  for (std::size_t bi = 0; bi < spec.bodies.size(); ++bi) {
    const BodySpec& body = spec.bodies[bi];
    ParticleBatch<D> batch;
    batch.body = static_cast<int>(bi);
    batch.material = body.material;
    Index<D> count;
    std::size_t n = 1;
    double volume = 1.0;
    for (int d = 0; d < D; ++d) {
      // Whole spacings that fit in the box, centred in it.
      count[d] = std::max(1, static_cast<int>(std::floor((body.box_max[d] - body.box_min[d]) / body.spacing[d] + 1e-9)));
      n *= static_cast<std::size_t>(count[d]);
      volume *= body.spacing[d];
    }
    const double rho = density(system.materials[body.material]);
    Vec<D> v0;
    for (int d = 0; d < D; ++d) v0[d] = body.velocity[d];
    for (std::size_t p = 0; p < n; ++p) {
      Vec<D> x;
      std::size_t rest = p;
      for (int d = 0; d < D; ++d) {
        const int i = static_cast<int>(rest % count[d]);
        rest /= count[d];
        const double margin = 0.5 * ((body.box_max[d] - body.box_min[d]) - count[d] * body.spacing[d]);
        x[d] = body.box_min[d] + margin + (i + 0.5) * body.spacing[d];
      }
      batch.x.push_back(x);
    }
    batch.v.assign(n, v0);
    if (spec.keep_initial_positions) batch.x0 = batch.x;
    batch.mass.assign(n, rho * volume);
    batch.volume.assign(n, volume);
    batch.stress.assign(n, Voigt{});
    batch.strain.assign(n, Voigt{});
    batch.particle_length = std::pow(volume, 1.0 / D);
    for (int d = 0; d < D; ++d) batch.half_width[d] = 0.5 * body.spacing[d] * system.grid.inv_h[d];
    // A model may reject its parameters for this body's particles (e.g. a
    // crack band wider than the fracture energy allows): name the body.
    auto initial_states = [&](const auto& material) -> MaterialStates {
      using M = std::decay_t<decltype(material)>;
      // Models without internal variables store nothing per particle.
      StateArray<M> states;
      if constexpr (!std::is_empty_v<typename M::State>) {
        states.reserve(n);
        ParticleInit init;
        init.axes_degrees = body.material_axes;
        init.length = batch.particle_length;
        init.cell_length = std::pow(system.grid.h.prod(), 1.0 / D);
        for (const Vec<D>& x : batch.x) {
          for (int d = 0; d < D; ++d) init.position[d] = x[d];
          if (const auto& center = body.material_axes_center; center && D > 1) {
            const double radial = std::atan2(init.position[1] - (*center)[1], init.position[0] - (*center)[0]);
            init.axes_degrees[0] = body.material_axes[0] + radial * 180.0 / std::numbers::pi;
          }
          states.push_back(material.initial_state(init));
        }
      }
      return states;
    };
    try {
      batch.states = std::visit(initial_states, system.materials[body.material]);
    } catch (const CaseError& e) {
      throw CaseError(spec.source + ": bodies \"" + body.name + "\" (material \"" +
                      spec.materials[body.material].name + "\"): " + e.what());
    }
    system.batches.push_back(std::move(batch));
  }
  // Particle ids in the order the particles were made: their rows in the output.
  std::uint32_t next_id = 0;
  for (auto& batch : system.batches) {
    batch.id.resize(batch.size());
    std::iota(batch.id.begin(), batch.id.end(), next_id);
    next_id += static_cast<std::uint32_t>(batch.size());
  }

  for (const NodeSetSpec& set : spec.node_sets) {
    std::vector<std::size_t> nodes;
    const auto& g = system.grid;
    for (std::size_t n = 0; n < g.node_count(); ++n) {
      const Vec<D> x = g.node_position(g.node_ijk(n));
      bool selected = true;
      for (int d = 0; d < D; ++d) {
        const double tol = 1e-6 * g.h[d];
        if (set.is_plane) {
          if (d == set.axis) selected = selected && std::abs(x[d] - set.at) <= tol;
        } else {
          selected = selected && x[d] >= set.box_min[d] - tol && x[d] <= set.box_max[d] + tol;
        }
      }
      if (selected) nodes.push_back(n);
    }
    if (nodes.empty()) {
      throw CaseError(spec.source + ": node_sets \"" + set.name + "\": selects no grid node");
    }
    for (int d = 0; d < D; ++d) {
      if (set.velocity[d]) system.constraints.push_back({set.name, nodes, d, *set.velocity[d]});
    }
    auto pairs = ghost_mirror_pairs<D, Shape>(system, set, nodes);
    if (!pairs.empty()) {
      for (NodeConstraint& k : system.constraints)
        if (k.name == set.name) k.mirror_plane = static_cast<int>(system.mirror_planes.size());
      system.mirror_planes.push_back({set.name, std::move(pairs), set.velocity});
    }
  }

  // Every particle must start where its stencil has grid nodes.
  for (const auto& batch : system.batches) {
    for (const auto& x : batch.x) {
      const Index<D> cell = system.grid.cell_of(x);
      for (int d = 0; d < D; ++d) {
        if (cell[d] < Shape::reach_below || cell[d] + Shape::reach_above > cells[d]) {
          throw CaseError(spec.source + ": bodies \"" + spec.bodies[batch.body].name +
                          "\": particles lie in the outermost cells, where the " + Shape::name +
                          " shape function has no nodes; enlarge the grid");
        }
      }
    }
  }
  sort_particles(system);
  nonlocal_setup(system);
}

}  // namespace flowmpm
