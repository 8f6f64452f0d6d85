// A force on each node of a node set (per axis, each a number or
// [[t, value], ...]): N in 3D, N/m (per unit thickness) in 2D, N/m^2 (per
// unit cross-section) in 1D. A point load is a node set of one node.
#pragma once
#include <algorithm>

#include "discretisation/loads/load_context.hpp"

namespace flowmpm {

struct NodalForceLoad {
  static constexpr const char* type_name = "nodal_force";
  int node_set = 0;
  AxisFunctions force;  // per node
  std::string where;

  static NodalForceLoad read(ParameterTable& t, const LoadReadContext& c) {
    NodalForceLoad l;
    if (c.node_set_names.empty()) t.fail("node_set", "the name of a [[node_sets]] table (the case has none)");
    const std::string name = t.choice("node_set", c.node_set_names);
    l.node_set = static_cast<int>(std::ranges::find(c.node_set_names, name) - c.node_set_names.begin());
    l.force = read_axis_functions(t, "force", c.dimension, "a force per node in N (N/m in 2D)");
    l.where = t.where("node_set");
    return l;
  }

  // The nodes must be within reach of the material: a force on a node no
  // particle touches acts on nothing.
  template <int D, class Shape>
  void attach(LoadSite<D, Shape>& site) const {
    const std::string& set_name = site.node_set_names[node_set];
    auto& system = site.system;
    const auto& nodes = site.node_sets[node_set];
    std::vector<char> touched(system.grid.node_count(), 0);
    for (const auto& b : system.batches) {
      for (const auto& x : b.x) {
        const Stencil<D, Shape, false> s(system.grid, x, b.half_width);
        for (int a = 0; a < s.size; ++a)
          if (s.N(a) > 0.0) touched[s.node(a)] = 1;
      }
    }
    if (std::ranges::none_of(nodes, [&](std::size_t n) { return touched[n] != 0; })) {
      throw CaseError(where + ": expected a node set next to the material, got \"" + set_name +
                      "\", whose nodes no particle reaches: the force would act on nothing");
    }
    system.loads.nodal.push_back({"force " + axis_functions_text(force, D == 3 ? "N" : D == 2 ? "N/m" : "N/m^2") +
                                      " on each of the " + std::to_string(nodes.size()) + " nodes of node set '" +
                                      set_name + "'",
                                  nodes, force});
  }
};

}  // namespace flowmpm
