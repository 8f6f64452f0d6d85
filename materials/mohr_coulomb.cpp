#include "materials/mohr_coulomb.hpp"

#include <algorithm>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "core/number_text.hpp"
#include "core/parameter_table.hpp"

namespace flowmpm {

MohrCoulomb MohrCoulomb::read(ParameterTable& t) {
  Parameters p;
  static_cast<FrictionalParameters&>(p) = read_frictional(t);
  MohrCoulombSoftening& s = p.softening;
  constexpr double radian = std::numbers::pi / 180.0;
  const double phi = p.friction_angle / radian, psi = p.dilation_angle / radian;
  s.on = t.has("residual_friction_angle") || t.has("residual_cohesion") || t.has("residual_dilation_angle");
  if (!s.on) {
    for (const char* key : {"softening_shear_strain", "softening_shear_displacement"})
      t.require(!t.has(key), key,
                "no softening range without a residual strength (residual_friction_angle, residual_cohesion "
                "or residual_dilation_angle)");
    return MohrCoulomb(p);
  }
  const double phi_r = t.number_or("residual_friction_angle", phi);
  t.require(phi_r > 0.0 && phi_r <= phi, "residual_friction_angle",
            "a residual friction angle in (0, phi] = (0, " + readable_text(phi) + "] degrees");
  s.friction_angle = phi_r * radian;
  s.cohesion = t.number_or("residual_cohesion", p.cohesion);
  t.require(s.cohesion >= 0.0 && s.cohesion <= p.cohesion, "residual_cohesion",
            "a residual cohesion in [0, c] = [0, " + readable_text(p.cohesion) + "] Pa");
  const double psi_r = t.number_or("residual_dilation_angle", std::min(psi, phi_r));
  t.require(psi_r >= 0.0 && psi_r <= std::min(psi, phi_r), "residual_dilation_angle",
            "a residual dilation angle in [0, min(psi, residual phi)] = [0, " +
                readable_text(std::min(psi, phi_r)) + "] degrees");
  s.dilation_angle = psi_r * radian;
  s.crack_band = t.has("softening_shear_displacement");
  const char* key = s.crack_band ? "softening_shear_displacement" : "softening_shear_strain";
  t.require(t.has("softening_shear_strain") != s.crack_band, key,
            "exactly one of softening_shear_strain (the plastic shear strain range [start, end], -) and "
            "softening_shear_displacement (the crack band's slip range [start, end], m) with a residual strength");
  const std::vector<double> range = t.numbers(key, 2);
  t.require(range[0] >= 0.0 && range[1] > range[0], key, "[start, end] with 0 <= start < end");
  s.start = range[0], s.end = range[1];
  return MohrCoulomb(p);
}

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

std::array<double, 3> MohrCoulomb::principal_return(const std::array<double, 3>& trial, const Surface& surface) const {
  const double sf = surface.sin_phi, sp = surface.sin_psi, T = surface.tension, strength = surface.strength;
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
  const double tol = 1e-10 * (s_trial.cwiseAbs().maxCoeff() + surface.cohesion);
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
    if (admissible && r[0] >= r[1] - tol && r[1] >= r[2] - tol && surface.yield_function(r) <= tol && r[0] <= T + tol) {
      return r;
    }
  }
  return {T, T, T};
}

}  // namespace flowmpm
