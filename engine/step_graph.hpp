// One explicit step as a oneTBB flow graph (DESIGN.md). A scheme is only a
// wiring of the same stage nodes: the Wiring lists node instances and the
// edges between them; the graph is built once per run and triggered once per
// step. Parallelism lives inside each stage (coarse graph, fine loops).
// A node may run two particle stages in one pass over the particles ("&"),
// where both read the same particle state: each particle's stencil is then
// evaluated once instead of twice.
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
const char* stage_name(Stage s);

// The stages one graph node runs, in order, in one pass.
using StageGroup = std::vector<Stage>;
// "p2g_momentum & p2g_force".
std::string group_name(const StageGroup& group);

struct Wiring {
  std::vector<StageGroup> nodes;            // node instances (a stage may appear twice)
  std::vector<std::pair<int, int>> edges;   // (from, to) node indices
  // Node indices in an order that respects every edge (the serial step).
  std::vector<int> topological_order() const;
  // Human-readable: "p2g_momentum & p2g_force -> grid_velocity -> ...",
  // with "+" between nodes that start the step side by side.
  std::string describe() const;
};

// USF:  p2g_momentum -> grid_velocity -> g2p_stress -> p2g_force -> grid_integrate -> g2p_motion
// USL:  p2g_momentum & p2g_force -> grid_velocity -> grid_integrate -> g2p_motion & g2p_stress
// MUSL: p2g_momentum & p2g_force -> grid_velocity -> grid_integrate -> g2p_motion -> remap
//       -> grid_velocity -> g2p_stress
Wiring wiring_of(Scheme scheme);

class StepGraph {
 public:
  using StageFunction = std::function<void(const StageGroup&)>;

  // Builds the graph once; `run_stages` does the work of a node.
  StepGraph(Wiring wiring, StageFunction run_stages);

  // Runs one step through the graph and waits for it.
  void run();
  // Runs one step serially in topological order, without the graph: the
  // reference the graph is checked against.
  void run_serial();

  const Wiring& wiring() const { return wiring_; }
  // Accumulated wall time per node of the wiring (s), summed over steps.
  const std::vector<double>& node_seconds() const { return node_seconds_; }

 private:
  void timed(int node);

  Wiring wiring_;
  StageFunction run_stages_;
  std::vector<double> node_seconds_;
  tbb::flow::graph graph_;
  tbb::flow::broadcast_node<tbb::flow::continue_msg> start_;
  std::vector<std::unique_ptr<tbb::flow::continue_node<tbb::flow::continue_msg>>> nodes_;
};

}  // namespace flowmpm
