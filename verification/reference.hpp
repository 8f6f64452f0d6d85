// The analytical solution a case is measured against, chosen by the `type`
// of its [reference] table (docs/validation/README.md). Each solution reads and
// checks its own keys, may set initial conditions, is sampled during the
// run, reports named error norms for summary.json and sweeps, may report
// named measures (quantities without a closed form to compare with, such
// as a final length) for summary.json, and lists what its samples
// accumulate for checkpoints (visit_state). Adding one is one new file and
// one line in the variant below.
#pragma once
#include <cstdint>
#include <map>
#include <string>
#include <variant>

#include "core/registry.hpp"
#include "engine/simulation_base.hpp"
#include "verification/axial_vibration.hpp"
#include "verification/cantilever.hpp"
#include "verification/column_collapse.hpp"
#include "verification/column_self_weight.hpp"
#include "verification/cylinder_transport.hpp"
#include "verification/elastic_impact.hpp"
#include "verification/elastic_wave.hpp"
#include "verification/incline.hpp"
#include "verification/lap_shear.hpp"
#include "verification/plate_with_hole.hpp"
#include "verification/prandtl_punch.hpp"
#include "verification/rigid_rotation.hpp"
#include "verification/slab_transport.hpp"
#include "verification/swelling_bending.hpp"
#include "verification/swelling_slab.hpp"
#include "verification/taylor_impact.hpp"
#include "verification/thermal_stress.hpp"
#include "verification/thick_cylinder.hpp"
#include "verification/uniaxial_stress.hpp"
#include "verification/uniform_stress.hpp"

namespace flowmpm {

using ReferenceSolution =
    std::variant<AxialVibration, ElasticWave, UniaxialStress, ColumnSelfWeight, SlabTransport, ThermalStress,
                 SwellingSlab, SwellingBending, UniformStressReference, PlateWithHole, ThickCylinder, Cantilever,
                 ElasticImpact, TaylorImpact, Incline, PrandtlPunch, LapShear, RigidRotation,
                 CylinderTransport, ColumnCollapse>;
using ReferenceSolutions = Registry<ReferenceSolution>;

class Reference {
 public:
  // Reads a [reference] table: `type`, the solution's own keys, and
  // `samples`, how many times the errors are sampled (0: every step).
  static Reference read(ParameterTable& t, const ReferenceContext& context) {
    Reference r{ReferenceSolutions::read(t, "type", context)};
    r.samples_ = t.integer_or("samples", 0);
    t.require(r.samples_ >= 0, "samples", "a number of error samples >= 0 (0: every step)");
    return r;
  }

  const char* type() const { return ReferenceSolutions::name_of(solution_); }
  std::int64_t samples() const { return samples_; }

  template <int D, class Shape>
  void initialise(DiscreteSystem<D, Shape>& system) const {
    std::visit([&](const auto& s) { s.initialise(system); }, solution_);
  }
  template <int D, class Shape>
  void sample(const DiscreteSystem<D, Shape>& system) {
    std::visit([&](auto& s) { s.sample(system); }, solution_);
  }
  // The same on a simulation of any dimension and shape function
  // (compiled once, in verification/reference.cpp).
  void initialise(SimulationBase& simulation) const;
  void sample(const SimulationBase& simulation);
  std::map<std::string, double> errors() const {
    return std::visit([](const auto& s) { return s.errors(); }, solution_);
  }
  // Calls f(name, value) for what the samples have accumulated, which a
  // checkpoint saves and a restart restores (engine/state_records.hpp).
  template <class F>
  void visit_state(F&& f) {
    std::visit([&](auto& s) { s.visit_state(f); }, solution_);
  }
  // Empty for a solution without measures.
  std::map<std::string, double> measures() const {
    return std::visit(
        [](const auto& s) -> std::map<std::string, double> {
          if constexpr (requires { s.measures(); }) {
            return s.measures();
          } else {
            return {};
          }
        },
        solution_);
  }

 private:
  explicit Reference(ReferenceSolution solution) : solution_(std::move(solution)) {}
  ReferenceSolution solution_;
  std::int64_t samples_ = 0;
};

}  // namespace flowmpm
