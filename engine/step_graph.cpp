#include "engine/step_graph.hpp"

#include <stdexcept>

namespace flowmpm {

const char* stage_name(Stage s) {
  switch (s) {
    case Stage::p2g_momentum: return "p2g_momentum";
    case Stage::p2g_force: return "p2g_force";
    case Stage::grid_velocity: return "grid_velocity";
    case Stage::grid_integrate: return "grid_integrate";
    case Stage::g2p_motion: return "g2p_motion";
    case Stage::g2p_stress: return "g2p_stress";
    case Stage::remap: return "remap";
  }
  return "?";
}

std::string group_name(const StageGroup& group) {
  std::string name;
  for (Stage s : group) name += (name.empty() ? "" : " & ") + std::string(stage_name(s));
  return name;
}

namespace {

// A chain of nodes; `heads` all feed the first element of `chain`.
Wiring chain(std::vector<StageGroup> heads, std::vector<StageGroup> chain) {
  Wiring w;
  w.nodes = heads;
  const int first = static_cast<int>(w.nodes.size());
  w.nodes.insert(w.nodes.end(), chain.begin(), chain.end());
  for (int h = 0; h < first; ++h) w.edges.emplace_back(h, first);
  for (int i = first; i + 1 < static_cast<int>(w.nodes.size()); ++i) w.edges.emplace_back(i, i + 1);
  return w;
}

}  // namespace

Wiring wiring_of(Scheme scheme) {
  using S = Stage;
  switch (scheme) {
    case Scheme::usf:
      return chain({{S::p2g_momentum}},
                   {{S::grid_velocity}, {S::g2p_stress}, {S::p2g_force}, {S::grid_integrate}, {S::g2p_motion}});
    case Scheme::usl:
      return chain({{S::p2g_momentum, S::p2g_force}},
                   {{S::grid_velocity}, {S::grid_integrate}, {S::g2p_motion, S::g2p_stress}});
    case Scheme::musl:
      return chain({{S::p2g_momentum, S::p2g_force}}, {{S::grid_velocity}, {S::grid_integrate}, {S::g2p_motion},
                                                       {S::remap}, {S::grid_velocity}, {S::g2p_stress}});
  }
  throw std::logic_error("unknown scheme");
}

std::vector<int> Wiring::topological_order() const {
  const int n = static_cast<int>(nodes.size());
  std::vector<int> indegree(n, 0), order;
  for (auto [from, to] : edges) ++indegree[to];
  std::vector<bool> done(n, false);
  while (static_cast<int>(order.size()) < n) {
    int next = -1;
    for (int i = 0; i < n && next < 0; ++i)
      if (!done[i] && indegree[i] == 0) next = i;
    if (next < 0) throw std::logic_error("the step wiring has a cycle");
    done[next] = true;
    order.push_back(next);
    for (auto [from, to] : edges)
      if (from == next) --indegree[to];
  }
  return order;
}

std::string Wiring::describe() const {
  // The stages that start the step run side by side ("+"), the rest follow ("->").
  std::vector<bool> has_predecessor(nodes.size(), false);
  for (auto [from, to] : edges) has_predecessor[to] = true;
  std::string text;
  for (int i : topological_order()) {
    if (!text.empty()) text += has_predecessor[i] ? " -> " : " + ";
    text += group_name(nodes[i]);
  }
  return text;
}

StepGraph::StepGraph(Wiring wiring, StageFunction run_stages)
    : wiring_(std::move(wiring)),
      run_stages_(std::move(run_stages)),
      node_seconds_(wiring_.nodes.size(), 0.0),
      start_(graph_) {
  for (int node = 0; node < static_cast<int>(wiring_.nodes.size()); ++node) {
    nodes_.push_back(std::make_unique<tbb::flow::continue_node<tbb::flow::continue_msg>>(
        graph_, [this, node](const tbb::flow::continue_msg&) {
          timed(node);
          return tbb::flow::continue_msg();
        }));
  }
  std::vector<bool> has_predecessor(nodes_.size(), false);
  for (auto [from, to] : wiring_.edges) {
    tbb::flow::make_edge(*nodes_[from], *nodes_[to]);
    has_predecessor[to] = true;
  }
  for (std::size_t i = 0; i < nodes_.size(); ++i)
    if (!has_predecessor[i]) tbb::flow::make_edge(start_, *nodes_[i]);
}

void StepGraph::timed(int node) {
  const auto begin = std::chrono::steady_clock::now();
  run_stages_(wiring_.nodes[node]);
  node_seconds_[node] += std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
}

void StepGraph::run() {
  start_.try_put(tbb::flow::continue_msg());
  graph_.wait_for_all();
}

void StepGraph::run_serial() {
  for (int i : wiring_.topological_order()) timed(i);
}

}  // namespace flowmpm
