// Two neighbouring nodes of a stencil line along x, handled at once: a pair
// of doubles in one SSE2 register (a GCC/Clang vector type, so it needs no
// -march and nothing the baseline x86-64 lacks). The grid keeps one array
// per component and the stencil numbers the nodes of a line consecutively,
// so a pair is one unaligned 16-byte load or store. A line of odd length
// ends with a single node: the pair's second lane is then 0 and is never
// stored. Arithmetic is element-wise IEEE, as in scalar code.
#pragma once
#include <cstring>

namespace flowmpm {

using NodePair = double __attribute__((vector_size(16)));

// Values at nodes n and n + 1 (Count = 2), or at n and 0 (Count = 1).
template <int Count>
[[gnu::always_inline]] inline NodePair load_nodes(const double* at_n) {
  if constexpr (Count == 2) {
    NodePair v;
    std::memcpy(&v, at_n, sizeof v);
    return v;
  } else {
    return NodePair{*at_n, 0.0};
  }
}

template <int Count>
[[gnu::always_inline]] inline void store_nodes(double* at_n, NodePair v) {
  if constexpr (Count == 2) {
    std::memcpy(at_n, &v, sizeof v);
  } else {
    *at_n = v[0];
  }
}

[[gnu::always_inline]] inline double sum(NodePair v) { return v[0] + v[1]; }

}  // namespace flowmpm
