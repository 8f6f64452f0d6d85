// Shape-function invariants at many particle positions in 1D, 2D and 3D,
// including the cells next to the grid boundary:
//   partition of unity        sum_I N_I = 1
//   zero gradient sum         sum_I dN_I = 0
//   linear reproduction       sum_I N_I x_I = x,  sum_I x_I (x) dN_I = I
// Tolerance 1e-12: the sums are of O(1) terms, exact up to round-off.
// Then continuity: uGIMP and B-spline weights and gradients are continuous
// across a cell face, the linear gradient jumps (cell-crossing noise).
#include <doctest/doctest.h>

#include <map>
#include <random>

#include "discretisation/shapes/shape_bspline.hpp"
#include "discretisation/shapes/shape_gimp.hpp"
#include "discretisation/shapes/shape_linear.hpp"
#include "discretisation/grid/stencil.hpp"

using namespace flowmpm;

template <int D, class Shape>
void check_invariants(double half_width = 0.25) {
  Vec<D> origin, h;
  Index<D> cells;
  for (int d = 0; d < D; ++d) {
    origin[d] = -1.0 + 0.3 * d;
    h[d] = 0.25 + 0.1 * d;  // anisotropic cells
    cells[d] = 6;
  }
  const Grid<D> grid(origin, h, cells);
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int sample = 0; sample < 2000; ++sample) {
    Vec<D> x;
    for (int d = 0; d < D; ++d) {
      // Every cell the shape function allows, first and last included.
      const double lo = Shape::reach_below, hi = cells[d] - Shape::reach_above + 1;
      x[d] = origin[d] + h[d] * (lo + (hi - lo) * unit(rng));
    }
    const Stencil<D, Shape> s(grid, x, Vec<D>::Constant(half_width));
    double sum_N = 0.0;
    Vec<D> sum_dN = Vec<D>::Zero(), sum_Nx = Vec<D>::Zero();
    Eigen::Matrix<double, D, D> sum_xdN = Eigen::Matrix<double, D, D>::Zero();
    for (int a = 0; a < s.size; ++a) {
      const Vec<D> xI = grid.node_position(grid.node_ijk(s.node(a)));
      CHECK(s.N(a) >= -1e-15);
      sum_N += s.N(a);
      sum_dN += s.gradient(a);
      sum_Nx += s.N(a) * xI;
      sum_xdN += xI * s.gradient(a).transpose();
    }
    CHECK(sum_N == doctest::Approx(1.0).epsilon(1e-12));
    for (int d = 0; d < D; ++d) {
      CHECK(std::abs(sum_dN[d]) < 1e-12 / h.minCoeff());
      CHECK(sum_Nx[d] == doctest::Approx(x[d]).epsilon(1e-12));
      for (int e = 0; e < D; ++e) CHECK(sum_xdN(d, e) == doctest::Approx(d == e ? 1.0 : 0.0).epsilon(1e-12));
    }
  }
}

TEST_CASE("linear shape functions: partition of unity, zero gradient sum, linear reproduction") {
  check_invariants<1, LinearShape>();
  check_invariants<2, LinearShape>();
  check_invariants<3, LinearShape>();
}

TEST_CASE("uGIMP: the invariants for 1, 2, 3 and 4 particles per cell and axis") {
  for (double lp : {0.5, 0.25, 1.0 / 6.0, 0.125}) {
    CAPTURE(lp);
    check_invariants<1, GimpShape>(lp);
    check_invariants<2, GimpShape>(lp);
    check_invariants<3, GimpShape>(lp);
  }
}

TEST_CASE("quadratic and cubic B-splines: the invariants") {
  check_invariants<1, QuadraticBSpline>();
  check_invariants<2, QuadraticBSpline>();
  check_invariants<3, QuadraticBSpline>();
  check_invariants<1, CubicBSpline>();
  check_invariants<2, CubicBSpline>();
  check_invariants<3, CubicBSpline>();
}

namespace {

// Largest change of any node's N and dN/dx when a 1D particle moves from
// just below to just above the cell face at x = 3 h.
template <class Shape>
std::pair<double, double> jump_across_face(double lp) {
  const Grid<1> grid(Vec<1>(0.0), Vec<1>(1.0), {8});
  const double eps = 1e-9;
  std::map<std::size_t, std::pair<double, double>> below, above;
  const Stencil<1, Shape> a(grid, Vec<1>(3.0 - eps), Vec<1>(lp)), b(grid, Vec<1>(3.0 + eps), Vec<1>(lp));
  for (int k = 0; k < a.size; ++k) below[a.node(k)] = {a.N(k), a.gradient(k)[0]};
  for (int k = 0; k < b.size; ++k) above[b.node(k)] = {b.N(k), b.gradient(k)[0]};
  double dN = 0.0, dG = 0.0;
  for (std::size_t n = 0; n < grid.node_count(); ++n) {
    const auto x = below.count(n) ? below[n] : std::pair{0.0, 0.0};
    const auto y = above.count(n) ? above[n] : std::pair{0.0, 0.0};
    dN = std::max(dN, std::abs(x.first - y.first));
    dG = std::max(dG, std::abs(x.second - y.second));
  }
  return {dN, dG};
}

}  // namespace

TEST_CASE("cell crossing: linear gradients jump, uGIMP and B-splines are continuous") {
  // Linear: N continuous; dN/dx of the node on the face flips from +1/h
  // (right node of the cell below) to -1/h (left node of the cell above).
  CHECK(jump_across_face<LinearShape>(0.0).first < 1e-8);
  CHECK(jump_across_face<LinearShape>(0.0).second == doctest::Approx(2.0));
  // The smooth ones change by O(eps / h) = 1e-9 at most (tolerance 1e-7).
  for (auto [N, G] : {jump_across_face<GimpShape>(0.25), jump_across_face<QuadraticBSpline>(0.0),
                      jump_across_face<CubicBSpline>(0.0)}) {
    CHECK(N < 1e-7);
    CHECK(G < 1e-7);
  }
}

TEST_CASE("linear shape function values by hand") {
  // Particle at (0.25, 0.5) in a unit cell: weights (0.75, 0.25) x (0.5, 0.5).
  const Grid<2> grid(Vec<2>::Zero(), Vec<2>::Ones(), {2, 2});
  const Stencil<2, LinearShape> s(grid, Vec<2>(0.25, 0.5), Vec<2>::Zero());
  CHECK(s.node(0) == 0);
  CHECK(s.node(1) == 1);
  CHECK(s.node(2) == 3);
  CHECK(s.node(3) == 4);
  CHECK(s.N(0) == doctest::Approx(0.375));
  CHECK(s.N(1) == doctest::Approx(0.125));
  CHECK(s.gradient(0)[0] == doctest::Approx(-0.5));
  CHECK(s.gradient(0)[1] == doctest::Approx(-0.75));
}

// The stage loops read N and dN two nodes at a time (pair_weights); the
// pairs must visit every stencil node once, with the node's own N and dN,
// for even and odd supports.
template <int D, class Shape>
void check_pairs_match_nodes() {
  Index<D> cells;
  cells.fill(8);
  const Grid<D> grid(Vec<D>::Zero(), Vec<D>::Ones(), cells);
  const Vec<D> x = Vec<D>::Constant(3.3);
  const Stencil<D, Shape> s(grid, x, Vec<D>::Constant(0.25));
  std::map<std::size_t, int> visits;
  s.for_each_node_pair([&]<int Count>(int line, int k, std::size_t n) {
    const auto w = s.template pair_weights<Count>(line, k);
    for (int lane = 0; lane < Count; ++lane) {
      const int a = line * Shape::support + k + lane;
      ++visits[n + lane];
      CHECK(s.node(a) == n + lane);
      CHECK(w.N[lane] == s.N(a));
      for (int j = 0; j < D; ++j) CHECK(w.dN[j][lane] == s.gradient(a)[j]);
    }
    if constexpr (Count == 1) CHECK(w.N[1] == 0.0);
  });
  CHECK(visits.size() == static_cast<std::size_t>(s.size));
  for (auto [node, count] : visits) CHECK(count == 1);
}

TEST_CASE("node pairs cover the stencil with each node's N and dN") {
  check_pairs_match_nodes<1, LinearShape>();
  check_pairs_match_nodes<2, QuadraticBSpline>();
  check_pairs_match_nodes<3, LinearShape>();
  check_pairs_match_nodes<3, GimpShape>();
  check_pairs_match_nodes<3, QuadraticBSpline>();
  check_pairs_match_nodes<3, CubicBSpline>();
}
