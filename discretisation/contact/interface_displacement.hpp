// A body's displacement at a grid node, for an imperfect interface
// (contact_law_interface.hpp, tasks/contact.hpp): the linear fit
//   u(x) ~ c + B (x - x_I)
// to the displacements u_p = x_p - X_p of the body's particles near node I,
// weighted by w_p = N_Ip V_p (least squares), evaluated at the node: c.
// With the weighted means x_bar, u_bar, the position covariance C and the
// position-displacement covariance K = cov(x, u),
//   c = u_bar - K^T C^-1 (x_bar - x_I),
// the mean displacement carried from the particles' centroid to the node
// by the fitted gradient B = (C^-1 K)^T. The particles behind a surface
// node lie inside the body (3h/8 deep on average at 2 per cell with linear
// shape functions): their mean alone would read the body's own shear and
// rotation over that depth as a jump across the interface (a rigid
// rotation theta of two bonded bodies as theta 3h/4), where the fit is
// exact for any linear displacement field. Directions in which the
// particles do not spread (a single row, slivers of weight: variance
// below `floor`) take the mean, unextrapolated.
// The sums are sum_p w_p q_p of the particle terms q = (u, x u^T), x
// relative to the grid's origin; sum_p w_p, sum_p w_p x and sum_p w_p x x^T
// are the field's nodal volume (ContactFields::volume) and its particle
// spread (particle_spread.hpp), which the normals use too.
#pragma once
#include <array>
#include <vector>

#include "core/vec.hpp"
#include "discretisation/contact/particle_spread.hpp"

namespace flowmpm {

template <int D>
struct InterfaceDisplacement {
  static constexpr int terms = D + D * D;
  // sum_p w_p q_p per term and node; empty for a field no interface bonds.
  std::array<std::vector<double>, terms> sum;

  bool empty() const { return sum[0].empty(); }
  void allocate(std::size_t nodes) {
    for (auto& s : sum) s.assign(nodes, 0.0);
  }

  // q_p for position x (from the grid's origin) and displacement u.
  static std::array<double, terms> particle_terms(const Vec<D>& x, const Vec<D>& u) {
    std::array<double, terms> q;
    int t = 0;
    for (int i = 0; i < D; ++i) q[t++] = u[i];
    for (int i = 0; i < D; ++i)
      for (int j = 0; j < D; ++j) q[t++] = x[i] * u[j];
    return q;
  }

  // c at node n (position `node` from the grid's origin), the field's
  // nodal volume there `volume` > 0 and its particle spread `spread`.
  Vec<D> at_node(std::size_t n, double volume, const ParticleSpread<D>& spread, const Vec<D>& node,
                 double floor) const {
    using Matrix = Eigen::Matrix<double, D, D>;
    const Vec<D> x_bar = spread.mean(n, volume);
    const Matrix C = spread.covariance(n, volume, x_bar);
    Vec<D> u_bar;
    Matrix K;
    int t = 0;
    for (int i = 0; i < D; ++i) u_bar[i] = sum[t++][n] / volume;
    for (int i = 0; i < D; ++i)
      for (int j = 0; j < D; ++j) K(i, j) = sum[t++][n] / volume - x_bar[i] * u_bar[j];
    // C^-1 (x_bar - x_I) over the directions the particles spread in.
    const Vec<D> scaled = inverse_over_spread<D>(C, Vec<D>(x_bar - node), floor);
    return u_bar - K.transpose() * scaled;
  }
};

}  // namespace flowmpm
