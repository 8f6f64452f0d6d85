#include "engine/step_graph.hpp"

#include <algorithm>
#include <chrono>
#include <stdexcept>

namespace flowmpm {

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

bool Wiring::stress_from_updated_grid() const {
  bool updated = false;
  for (int node : topological_order()) {
    for (Stage stage : nodes[node]) {
      if (stage == Stage::g2p_stress) return updated;
      if (stage == Stage::grid_integrate) updated = true;
      if (stage == Stage::grid_velocity) updated = false;
    }
  }
  return false;
}

std::string Wiring::describe() const {
  // Chains of nodes joined by their edges, in topological order; a chain
  // that reaches a node already written ends with it (a join), and chains
  // that run beside one another are separated by " || ".
  const int n = static_cast<int>(nodes.size());
  std::vector<std::vector<int>> successors(n);
  for (auto [from, to] : edges) successors[from].push_back(to);
  std::vector<bool> written(n, false);
  std::string text;
  for (int start : topological_order()) {
    if (written[start]) continue;
    if (!text.empty()) text += " || ";
    text += group_name(nodes[start]);
    written[start] = true;
    for (int at = start; !successors[at].empty();) {
      const auto next = std::ranges::find_if(successors[at], [&](int s) { return !written[s]; });
      if (next == successors[at].end()) {
        text += " -> " + group_name(nodes[successors[at].front()]);
        break;
      }
      text += " -> " + group_name(nodes[*next]);
      written[*next] = true;
      at = *next;
    }
  }
  return text;
}

void Wiring::check_disjoint() const {
  // reaches[i][j]: a path of edges leads from node i to node j.
  const int n = static_cast<int>(nodes.size());
  std::vector<std::vector<bool>> reaches(n, std::vector<bool>(n, false));
  const std::vector<int> order = topological_order();
  for (auto it = order.rbegin(); it != order.rend(); ++it) {
    for (auto [from, to] : edges) {
      if (from != *it) continue;
      reaches[from][to] = true;
      for (int k = 0; k < n; ++k)
        if (reaches[to][k]) reaches[from][k] = true;
    }
  }
  auto access = [&](int node) {
    StageAccess a;
    for (Stage s : nodes[node]) a.reads |= stage_access(s).reads, a.writes |= stage_access(s).writes;
    return a;
  };
  for (int i = 0; i < n; ++i) {
    for (int j = i + 1; j < n; ++j) {
      if (reaches[i][j] || reaches[j][i]) continue;
      const StageAccess a = access(i), b = access(j);
      const unsigned clash = (a.writes & (b.reads | b.writes)) | (b.writes & a.reads);
      if (clash == 0) continue;
      throw std::logic_error("the step wiring lets \"" + group_name(nodes[i]) + "\" and \"" + group_name(nodes[j]) +
                             "\" run at the same time, but one writes what the other reads or writes (" +
                             data_names(clash) + "): wire a path between them");
    }
  }
}

StepGraph::StepGraph(Wiring wiring, NodeFunction run_node)
    : wiring_(std::move(wiring)),
      run_node_(std::move(run_node)),
      node_seconds_(wiring_.nodes.size(), 0.0),
      serial_order_(wiring_.topological_order()),
      start_(graph_) {
  wiring_.check_disjoint();
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
  run_node_(node);
  node_seconds_[node] += std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
}

void StepGraph::run() {
  start_.try_put(tbb::flow::continue_msg());
  graph_.wait_for_all();
}

void StepGraph::run_serial() {
  for (int i : serial_order_) timed(i);
}

}  // namespace flowmpm
