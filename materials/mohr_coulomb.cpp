#include "materials/mohr_coulomb.hpp"

#include <stdexcept>
#include <string>

#include <Eigen/Dense>

#include "core/parameter_table.hpp"

namespace flowmpm {

MohrCoulomb MohrCoulomb::read(ParameterTable& t) { return MohrCoulomb(read_frictional(t)); }

void MohrCoulomb::unsupported(StressState kind) {
  throw std::logic_error(std::string("mohr_coulomb: no return in ") + stress_state_name(kind) +
                         " (the case reader refuses it)");
}

namespace {

// A linear surface of the principal stresses (descending), a . sigma <= b,
// with its flow direction n: the gradient of its potential.
struct Plane {
  Eigen::Vector3d a, n;
  double b;
};

}  // namespace

std::array<double, 3> MohrCoulomb::principal_return(const std::array<double, 3>& trial) const {
  const double sf = sin_phi, sp = sin_psi, T = parameters.tension_cutoff;
  // f_13 (main plane), f_12 (with it on sigma_2 = sigma_3), f_23 (with it on
  // sigma_1 = sigma_2), the cut-off on sigma_1, sigma_2, sigma_3.
  const std::array<Plane, 6> planes{{
      {{1 + sf, 0, -(1 - sf)}, {1 + sp, 0, -(1 - sp)}, strength},
      {{1 + sf, -(1 - sf), 0}, {1 + sp, -(1 - sp), 0}, strength},
      {{0, 1 + sf, -(1 - sf)}, {0, 1 + sp, -(1 - sp)}, strength},
      {{1, 0, 0}, {1, 0, 0}, T},
      {{0, 1, 0}, {0, 1, 0}, T},
      {{0, 0, 1}, {0, 0, 1}, T},
  }};
  // The candidate active sets, in order (header); -1 ends a set.
  constexpr int sets[][3] = {{0, -1, -1}, {0, 1, -1}, {0, 2, -1}, {3, -1, -1}, {3, 4, -1},
                             {0, 3, -1},  {0, 1, 3},  {0, 3, 4}};
  const Eigen::Vector3d s_trial(trial[0], trial[1], trial[2]);
  auto D = [&](const Eigen::Vector3d& n) -> Eigen::Vector3d {
    return (lambda * n.sum()) * Eigen::Vector3d::Ones() + 2.0 * mu * n;
  };
  // Round-off allowance on the checks, in Pa.
  const double tol = 1e-10 * (s_trial.cwiseAbs().maxCoeff() + parameters.cohesion);
  for (const auto& set : sets) {
    const int m = set[1] < 0 ? 1 : set[2] < 0 ? 2 : 3;
    Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 3, 3> A(m, m);
    Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 3, 1> f(m);
    for (int i = 0; i < m; ++i) {
      const Plane& pi = planes[set[i]];
      f[i] = pi.a.dot(s_trial) - pi.b;
      for (int j = 0; j < m; ++j) A(i, j) = pi.a.dot(D(planes[set[j]].n));
    }
    const Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 3, 1> dgamma = A.partialPivLu().solve(f);
    Eigen::Vector3d s = s_trial;
    bool admissible = true;
    for (int j = 0; j < m; ++j) {
      // dgamma_j times a_j . D n_j is the stress it returns by (Pa).
      admissible = admissible && dgamma[j] * A(j, j) >= -tol;
      s -= dgamma[j] * D(planes[set[j]].n);
    }
    const std::array<double, 3> r{s[0], s[1], s[2]};
    if (admissible && r[0] >= r[1] - tol && r[1] >= r[2] - tol && yield_function(r) <= tol && r[0] <= T + tol) {
      return r;
    }
  }
  return {T, T, T};
}

}  // namespace flowmpm
