#include <cmath>
#include <limits>
#include <string>
#include <variant>
#include <vector>

#include <spdlog/spdlog.h>

#include "app/run_case_internal.hpp"
#include "core/number_text.hpp"
#include "discretisation/bodies/lattice.hpp"
#include "discretisation/contact/contact_fields.hpp"
#include "discretisation/shapes/shape_functions.hpp"
#include "engine/simulation.hpp"
#include "io/case/memory_estimate.hpp"

namespace flowmpm::run_internal {

namespace {

// The particle fields a system stores.
std::string stored_fields(int dimension, bool heat, bool solvent) {
  const std::string vec = dimension == 1 ? "scalar" : std::to_string(dimension) + "-vector";
  return "x, v (" + vec + "), mass, volume, stress, strain (6 Voigt)" +
         std::string(heat ? ", temperature and its step" : "") +
         std::string(solvent ? ", concentration and its step" : "");
}

// With transport: both time-step limits and which one governs.
std::string time_step_limits(const TimeStepLimit& limits) {
  const DiffusionStep& diffusion = *limits.diffusion;
  return fmt::format("wave limit {:.4g} s (material '{}'), {} diffusion limit {:.4g} s (material '{}', diffusivity "
                     "{:.4g} m^2/s): the {} limit governs",
                     limits.wave.dt(), limits.wave.material, diffusion.field, diffusion.dt, diffusion.material,
                     diffusion.diffusivity, limits.diffusion_governs() ? "diffusion" : "wave");
}

// Each strain_softening material's crack band: the nonlocal length l and
// whether the cells resolve it (docs/theory/softening.md, "Choosing l").
template <int D>
void log_crack_bands(spdlog::logger& log, const Case& c, double cell_volume) {
  const double h = std::pow(cell_volume, 1.0 / D);
  for (const NamedMaterial& m : c.system.materials) {
    const auto* s = std::get_if<StrainSoftening>(&m.model);
    if (!s || !s->parameters.fracture_energy) continue;
    if (!s->parameters.nonlocal_length) {
      log.info("material '{}': the crack band of one cell (nonlocal_length = 0)", m.name);
      continue;
    }
    const double l = *s->parameters.nonlocal_length;
    const bool by_default = l == StrainSoftening::default_nonlocal_length(s->parameters);
    log.info("material '{}': the crack band's opening averaged over nonlocal_length l = {} m ({}), {:.3g} cells",
             m.name, readable_text(l), by_default ? "the default, 2 G_c / (E eps_i^2)" : "given", l / h);
    if (l < 6.0 * h) {
      log.warn("material '{}': l = {} m is only {:.2g} cells: a band several cells wide fills the window and "
               "dissipates more than G_c (under-resolved); cells below l / 6 = {} m resolve it",
               m.name, readable_text(l), l / h, readable_text(l / 6.0));
    }
    if (const double cells = std::pow(4.0 * l / h, D); cells > 1e5) {
      log.warn("material '{}': the window reaches 4 l = {} m, up to {:.3g} cells around each softening particle "
               "(slow); give nonlocal_length, a material length (about three aggregate sizes for concrete)",
               m.name, readable_text(4.0 * l), cells);
    }
  }
}

// Warns of each body (or contact group: its bodies together) of a
// [[contacts]] pair, rigid ones included, thinner than
// ContactFields::min_body_cells, below which a body on it or on which it
// rests can stick or slide short where a surface falls between node planes
// (a block on a rigid floor 1 to 2 cells thick, docs/guide/contact.md):
// its thickness is the smallest extent of its particles' box (a bounding
// box: a thin arm of an irregular body goes unseen).
template <int D, class Shape>
void warn_thin_contact_bodies(spdlog::logger& log, const Case& c, const DiscreteSystem<D, Shape>& system) {
  const std::vector<BodySpec>& bodies = c.system.bodies;
  // A body's member: itself, or its group (numbered after the bodies).
  auto member = [&](int body) {
    const int group = bodies[body].contact_group;
    return group < 0 ? body : static_cast<int>(bodies.size()) + group;
  };
  const std::size_t members = bodies.size() + c.system.contact_groups.size();
  std::vector<bool> in_contact(members, false);
  for (const ContactSpec& k : c.system.contacts) in_contact[member(k.first)] = in_contact[member(k.second)] = true;
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<Vec<D>> low(members, Vec<D>::Constant(inf)), high(members, Vec<D>::Constant(-inf));
  for (const auto& b : system.batches) {
    const int m = member(b.body);
    if (!in_contact[m]) continue;
    const Vec<D> half = Vec<D>::Constant(0.5 * b.particle_length);
    for (std::size_t p = 0; p < b.size(); ++p)
      low[m] = low[m].cwiseMin(b.x[p] - half), high[m] = high[m].cwiseMax(b.x[p] + half);
  }
  const double h = system.grid.h.minCoeff();
  constexpr double min_cells = ContactFields<D>::min_body_cells;
  for (std::size_t m = 0; m < members; ++m) {
    if (!in_contact[m] || !(low[m].array() < inf).all()) continue;
    const double thickness = (high[m] - low[m]).minCoeff();
    if (thickness >= min_cells * h * (1.0 - 1e-9)) continue;
    const std::string name = m < bodies.size() ? "body '" + bodies[m].name + "'"
                                               : "contact group '" + c.system.contact_groups[m - bodies.size()] + "'";
    log.warn("{} is {:.2g} cells thick ({} m, the smallest extent of its particles) and in contact: below {:g} "
             "cells a body, or one it supports, can stick or slide short where a surface falls between node "
             "planes (a block on a rigid floor: docs/guide/contact.md has the table); cells of {} m or less "
             "give it {:g}",
             name, thickness / h, readable_text(thickness), min_cells, readable_text(thickness / min_cells), min_cells);
  }
}

// Warns of every box body whose extent along an axis is not a whole number
// of particle spacings: the lattice fills as many whole spacings as fit,
// centred in the box (discretisation/bodies/lattice.hpp), so each of the
// box's faces on that axis lies inside its particles' domain by half the
// remainder. A slab 4.5 spacings thick left its top h/8 below the block on
// it, and the block slid 7.2 % short (docs/guide/contact.md).
template <int D>
void warn_box_not_whole_spacings(spdlog::logger& log, const Case& c) {
  for (const BodySpec& body : c.system.bodies) {
    const auto* box = std::get_if<BoxShape>(&body.shape.shape);
    if (!box || body.particles) continue;
    const Lattice lattice(*box, body.spacing, D);
    for (int d = 0; d < D; ++d) {
      const double margin = lattice.corner[d] - box->min[d];  // half the remainder
      if (2.0 * margin < 1e-6 * body.spacing[d]) continue;
      const double extent = box->max[d] - box->min[d];
      log.warn("body '{}': its box is {:.4g} particle spacings along {} ({} m at {} m): its particles fill {}, "
               "centred, so its faces along {} lie {} m inside the box's; make the box a whole number of spacings "
               "(docs/guide/contact.md)",
               body.name, extent / body.spacing[d], "xyz"[d], readable_text(extent), readable_text(body.spacing[d]),
               lattice.count[d], "xyz"[d], readable_text(margin));
    }
  }
}

template <int D, class Shape>
void log_system(spdlog::logger& log, const Case& c, const Simulation<D, Shape>& sim) {
  const Scheme& scheme = *c.scheme;
  const DiscreteSystem<D, Shape>& system = sim.system();
  log.info("model: {}D ({}), scheme {} [{}], shape function {}, velocity update {}{}", D,
           stress_state_name(system.stress_state), scheme.label, sim.graph().wiring().describe(), Shape::name,
           velocity_update_name(c.system.velocity_update),
           c.system.velocity_update == VelocityUpdate::blend
               ? " (FLIP fraction " + std::to_string(system.flip_fraction) + ")"
           : c.system.velocity_update == VelocityUpdate::xpic ? " (order " + std::to_string(system.xpic_order) + ")"
                                                               : "");
  warn_box_not_whole_spacings<D>(log, c);
  std::string cells;
  for (int d = 0; d < D; ++d) cells += (d ? " x " : "") + std::to_string(system.grid.cells[d]);
  log.info("grid: {} cells, {} nodes, {} blocks of {}^{} cells ({} occupied)", cells,
               system.grid.node_count(), system.blocks.block_count, BlockLayout<D, Shape>::block_cells, D,
               system.blocks.occupied.size());
  for (const auto& b : system.batches) {
    if (c.system.bodies[b.body].rigid()) {
      const std::string velocity = axis_functions_text(*c.system.bodies[b.body].rigid_velocity, "m/s");
      log.info("body '{}': {} particles, rigid, {}", c.system.bodies[b.body].name, b.size(),
               velocity.empty() ? "at rest" : "velocity " + velocity);
      continue;
    }
    const auto& m = c.system.materials[b.material];
    log.info("body '{}': {} particles, material '{}' ({}, density {} kg/m^3, wave speed {:.4g} m/s)",
                 c.system.bodies[b.body].name, b.size(), m.name, type_name(m.model), density(m.model),
                 wave_speed(m.model));
  }
  log.info("particle fields stored: {}", stored_fields(D, system.heat.has_value(), system.solvent.has_value()));
  if (system.nonlocal) {
    log.info("nonlocal averages: over the initial positions (x0 stored), settled with the step's end by "
             "nonlocal_settle");
  }
  log_crack_bands<D>(log, c, system.grid.h.prod());
  if (system.contact) {
    const auto& contact = *system.contact;
    log.info("contact: {} velocity fields ({} deformable contact bodies, {} rigid, and the grid's for the rest)",
             contact.fields, contact.deformable_count(), contact.rigid.size());
    for (const ContactPair& p : contact.pairs) {
      std::string law = ContactLaws::name_of(p.law);
      if (const auto* coulomb = std::get_if<CoulombLaw>(&p.law)) law += ", mu " + readable_text(coulomb->friction);
      if (const auto* bond = std::get_if<InterfaceLaw>(&p.law)) {
        log.info("contact '{}': interface, D_n {} Pa/m, D_t {} Pa/m, bonded wherever both bodies carry mass", p.name,
                 readable_text(bond->normal_stiffness), readable_text(bond->tangential_stiffness));
        continue;
      }
      log.info("contact '{}': {}, touching where the two volumes fill {} of a node's", p.name, law,
               readable_text(p.touch_fraction));
    }
    warn_thin_contact_bodies(log, c, system);
  }
  for (const auto& k : system.constraints) {
    log.info("node set '{}': {} nodes, velocity prescribed along {}", k.name, k.nodes.size(),
                 "xyz"[k.axis]);
  }
  if (system.heat || system.solvent) {
    log.info("transport: {}{}{} on the grid, a branch of the step graph beside the momentum stages",
             system.heat ? "heat conduction" : "", system.heat && system.solvent ? " and " : "",
             system.solvent ? "solvent diffusion" : "");
  }
  for (const auto* field : {&system.heat, &system.solvent}) {
    if (!*field) continue;
    for (const auto& k : (*field)->prescribed) {
      log.info("node set '{}': {} nodes, {} prescribed", k.name, k.nodes.size(),
               field == &system.heat ? "temperature" : "concentration");
    }
  }
  for (const auto& f : system.surface_fluxes) {
    log.info("surface flux '{}': {}{}", f.name, f.heat ? "heat" : "", f.solvent ? (f.heat ? " and solvent" : "solvent") : "");
  }
  if (system.gravity.norm() > 0.0) log.info("gravity: {} m/s^2", system.gravity.norm());
  for (const auto& load : system.loads.surface) log.info("load: {}", load.description);
  for (const auto& load : system.loads.nodal) log.info("load: {}", load.description);
  for (const auto& load : system.loads.body) log.info("load: {}", load.description);
  if (system.damping) {
    log.info("damping: local alpha {}, viscous c {} 1/s (at t = 0; docs/guide/loads.md)", system.damping->local(0.0),
             system.damping->viscous(0.0));
  }
  for (const auto& body : c.system.bodies) {
    if (body.initial_stress) {
      log.info("body '{}': initial stress {}", body.name, InitialStresses::name_of(*body.initial_stress));
    } else if (body.particles && !body.particles->stress.empty()) {
      log.info("body '{}': initial stress per particle from {}", body.name, body.particles->source);
    }
  }
  const MemoryEstimate estimate = estimate_memory(c);
  log.info("{}", estimate_text(estimate));
  if (estimate.steps > long_run_steps) {
    log.warn("a long run: {:.3g} steps (more than {:.0e})", estimate.steps, long_run_steps);
  }
  const TimeStep& time = c.time_step;
  const StableStep& stable = time.limits().wave;
  const char* axisymmetric = c.system.axisymmetric ? ", axisymmetric" : "";
  if (time.automatic()) {
    log.info("time: dt automatic, CFL {} of h/c = {:.4g} s (the stable limit is {:.3g} h/c for {} with {} at {:.3g} "
             "particles per cell{}), to t = {:.6g} s",
             time.cfl(), stable.crossing, stable.factor, scheme.label, Shape::name, stable.particles_per_cell,
             axisymmetric, time.end_time());
  } else {
    log.info("time: dt = {:.6g} s = {:.3g} h/c ({:.3g} of the stable limit {:.3g} h/c for {} with {} at {:.3g} "
             "particles per cell{}), {} steps to t = {:.6g} s",
             time.first_dt(), time.first_dt() / stable.crossing, time.first_dt() / stable.dt(), stable.factor,
             scheme.label, Shape::name, stable.particles_per_cell, axisymmetric, time.fixed_steps(), time.end_time());
  }
  if (time.limits().diffusion) log.info("time-step limits: {}", time_step_limits(time.limits()));
  if (const auto& bond = time.limits().interface) {
    log.info("time-step limits: wave limit {:.4g} s, interface '{}' limit {:.4g} s (D {:.4g} Pa/m): together "
             "1 / sqrt(1 / dt_w^2 + 1 / dt_i^2) = {:.4g} s",
             stable.dt(), bond->contact, bond->dt, bond->stiffness, time.limits().mechanical_dt());
  }
}

}  // namespace

void log_model(spdlog::logger& log, const Case& c, const SimulationBase& sim) {
  with_dimension_and_shape(sim.dimension(), sim.shape(), [&]<int D, class Shape>() {
    log_system(log, c, dynamic_cast<const Simulation<D, Shape>&>(sim));
  });
}

}  // namespace flowmpm::run_internal
