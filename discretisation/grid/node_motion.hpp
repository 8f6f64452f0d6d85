// A node's velocity v_I and velocity change dv_I side by side in one
// vector register, for g2p's sums with shape functions of wide support
// (tasks/g2p.hpp): one load per node, and one multiply-add each gives
// sum_I N_Ip (v_I, dv_I) and the columns sum_I (v_I, dv_I) dN_Ip/dx_j of
// the velocity gradient. Lanes: v in 0 .. D-1, dv in D .. 2D-1, the rest 0
// (8 lanes in 3D, one AVX-512 register or two AVX2 ones; 4 in 2D, 2 in 1D).
// A GCC/Clang vector type: it builds without -march, as the portable build
// needs, and its arithmetic is element-wise IEEE.
#pragma once

namespace flowmpm {

// Vectors of 2, 4 and 8 doubles (a vector size given by a template
// parameter is not subscriptable in GCC 12).
template <int Lanes>
struct DoubleLanes;
template <>
struct DoubleLanes<2> {
  using type = double __attribute__((vector_size(16)));
};
template <>
struct DoubleLanes<4> {
  using type = double __attribute__((vector_size(32)));
};
template <>
struct DoubleLanes<8> {
  using type = double __attribute__((vector_size(64)));
};

template <int D>
struct NodeMotion {
  static constexpr int lanes = D == 3 ? 8 : 2 * D;
  using Lanes = typename DoubleLanes<lanes>::type;
  Lanes value;
};

}  // namespace flowmpm
