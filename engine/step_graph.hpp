// One explicit step as a oneTBB flow graph (DESIGN.md). A scheme is only a
// wiring of the same stage nodes: the Wiring lists node instances and the
// edges between them; the graph is built once per run and triggered once per
// step. Parallelism lives inside each stage (coarse graph, fine loops).
#pragma once
#include <chrono>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <tbb/flow_graph.h>

#include "io/case_file.hpp"

namespace flowmpm {

enum class Stage { p2g_momentum, p2g_force, grid_velocity, grid_integrate, g2p_motion, g2p_stress, remap };
constexpr int stage_count = 7;
const char* stage_name(Stage s);

struct Wiring {
  std::vector<Stage> nodes;                 // node instances (a stage may appear twice)
  std::vector<std::pair<int, int>> edges;   // (from, to) node indices
  // Node indices in an order that respects every edge (the serial step).
  std::vector<int> topological_order() const;
  // Human-readable: "p2g_momentum + p2g_force -> grid_velocity -> ...".
  std::string describe() const;
};

// USF:  p2g_momentum -> grid_velocity -> g2p_stress -> p2g_force -> grid_integrate -> g2p_motion
// USL:  p2g_momentum + p2g_force -> grid_velocity -> grid_integrate -> g2p_motion -> g2p_stress
// MUSL: p2g_momentum + p2g_force -> grid_velocity -> grid_integrate -> g2p_motion -> remap
//       -> grid_velocity -> g2p_stress
Wiring wiring_of(Scheme scheme);

class StepGraph {
 public:
  using StageFunction = std::function<void(Stage)>;

  // Builds the graph once; `run_stage` does the work of a stage.
  StepGraph(Wiring wiring, StageFunction run_stage);

  // Runs one step through the graph and waits for it.
  void run();
  // Runs one step serially in topological order, without the graph: the
  // reference the graph is checked against.
  void run_serial();

  const Wiring& wiring() const { return wiring_; }
  // Accumulated wall time per stage (s), summed over instances and steps.
  const std::array<double, stage_count>& stage_seconds() const { return stage_seconds_; }

 private:
  void timed(Stage s);

  Wiring wiring_;
  StageFunction run_stage_;
  std::array<double, stage_count> stage_seconds_{};
  tbb::flow::graph graph_;
  tbb::flow::broadcast_node<tbb::flow::continue_msg> start_;
  std::vector<std::unique_ptr<tbb::flow::continue_node<tbb::flow::continue_msg>>> nodes_;
};

}  // namespace flowmpm
