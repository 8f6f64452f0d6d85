// Builds the DiscreteSystem of a SystemSpec: the grid, each body's particles
// (the lattice points inside its shape, or particles from a file; one batch
// per body, of one material) with their initial stress, velocity
// constraints and prescribed temperatures and concentrations on node sets,
// surface fluxes, loads and damping, then the first sort and, if a model
// asks for them, the nonlocal weights. Temperatures and
// concentrations are stored only when the scene conducts heat or diffuses
// solvent. Volumes are per unit thickness in 2D and per unit cross-section
// in 1D. Throws CaseError naming the spec's source and the body, node set
// or load for what only the built system can tell (a shape with no lattice
// point, overlapping bodies, a body in the outermost cells, a node set with
// no node, a load that acts on nothing). A case with contacts gets its
// velocity fields (discretisation/contact/build_contact.hpp).
#pragma once
#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <numbers>
#include <type_traits>

#include <Eigen/Geometry>

#include "core/errors.hpp"
#include "core/number_text.hpp"
#include "discretisation/bodies/body_overlap.hpp"
#include "discretisation/nonlocal/nonlocal_average.hpp"
#include "discretisation/grid/particle_sort.hpp"
#include "discretisation/bodies/surface_faces.hpp"
#include "discretisation/contact/build_contact.hpp"
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

namespace detail {

// A wall on the node plane `set` (NodeSetSpec::wall): its nodes and those
// beyond it (away from the material) within the shape function's reach.
template <int D, class Shape>
Wall<D> wall_of(const DiscreteSystem<D, Shape>& system, const SystemSpec& spec, const NodeSetSpec& set,
                const std::vector<std::size_t>& plane_nodes) {
  const int a = set.axis;
  std::size_t below = 0, above = 0;
  for (const auto& b : system.batches)
    for (const auto& x : b.x) (x[a] < set.at ? below : above) += 1;
  if (below > 0 && above > 0) {
    throw CaseError(spec.source + ": node_sets \"" + set.name +
                    "\": a wall needs the material on one side of its plane, and it lies on both");
  }
  Wall<D> w;
  w.name = set.name;
  w.axis = a;
  w.outward = below == 0 ? -1.0 : 1.0;  // from the material into the wall
  w.law = *set.wall;
  w.velocity = set.velocity;
  const auto& g = system.grid;
  for (const std::size_t n : plane_nodes) {
    w.nodes.push_back(n);
    const Index<D> i = g.node_ijk(n);
    for (int j = 1; j <= std::max(Shape::reach_below, Shape::reach_above); ++j) {
      Index<D> beyond = i;
      beyond[a] = i[a] + static_cast<int>(w.outward) * j;
      if (beyond[a] >= 0 && beyond[a] <= g.cells[a]) w.nodes.push_back(g.node_index(beyond));
    }
  }
  return w;
}

// A body's particles before its batch is made: the lattice points inside
// its shape (each with the lattice cell's volume), or its particle file.
inline ParticleList body_particles(const BodySpec& body, int dimension, std::optional<Lattice>& lattice) {
  if (body.particles) return *body.particles;
  lattice.emplace(body.shape.bounds(), body.spacing, dimension);
  ParticleList list;
  list.position = fill(body.shape, *lattice);
  list.volume.assign(list.position.size(), lattice->cell_volume());
  if (list.position.empty()) {
    throw CaseError(body.where + ": expected a shape that holds particle centres of its lattice, got a " +
                    body.shape.type() + " with none");
  }
  return list;
}

// The initial stress of a body's particle at x: from its file, else the
// body's initial_stress, else 0. `top` is the body's highest point along
// the vertical (geostatic).
inline Voigt initial_stress(const BodySpec& body, const ParticleList& list, std::size_t p, double rho, double top) {
  if (!list.stress.empty()) return list.stress[p];
  if (!body.initial_stress) return Voigt{};
  return std::visit([&](const auto& s) { return s.at(list.position[p], rho, top); }, *body.initial_stress);
}

// The body's highest point along `axis`: its shape's bounds, or its
// highest particle plus half its size.
inline double body_top(const BodySpec& body, const ParticleList& list, int axis, int dimension) {
  if (!body.particles) return body.shape.bounds().max[axis];
  double top = -std::numeric_limits<double>::infinity();
  for (std::size_t p = 0; p < list.size(); ++p)
    top = std::max(top, list.position[p][axis] + 0.5 * std::pow(list.volume[p], 1.0 / dimension));
  return top;
}

// Adds a rigid rotation at `omega` (rad/s) about the centroid x_c of the
// body's particles (volume-weighted: one density per body, so the centre
// of mass): v_p += omega x (x_p - x_c). The body's linear momentum is
// unchanged and its angular momentum about x_c is I omega.
template <int D>
void add_rigid_spin(ParticleBatch<D>& batch, const ParticleList& list, const Vec3& omega) {
  Vec3 centroid{};
  double volume = 0.0;
  for (std::size_t p = 0; p < list.size(); ++p) {
    for (int d = 0; d < 3; ++d) centroid[d] += list.volume[p] * list.position[p][d];
    volume += list.volume[p];
  }
  for (double& c : centroid) c /= volume;
  for (std::size_t p = 0; p < list.size(); ++p) {
    const Eigen::Vector3d r(list.position[p][0] - centroid[0], list.position[p][1] - centroid[1],
                            list.position[p][2] - centroid[2]);
    const Eigen::Vector3d spin = Eigen::Vector3d(omega[0], omega[1], omega[2]).cross(r);
    for (int d = 0; d < D; ++d) batch.v[p][d] += spin[d];
  }
}

}  // namespace detail

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
  system.blocks = BlockLayout<D, Shape>(cells);
  system.block_energy.assign(system.blocks.block_count, BlockEnergy{});
  for (const auto& m : spec.materials) system.materials.push_back(m.model);
  for (int d = 0; d < D; ++d) system.gravity[d] = spec.gravity[d];
  system.flip_fraction = spec.flip_fraction;
  system.velocity_update = spec.velocity_update;
  system.xpic_order = spec.xpic_order;
  if (D == 2 && spec.plane_stress) system.stress_state = StressState::plane_stress;
  if (D == 2 && spec.axisymmetric) system.stress_state = StressState::axisymmetric;
  system.dt = spec.dt;
  if (spec.conducts_heat()) system.heat.emplace();
  if (spec.diffuses_solvent()) system.solvent.emplace();
  for (const SurfaceFluxSpec& f : spec.surface_fluxes) {
    const BodySpec& body = spec.bodies[f.body];
    double area = 1.0;  // the spacing's cell over its thickness normal to the face
    for (int d = 0; d < D; ++d)
      if (d != f.axis) area *= body.spacing[d];
    system.surface_fluxes.push_back({f.name, area, f.heat, f.solvent});
  }

  // The least particle mass and heat capacity, for the transport thresholds.
  double lightest = std::numeric_limits<double>::infinity();
  double least_heat_capacity = std::numeric_limits<double>::infinity();

  // Every body's particles first: overlaps are resolved between them.
  std::vector<ParticleList> particles;
  std::vector<BodyGeometry> geometry(spec.bodies.size());
  for (std::size_t bi = 0; bi < spec.bodies.size(); ++bi) {
    particles.push_back(detail::body_particles(spec.bodies[bi], D, geometry[bi].lattice));
    if (!spec.bodies[bi].particles) geometry[bi].shape = &spec.bodies[bi].shape;
  }
  resolve_overlaps(spec, particles);

  for (std::size_t bi = 0; bi < spec.bodies.size(); ++bi) {
    const BodySpec& body = spec.bodies[bi];
    // Released once the batch is made: set-up needs no more memory than the sort.
    const ParticleList list = std::move(particles[bi]);
    const std::size_t n = list.size();
    ParticleBatch<D> batch;
    batch.body = static_cast<int>(bi);
    batch.material = body.material;
    // A rigid body's particles carry no mass (contact_fields.hpp).
    const double rho = body.rigid() ? 0.0 : density(system.materials[body.material]);
    Vec<D> v0;
    for (int d = 0; d < D; ++d) v0[d] = body.velocity[d];
    // The faces of this body's box with a surface flux.
    for (std::size_t k = 0; k < spec.surface_fluxes.size(); ++k) {
      const SurfaceFluxSpec& f = spec.surface_fluxes[k];
      if (f.body == static_cast<int>(bi)) batch.surface_flux[2 * f.axis + (f.side > 0)] = static_cast<int>(k);
    }
    const bool has_fluxes = std::ranges::any_of(batch.surface_flux, [](int k) { return k >= 0; });
    // Volumes: per unit thickness in 2D; axisymmetric, per radian, V = r A
    // (the area A of the section times the radius).
    std::vector<double> volume = list.volume;
    if (spec.axisymmetric) {
      for (std::size_t p = 0; p < n; ++p) {
        if (!(list.position[p][0] > 0.0)) {
          throw CaseError(body.where + ": a particle at r = " + readable_text(list.position[p][0]) +
                          ": expected the body at r > 0 (axisymmetric: x is the radius)");
        }
        volume[p] *= list.position[p][0];
      }
    }
    batch.x.resize(n);
    batch.mass.resize(n);
    for (std::size_t p = 0; p < n; ++p) {
      for (int d = 0; d < D; ++d) batch.x[p][d] = list.position[p][d];
      batch.mass[p] = rho * volume[p];
    }
    // The particles on a face with a surface flux: the body's surface faces
    // with that normal (the first or last lattice layer of a box).
    if (has_fluxes) {
      if (!geometry[bi].lattice) {
        throw CaseError(spec.source + ": surface_fluxes on bodies \"" + body.name +
                        "\": its particles come from a file, so it has no faces; give the body a shape");
      }
      batch.flux_faces.assign(n, 0);
      for (int k = 0; k < 2 * D; ++k) {
        if (batch.surface_flux[k] < 0) continue;
        const std::pair<int, double> face{k / 2, k % 2 ? 1.0 : -1.0};
        for (const LoadedFace<D>& f : surface_faces(batch, body.shape, *geometry[bi].lattice, std::nullopt, face))
          batch.flux_faces[f.particle] |= std::uint8_t(1u << k);
      }
    }
    batch.v.assign(n, v0);
    if (body.angular_velocity != Vec3{}) detail::add_rigid_spin(batch, list, body.angular_velocity);
    // APIC: the initial velocity's gradient, the spin's skew matrix
    // C_ij = -e_ijk omega_k (0 for a uniform velocity).
    if (spec.velocity_update == VelocityUpdate::apic) {
      const Vec3& w = body.angular_velocity;
      const double spin[3][3] = {{0.0, -w[2], w[1]}, {w[2], 0.0, -w[0]}, {-w[1], w[0], 0.0}};
      std::array<double, D * D> C;
      for (int i = 0; i < D; ++i)
        for (int j = 0; j < D; ++j) C[D * i + j] = spin[i][j];
      batch.affine.assign(n, C);
    }
    if (spec.keep_initial_positions) batch.x0 = batch.x;
    batch.volume = volume;
    double top = 0.0;
    if (body.initial_stress) {
      if (const auto* g = std::get_if<GeostaticStress>(&*body.initial_stress)) top = detail::body_top(body, list, g->vertical, D);
    }
    batch.stress.reserve(n);
    for (std::size_t p = 0; p < n; ++p) batch.stress.push_back(detail::initial_stress(body, list, p, rho, top));
    batch.strain.assign(n, Voigt{});
    if (system.heat) {
      batch.temperature.assign(n, body.temperature);
      // The change since the stress-free state, for the first stress
      // update: T - T_ref (materials/expansion.hpp).
      const auto& reference = transport(system.materials[body.material]).reference_temperature;
      batch.temperature_step.assign(n, reference ? body.temperature - *reference : 0.0);
      for (const double v : volume)
        least_heat_capacity = std::min(least_heat_capacity, rho * v * transport(system.materials[body.material]).heat_capacity);
    }
    if (system.solvent) {
      batch.concentration.assign(n, body.concentration);
      batch.concentration_step.assign(n, body.concentration);  // since c = 0, stress free
    }
    // The particle size: a lattice cell, or the mean particle of a file.
    double mean_volume = 0.0;
    for (const double v : list.volume) mean_volume += v / static_cast<double>(n);
    batch.particle_length = std::pow(body.particles ? mean_volume : list.volume[0], 1.0 / D);
    for (int d = 0; d < D; ++d) {
      const double side = body.particles ? batch.particle_length : body.spacing[d];
      batch.half_width[d] = 0.5 * side * system.grid.inv_h[d];
    }
    // A model may reject its parameters for this body's particles (e.g. a
    // crack band wider than the fracture energy allows): name the body.
    auto initial_states = [&](const auto& material) -> MaterialStates {
      using M = std::decay_t<decltype(material)>;
      // Models without internal variables store nothing per particle.
      StateArray<M> states;
      if constexpr (!std::is_empty_v<typename M::State>) {
        states.reserve(n);
        ParticleInit init;
        init.length = batch.particle_length;
        init.cell_length = std::pow(system.grid.h.prod(), 1.0 / D);
        for (std::size_t p = 0; p < n; ++p) {
          const Vec3 axes = list.material_axes.empty() ? body.material_axes : list.material_axes[p];
          init.axes_degrees = axes;
          init.stress = batch.stress[p];
          for (int d = 0; d < D; ++d) init.position[d] = batch.x[p][d];
          if (const auto& center = body.material_axes_center; center && D > 1) {
            const double radial = std::atan2(init.position[1] - (*center)[1], init.position[0] - (*center)[0]);
            init.axes_degrees[0] = axes[0] + radial * 180.0 / std::numbers::pi;
          }
          states.push_back(material.initial_state(init));
        }
      }
      return states;
    };
    try {
      if (!body.rigid()) batch.states = std::visit(initial_states, system.materials[body.material]);
    } catch (const CaseError& e) {
      throw CaseError(spec.source + ": bodies \"" + body.name + "\" (material \"" +
                      spec.materials[body.material].name + "\"): " + e.what());
    }
    if (!body.rigid())
      for (const double m : batch.mass) lightest = std::min(lightest, m);
    system.batches.push_back(std::move(batch));
  }
  if (!spec.contacts.empty()) build_contact(spec, system);
  if (spec.velocity_update == VelocityUpdate::xpic) {
    system.xpic.resize(static_cast<std::size_t>(system.field_count()));
    for (XpicNodes<D>& x : system.xpic) x.allocate(system.grid.node_count());
  }
  // A node holding less than a millionth of the least particle capacity
  // only sees the far tail of a shape function: its transport update
  // dt Q / (mC) is noise, and it keeps its value.
  if (system.heat) {
    system.grid.heat.allocate(system.grid.node_count());
    system.heat->capacity_threshold = 1e-6 * least_heat_capacity;
  }
  if (system.solvent) {
    system.grid.solvent.allocate(system.grid.node_count());
    system.solvent->capacity_threshold = 1e-6 * lightest;
  }
  // Particle ids in the order the particles were made: their rows in the output.
  std::uint32_t next_id = 0;
  for (auto& batch : system.batches) {
    batch.id.resize(batch.size());
    std::iota(batch.id.begin(), batch.id.end(), next_id);
    next_id += static_cast<std::uint32_t>(batch.size());
  }

  std::vector<std::vector<std::size_t>> node_set_nodes;
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
    if (set.wall) {
      system.walls.push_back(detail::wall_of<D, Shape>(system, spec, set, nodes));
    } else {
      for (int d = 0; d < D; ++d) {
        if (set.velocity[d]) system.constraints.push_back({set.name, nodes, d, *set.velocity[d]});
      }
    }
    if (set.temperature) system.heat->prescribed.push_back({set.name, nodes, *set.temperature});
    if (set.concentration) system.solvent->prescribed.push_back({set.name, nodes, *set.concentration});
    if (set.constrains_velocity()) {
      auto pairs = ghost_mirror_pairs<D, Shape>(system, set, nodes);
      if (!pairs.empty()) {
        for (NodeConstraint& k : system.constraints)
          if (k.name == set.name) k.mirror_plane = static_cast<int>(system.mirror_planes.size());
        system.mirror_planes.push_back({set.name, std::move(pairs), set.velocity});
      }
    }
    node_set_nodes.push_back(std::move(nodes));
  }

  std::vector<std::string> body_names, node_set_names;
  for (const BodySpec& b : spec.bodies) body_names.push_back(b.name);
  for (const NodeSetSpec& s : spec.node_sets) node_set_names.push_back(s.name);
  LoadSite<D, Shape> site{system, geometry, node_set_nodes, body_names, node_set_names};
  for (const Load& load : spec.loads) std::visit([&](const auto& l) { l.attach(site); }, load);

  if (spec.damping) {
    system.damping = *spec.damping;
    // Prescribed velocities are not damped: constrained axes and ghost nodes.
    auto& undamped = system.damping->undamped;
    undamped.assign(system.grid.node_count(), 0);
    for (const NodeConstraint& c : system.constraints)
      for (const std::size_t n : c.nodes) undamped[n] |= static_cast<std::uint8_t>(1u << c.axis);
    for (const MirrorPlane& plane : system.mirror_planes)
      for (const auto& [ghost, mirror] : plane.pairs) undamped[ghost] = 0x7;
  }

  // Every particle, and every loaded face, must start where its stencil
  // has grid nodes.
  auto inside = [&](const Vec<D>& x) {
    const Index<D> cell = system.grid.cell_of(x);
    for (int d = 0; d < D; ++d)
      if (cell[d] < Shape::reach_below || cell[d] + Shape::reach_above > cells[d]) return false;
    return true;
  };
  for (const auto& batch : system.batches) {
    for (const auto& x : batch.x) {
      if (!inside(x)) {
        throw CaseError(spec.source + ": bodies \"" + spec.bodies[batch.body].name +
                        "\": particles lie in the outermost cells, where the " + Shape::name +
                        " shape function has no nodes; enlarge the grid");
      }
    }
  }
  for (const SurfaceLoad<D>& load : system.loads.surface) {
    for (const LoadedFace<D>& face : load.faces) {
      if (!inside(system.batches[load.batch].x[face.particle] + face.offset)) {
        throw CaseError(spec.source + ": " + load.description + ": a loaded face lies in the outermost cells, where the " +
                        Shape::name + " shape function has no nodes; enlarge the grid");
      }
    }
  }
  sort_particles(system);
  nonlocal_setup(system);
}

}  // namespace flowmpm
