// Where each contact body's particles lie around a grid node: the sums
// sum_p w_p x_p and sum_p w_p x_p x_p^T (upper triangle), w_p = N_Ip V_p,
// x relative to the grid's origin (sum_p w_p is the field's nodal volume,
// ContactFields::volume). From two bodies' sums, the direction that
// separates their particles at the node (`separating_normal`): the
// least-squares fit of which body a particle belongs to (0 for a, 1 for
// b) by a linear function c + g . x over both bodies' particles, weighted
// by w_p, has g = C^-1 (x_b - x_a) times a positive factor, C the weighted
// position covariance of the particles of both and x_a, x_b each body's
// weighted mean position (linear discriminant analysis, [Hastie 2009]
// 4.3; NairnMPM's regression normals [NairnMPM]). It looks only at where
// the particles of the two bodies are, so a face of either body that the
// other does not touch (a free side face at a corner, the end of a floor)
// does not tilt it, where the bodies' volume gradients both do.
#pragma once
#include <array>
#include <vector>

#include <Eigen/Eigenvalues>

#include "core/vec.hpp"

namespace flowmpm {

// C^-1 v over the directions in which the covariance C has a variance
// above `floor`; the others (particles that do not spread along them: a
// single row, slivers of weight) are left out.
template <int D>
Vec<D> inverse_over_spread(const Eigen::Matrix<double, D, D>& C, const Vec<D>& v, double floor) {
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, D, D>> eigen(C);
  Vec<D> result = Vec<D>::Zero();
  for (int k = 0; k < D; ++k) {
    const double variance = eigen.eigenvalues()[k];
    if (variance > floor) {
      const Vec<D> axis = eigen.eigenvectors().col(k);
      result += (axis.dot(v) / variance) * axis;
    }
  }
  return result;
}

template <int D>
struct ParticleSpread {
  static constexpr int terms = D + D * (D + 1) / 2;
  std::array<std::vector<double>, terms> sum;  // sum_p w_p q_p per term and node

  void allocate(std::size_t nodes) {
    for (auto& s : sum) s.assign(nodes, 0.0);
  }

  // The weighted mean position and position covariance at node n, from
  // the sums over w_p, the field's nodal volume `volume` > 0 there.
  Vec<D> mean(std::size_t n, double volume) const {
    Vec<D> x;
    for (int i = 0; i < D; ++i) x[i] = sum[i][n] / volume;
    return x;
  }
  Eigen::Matrix<double, D, D> covariance(std::size_t n, double volume, const Vec<D>& mean) const {
    Eigen::Matrix<double, D, D> C;
    int t = D;
    for (int i = 0; i < D; ++i)
      for (int j = i; j < D; ++j, ++t) C(i, j) = C(j, i) = sum[t][n] / volume - mean[i] * mean[j];
    return C;
  }

  // q_p for the position x (from the grid's origin).
  static std::array<double, terms> particle_terms(const Vec<D>& x) {
    std::array<double, terms> q;
    int t = 0;
    for (int i = 0; i < D; ++i) q[t++] = x[i];
    for (int i = 0; i < D; ++i)
      for (int j = i; j < D; ++j) q[t++] = x[i] * x[j];
    return q;
  }
};

// The unit normal at node n pointing from body a's particles to body b's,
// from their sums and nodal volumes (both > 0); directions along which the
// particles of both spread less than sqrt(floor) (m) are left out. False
// where no direction separates them.
template <int D>
bool separating_normal(const ParticleSpread<D>& a, double volume_a, const ParticleSpread<D>& b, double volume_b,
                       std::size_t n, double floor, Vec<D>& normal) {
  const double volume = volume_a + volume_b;
  const Vec<D> mean_a = a.mean(n, volume_a), mean_b = b.mean(n, volume_b);
  Vec<D> mean;
  for (int i = 0; i < D; ++i) mean[i] = (a.sum[i][n] + b.sum[i][n]) / volume;
  // The covariance of both bodies' particles together.
  Eigen::Matrix<double, D, D> C;
  int t = D;
  for (int i = 0; i < D; ++i)
    for (int j = i; j < D; ++j, ++t) C(i, j) = C(j, i) = (a.sum[t][n] + b.sum[t][n]) / volume - mean[i] * mean[j];
  const Vec<D> g = inverse_over_spread<D>(C, Vec<D>(mean_b - mean_a), floor);
  const double length = g.norm();
  if (!(length > 0.0)) return false;
  normal = g / length;
  return true;
}

}  // namespace flowmpm
