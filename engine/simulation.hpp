// A running simulation: the DiscreteSystem, the step graph wired for a
// scheme (with nonlocal_settle after g2p_stress where a model asks for
// nonlocal averages, and the transport branch where the scene conducts
// heat or diffuses solvent) with each node's pass resolved once
// (tasks/stage_table.hpp), and what the time loop and the writers read off
// it. Its members are compiled once per dimension and shape function, in
// the engine library (engine/simulation_impl.hpp,
// engine/simulation_instances.cpp.in): including this header compiles no
// kernel.
#pragma once
#include <functional>
#include <string>
#include <vector>

#include "discretisation/discrete_system.hpp"
#include "discretisation/shapes/shape_functions.hpp"
#include "discretisation/system_spec.hpp"
#include "engine/schemes.hpp"
#include "engine/simulation_base.hpp"
#include "engine/step_graph.hpp"
#include "tasks/stage.hpp"

namespace flowmpm {

template <int D, class Shape>
class Simulation final : public SimulationBase {
 public:
  // `wiring`: the scheme's; the transport branch is added when the scene
  // needs it (step_wiring), beside the momentum stages unless `branch`
  // says otherwise. `observer`, if given, is called as each stage starts
  // (from any thread; for the stages of one node, in their order, as the
  // node starts). `fixed_dt`: the time step when it stays fixed, 0 when the
  // caller sets system().dt before every step.
  Simulation(const SystemSpec& spec, const Wiring& wiring, double fixed_dt,
             std::function<void(Stage)> observer = {}, TransportBranch branch = TransportBranch::beside);

  DiscreteSystem<D, Shape>& system() { return system_; }
  const DiscreteSystem<D, Shape>& system() const { return system_; }
  const StepGraph& graph() const { return graph_; }

  // SimulationBase
  int dimension() const override { return D; }
  ShapeChoice shape() const override { return shape_; }
  const char* shape_function() const override { return Shape::name; }
  StressState stress_state() const override { return system_.stress_state; }
  const Wiring& wiring() const override { return graph_.wiring(); }
  void advance() override;
  void advance_serial() override;
  SystemScalars& scalars() override { return system_; }
  const SystemScalars& scalars() const override { return system_; }
  SystemSize size() const override;
  std::int64_t unsettled_steps() const override { return system_.nonlocal ? system_.nonlocal->unsettled_steps : 0; }
  bool damped() const override { return system_.damping.has_value(); }
  bool in_contact() const override { return system_.contact.has_value(); }
  void measure_speed() override;
  Diagnostics diagnostics(std::size_t body_count) const override;
  void snapshot_into(ParticleSnapshot& s, const std::vector<std::string>& names) const override;
  using SimulationBase::snapshot;
  std::string fastest_particle(const std::vector<std::string>& body_names) const override;
  void save_state(StateRecords& records) const override;
  void restore_state(const StateRecords& records) override;

 private:
  void run_node(int node);
  template <class RunStep>
  void finish_step(RunStep&& run_step);

  DiscreteSystem<D, Shape> system_;
  ShapeChoice shape_;
  double fixed_dt_;
  std::function<void(Stage)> observer_;
  std::vector<void (*)(DiscreteSystem<D, Shape>&)> passes_;  // per node (tasks/stage_table.hpp)
  StepGraph graph_;
};

// Compiled in the engine library, nowhere else.
#define FLOWMPM_EXTERN_SIMULATION(Shape)          \
  extern template class Simulation<1, Shape>;     \
  extern template class Simulation<2, Shape>;     \
  extern template class Simulation<3, Shape>;
FLOWMPM_SHAPE_FUNCTIONS(FLOWMPM_EXTERN_SIMULATION)
#undef FLOWMPM_EXTERN_SIMULATION

}  // namespace flowmpm
