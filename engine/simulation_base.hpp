// A running simulation as the time loop and its services see it, whatever
// its dimension and shape function: the step, the clock and run-wide sums
// (SystemScalars), the diagnostics, snapshots and the carried state. The
// one implementation is Simulation<D, Shape> (engine/simulation.hpp),
// compiled once per dimension and shape function into the engine library;
// make_simulation picks it from the case's choices.
#pragma once
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "discretisation/discrete_system.hpp"
#include "discretisation/shapes/shape_functions.hpp"
#include "discretisation/system_spec.hpp"
#include "engine/diagnostics.hpp"
#include "engine/schemes.hpp"
#include "engine/snapshot.hpp"
#include "engine/state_records.hpp"
#include "tasks/stage.hpp"

namespace flowmpm {

// What a system holds beyond its clock, for the log and the summary.
struct SystemSize {
  std::size_t particles = 0;
  std::size_t nodes = 0;
  double total_mass = 0.0;  // kg (per unit thickness in 2D, per unit cross-section in 1D)
};

class SimulationBase {
 public:
  virtual ~SimulationBase() = default;

  virtual int dimension() const = 0;
  virtual ShapeChoice shape() const = 0;
  virtual const char* shape_function() const = 0;  // its name
  virtual StressState stress_state() const = 0;
  // The wiring the graph runs (the scheme's, with what the scene adds).
  virtual const Wiring& wiring() const = 0;

  // One step through the flow graph (or serially, as the reference).
  virtual void advance() = 0;
  virtual void advance_serial() = 0;

  // The clock and the run-wide sums; the loop sets dt before each step.
  virtual SystemScalars& scalars() = 0;
  virtual const SystemScalars& scalars() const = 0;
  virtual SystemSize size() const = 0;
  // Steps whose nonlocal averages did not settle (0 without them).
  virtual std::int64_t unsettled_steps() const = 0;
  virtual bool damped() const = 0;
  virtual bool in_contact() const = 0;  // bodies in contact: a contact component

  // Sets the largest particle speed and the kinetic energy (measured
  // during each step; this measures them outside one, e.g. at the start).
  virtual void measure_speed() = 0;
  // Energies, per body the volume-weighted mean stress and strain, and the
  // reactions (engine/diagnostics.hpp).
  virtual Diagnostics diagnostics(std::size_t body_count) const = 0;
  // The fields named in `names` (engine/take_snapshot.hpp), into `s`,
  // reusing its storage.
  virtual void snapshot_into(ParticleSnapshot& s, const std::vector<std::string>& names) const = 0;
  ParticleSnapshot snapshot(const std::vector<std::string>& names) const {
    ParticleSnapshot s;
    snapshot_into(s, names);
    return s;
  }
  // Where the fastest particle is, of which body, and how fast it moves.
  virtual std::string fastest_particle(const std::vector<std::string>& body_names) const = 0;

  // The state carried from step to step (engine/carried_state.hpp), for
  // checkpoints; restore throws std::runtime_error naming a record that
  // does not fit.
  virtual void save_state(StateRecords& records) const = 0;
  virtual void restore_state(const StateRecords& records) = 0;
};

// The simulation of `spec` for its dimension and shape function, wired as
// `wiring` (with what the scene adds: engine/simulation.hpp). `fixed_dt`:
// the time step when it stays fixed, 0 when the caller sets dt before
// every step. `observer`, if given, is called as each stage starts.
std::unique_ptr<SimulationBase> make_simulation(const SystemSpec& spec, const Wiring& wiring, double fixed_dt,
                                                std::function<void(Stage)> observer = {});

}  // namespace flowmpm
