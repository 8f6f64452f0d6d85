// Particles of one material: a batch, stored as one array per field
// (structure of arrays) and kept sorted by grid block, so that neighbours in
// memory are neighbours in space. Fields no part of the scene reads are not
// stored (empty arrays).
#pragma once
#include <array>
#include <cstdint>
#include <variant>
#include <vector>

#include "core/vec.hpp"
#include "core/voigt.hpp"
#include "materials/material.hpp"

namespace flowmpm {

// The state arrays of a batch's model (empty for models without state).
template <class Variant>
struct StateArraysOf;
template <class... Models>
struct StateArraysOf<std::variant<Models...>> {
  using type = std::variant<StateArray<Models>...>;
};
using MaterialStates = StateArraysOf<Material>::type;

// A particle as a step found it, kept by the stress update of a model that
// asks for nonlocal averages, so that the update can be redone from the same
// start with a new average (tasks/nonlocal_settle.hpp). Written for every
// particle by each step's stress update before it is read, so the sort need
// not permute it.
template <int D>
struct StepStart {
  MaterialStates states;
  std::vector<Voigt> stress, strain;
  std::vector<double> volume;
  // The step's velocity gradient, row by row, then the hoop rate v_r / r
  // (axisymmetric; 0 otherwise) (1/s).
  std::vector<std::array<double, D * D + 1>> L;
};

template <int D>
struct ParticleBatch {
  int body = 0;      // index into SystemSpec::bodies
  int material = 0;  // index into SystemSpec::materials (none, -1, for a rigid body)
  // Its velocity field: 0 the grid's, k >= 1 a contact field
  // (discretisation/contact/contact_fields.hpp).
  int field = 0;
  double particle_length = 0.0;  // initial particle size (m), see MaterialInput::length
  Vec<D> half_width = Vec<D>::Zero();  // initial half-width per axis, in cells (uGIMP)
  // Body force per unit mass on these particles during the step: gravity
  // plus their body's body force at the step's start (m/s^2), set by p2g.
  Vec<D> acceleration = Vec<D>::Zero();
  std::vector<Vec<D>> x, v;                // m, m/s
  std::vector<Vec<D>> x0;                  // initial positions, only when a reference or an average needs them
  std::vector<double> mass, volume;        // kg, m^3
  std::vector<Voigt> stress, strain;       // Pa, -
  std::vector<std::uint32_t> id;           // made in this order at set-up: the output row
  // Only with APIC (tasks/p2g.hpp, g2p.hpp): the affine velocity
  // C_p = B_p D_p^-1, row by row (1/s; docs/theory/transfers.md).
  std::vector<std::array<double, D * D>> affine;
  MaterialStates states;                   // the model's internal variables
  // Only when the scene conducts heat: T (K) and its change over the last
  // transport step; only when it diffuses solvent: c (weight fraction) and
  // its change (tasks/transport.hpp).
  std::vector<double> temperature, temperature_step;
  std::vector<double> concentration, concentration_step;
  // Only when the body has surface fluxes: bit f set when the particle lies
  // on face f = 2 axis + (0 at the box's min, 1 at its max), whose flux is
  // DiscreteSystem::surface_fluxes[surface_flux[f]].
  std::vector<std::uint8_t> flux_faces;
  std::array<int, 6> surface_flux{-1, -1, -1, -1, -1, -1};
  // Only for a model asking for nonlocal averages
  // (discretisation/nonlocal/nonlocal_average.hpp): the average of the neighbours'
  // sources at the end of the last step, the particle's own weight in it,
  // and the particle as the step found it.
  std::vector<double> nonlocal_others, nonlocal_self_weight;
  StepStart<D> step_start;

  // Particles of block b are [block_begin[b], block_begin[b + 1]).
  std::vector<std::uint32_t> block_begin;

  std::size_t size() const { return x.size(); }

  // Calls f(name, column) for every per-particle array, the model's states
  // included: the one list of the fields, which the sort permutes and the
  // output snapshot copies by name, so that no field can be left behind.
  template <class F>
  void for_each_column(F&& f) {
    for_each_column_of(*this, f);
  }
  template <class F>
  void for_each_column(F&& f) const {
    for_each_column_of(*this, f);
  }

 private:
  template <class Self, class F>
  static void for_each_column_of(Self& self, F& f) {
    f("position", self.x);
    f("velocity", self.v);
    f("initial_position", self.x0);
    f("mass", self.mass);
    f("volume", self.volume);
    f("stress", self.stress);
    f("strain", self.strain);
    f("id", self.id);
    f("affine_velocity", self.affine);
    f("temperature", self.temperature);
    f("temperature_step", self.temperature_step);
    f("concentration", self.concentration);
    f("concentration_step", self.concentration_step);
    f("flux_faces", self.flux_faces);
    f("nonlocal_others", self.nonlocal_others);
    f("nonlocal_self_weight", self.nonlocal_self_weight);
    std::visit([&](auto& states) { f("state", states); }, self.states);
  }
};

}  // namespace flowmpm
