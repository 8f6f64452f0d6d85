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
#include "discretisation/contact/contact_fields.hpp"
#include "discretisation/grid/blocks.hpp"
#include "discretisation/loads/external_loads.hpp"
#include "discretisation/grid/grid.hpp"
#include "discretisation/nonlocal/nonlocal_bins.hpp"
#include "discretisation/grid/particles.hpp"
#include "discretisation/grid/xpic_nodes.hpp"
#include "discretisation/velocity_update.hpp"
#include "materials/material.hpp"
#include "materials/stress_state.hpp"

namespace flowmpm {

// Prescribed velocity of one axis on a set of nodes, and the reaction: the
// force the constraint applied on the body along that axis in the last
// step (N; per unit thickness in 2D, N/m, and per unit cross-section in 1D,
// N/m^2). Energies likewise: J, J/m in 2D, J/m^2 in 1D.
struct NodeConstraint {
  std::string name;
  std::vector<std::size_t> nodes;
  int axis = 0;
  TimeFunction velocity;  // m/s
  int mirror_plane = -1;  // index into mirror_planes when the set is one
  double reaction = 0.0;
  double work = 0.0;  // J: the reaction's work on the body since t = 0, sum of reaction V dt
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
// gives v = V on the plane and keeps second-order accuracy (docs/theory/shape_functions.md).
struct MirrorPlane {
  std::string name;
  std::vector<std::pair<std::size_t, std::size_t>> pairs;  // (ghost, mirror)
  std::array<std::optional<TimeFunction>, 3> velocity;     // prescribed per axis
};

// A held plane that holds only in compression (NodeSetSpec::wall): its nodes
// and those beyond it within the shape function's reach, the unit normal
// out of the material into the wall (along `axis`, sign `outward`), its
// law and velocity; the force the material put on it over the last step
// (N; N/m in 2D) and its work on the material since t = 0 (J).
template <int D>
struct Wall {
  std::string name;
  std::vector<std::size_t> nodes;
  int axis = 0;
  double outward = 1.0;
  ContactLaw law;
  AxisFunctions velocity;
  Vec<D> force = Vec<D>::Zero();
  double work = 0.0;

  // The wall's velocity at time t (m/s; 0 along an axis it does not move on).
  Vec<D> velocity_at(double t) const { return axis_values<D>(velocity, t); }
  // The unit normal out of the material into the wall.
  Vec<D> normal() const {
    Vec<D> n = Vec<D>::Zero();
    n[axis] = outward;
    return n;
  }
};

// A temperature or concentration prescribed on a set of nodes.
struct PrescribedValue {
  std::string name;
  std::vector<std::size_t> nodes;
  TimeFunction value;  // K or weight fraction
};

// Heat or solvent transport (tasks/transport.hpp), present in a system
// only when its scene carries the field: its prescribed nodal values.
struct TransportField {
  // Nodes with less capacity than this (a millionth of the smallest
  // particle's) only see the far tail of a shape function: their rate
  // flow / capacity would be noise, so their value is left as mapped.
  double capacity_threshold = 0.0;
  std::vector<PrescribedValue> prescribed;
};

// A flux through a face of a body, carried by the particles on that face.
struct SurfaceFlux {
  std::string name;
  double area = 0.0;  // face area per particle (m^2; per unit thickness in 2D, 1 in 1D)
  std::optional<TimeFunction> heat;     // W/m^2 into the body
  std::optional<TimeFunction> solvent;  // kg/(m^2 s) into the body
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

// A step's energy sums over the particles of one block (tasks/g2p.hpp),
// added block by block in a fixed order (engine/energy_balance.hpp) so that
// they do not depend on the thread count.
struct BlockEnergy {
  double kinetic = 0.0;         // sum m v^2 / 2 after the step (J)
  double gravity_work = 0.0;    // sum m g . dx over the step (J)
  double expansion_work = 0.0;  // -sum V sigma : d eps_expansion over the step (J)
};

// The work done on the bodies since t = 0 (J), for the energy balance.
struct WorkDone {
  double gravity = 0.0;    // by gravity and the body forces: sum m g_p . dx
  double boundary = 0.0;   // by the velocity constraints' reactions
  double expansion = 0.0;  // by the expansion strains (thermal, solvent) against the stress
  double load = 0.0;       // by the tractions, pressures and nodal forces (docs/guide/loads.md)
  // By contact (tasks/contact.hpp): the impulses of the contact laws times
  // the mean of each field's nodal velocity at the start and at the end of
  // the step, the rigid bodies' work included; friction and impacts take
  // energy out (< 0), a moving rigid body may put it in.
  double contact = 0.0;
};

// The nonlocal averages of a system whose models ask for them: the bins of
// the particles' initial positions and, per particle that has been a
// source, (batch << 32 | particle): the particles within the cut-off and
// their weights alpha, in a fixed order; dropped with the bins when the
// particles are re-sorted.
template <int D>
struct NonlocalAverages {
  NonlocalBins<D> bins;
  std::unordered_map<std::uint64_t, std::vector<NonlocalNeighbour>> neighbours;
  std::int64_t unsettled_steps = 0;  // steps whose averages did not settle
};

// The system's clock and its run-wide sums: what the time loop and its
// services read and set, the same for every dimension and shape function
// (engine/simulation_base.hpp hands them out without the system's type).
struct SystemScalars {
  double t = 0.0, dt = 0.0;  // time at the start of the step, time step (s)
  double max_speed_sq = 0.0;  // largest |v_p|^2 after the last step (m^2/s^2)
  std::int64_t step = 0;
  std::int64_t sorts = 0;  // particle sorts so far (the first at set-up)
  double kinetic_energy = 0.0;  // after the last step (J)
  WorkDone work;
  // Power of the damping forces over the last step (W; per unit thickness
  // in 2D, per unit cross-section in 1D): sum over the nodes of f_d . v,
  // v the mean of the node's velocity before and after the update, so that
  // it is exactly the damping's share of the grid's kinetic energy change
  // (<= 0). damping_dissipated = -sum of damping_power dt over the steps (J).
  double damping_power = 0.0;
  double damping_dissipated = 0.0;
};

template <int D, class Shape>
struct DiscreteSystem : SystemScalars {
  // 3D, plane strain or plane stress (2D), uniaxial stress (1D).
  StressState stress_state =
      D == 3 ? StressState::three_d : D == 2 ? StressState::plane_strain : StressState::uniaxial_stress;

  Grid<D> grid;
  BlockLayout<D, Shape> blocks;
  std::vector<ParticleBatch<D>> batches;
  std::vector<Material> materials;
  std::vector<NodeConstraint> constraints;
  std::vector<MirrorPlane> mirror_planes;
  std::vector<Wall<D>> walls;  // node sets that are walls
  // Transport: present only in a scene that conducts heat (diffuses
  // solvent); the particles then carry the field.
  std::optional<TransportField> heat, solvent;
  std::vector<SurfaceFlux> surface_fluxes;
  Vec<D> gravity = Vec<D>::Zero();
  ExternalLoads<D> loads;          // tractions, pressures, nodal and body forces
  std::optional<Damping> damping;  // quasi-static damping, if the case has it
  double flip_fraction = 1.0;
  // APIC: the particles carry their affine velocity (ParticleBatch::affine);
  // XPIC(m): the nodal fields of its projections, one per velocity field
  // (tasks/xpic.hpp), empty otherwise.
  VelocityUpdate velocity_update = VelocityUpdate::flip;
  int xpic_order = 5;
  std::vector<XpicNodes<D>> xpic;
  // Nonlocal averages: present only when a model asks for them
  // (discretisation/nonlocal/nonlocal_average.hpp, tasks/nonlocal_settle.hpp).
  std::optional<NonlocalAverages<D>> nonlocal;
  // Contact: present only when the case puts bodies in contact; each such
  // body then has a velocity field of its own
  // (discretisation/contact/contact_fields.hpp).
  std::optional<ContactFields<D>> contact;

  StepFlags flags;

  std::vector<BlockEnergy> block_energy;  // per block of `blocks`, this step's sums

  // Velocity field k: 0 the grid's, k >= 1 a deformable contact body's.
  NodalField<D>& field(int k) { return k == 0 ? grid : contact->deformable[k - 1]; }
  const NodalField<D>& field(int k) const { return k == 0 ? grid : contact->deformable[k - 1]; }
  // The deformable velocity fields: 1 without contact.
  int field_count() const { return contact ? 1 + contact->deformable_count() : 1; }
  // Particles whose velocity is prescribed: a rigid body's (contact).
  bool is_rigid(const ParticleBatch<D>& b) const { return b.field > 0 && contact->is_rigid(b.field); }

  std::size_t particle_count() const {
    std::size_t n = 0;
    for (const auto& b : batches) n += b.size();
    return n;
  }
};

// Calls f.template operator()<Hoop>() once, Hoop true where the analysis is
// axisymmetric (2D only): the particle passes' hoop terms, compiled in only
// where they can run.
template <int D, class Shape, class F>
void with_hoop(const DiscreteSystem<D, Shape>& system, F&& f) {
  if constexpr (D == 2) {
    if (system.stress_state == StressState::axisymmetric) {
      f.template operator()<true>();
      return;
    }
  }
  f.template operator()<false>();
}

}  // namespace flowmpm
