// One explicit step as a oneTBB flow graph. A scheme (engine/schemes.hpp)
// is only a wiring of the same stage nodes: the Wiring lists node instances
// and the edges between them; the graph is built once per run and triggered
// once per step. Parallelism lives inside each stage (coarse graph, fine
// loops). A node may run two particle stages in one pass over the particles
// ("&"), where both read the same particle state: each particle's stencil is
// then evaluated once instead of twice. Nodes without a path between them
// run concurrently (the transport branch beside the momentum stages).
#pragma once
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <tbb/flow_graph.h>

#include "tasks/stage.hpp"

namespace flowmpm {

struct Wiring {
  std::vector<StageGroup> nodes;            // node instances (a stage may appear twice)
  std::vector<std::pair<int, int>> edges;   // (from, to) node indices
  // Node indices in an order that respects every edge (the serial step).
  std::vector<int> topological_order() const;
  // Whether the stress update takes the grid velocity after its update
  // (USL: grid_integrate is the last grid stage before g2p_stress), not one
  // mapped from the particles (USF, MUSL: grid_velocity is).
  bool stress_from_updated_grid() const;
  // Human-readable: "p2g_momentum & p2g_force -> grid_velocity -> ...";
  // a branch that runs beside follows " || " and ends with the node it
  // joins before: "... || transport_p2g -> ... -> transport_g2p -> g2p_motion & g2p_stress".
  std::string describe() const;
  // Throws std::logic_error naming both nodes when two nodes without a path
  // between them (which the graph may run at the same time) write data the
  // other reads or writes (tasks/stage.hpp stage_access).
  void check_disjoint() const;
};

class StepGraph {
 public:
  // Runs the work of node `node` of the wiring.
  using NodeFunction = std::function<void(int node)>;

  // Builds the graph once, after wiring.check_disjoint().
  StepGraph(Wiring wiring, NodeFunction run_node);

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
  NodeFunction run_node_;
  std::vector<double> node_seconds_;
  std::vector<int> serial_order_;
  tbb::flow::graph graph_;
  tbb::flow::broadcast_node<tbb::flow::continue_msg> start_;
  std::vector<std::unique_ptr<tbb::flow::continue_node<tbb::flow::continue_msg>>> nodes_;
};

}  // namespace flowmpm
