// What the frictional (soil) models share, mohr_coulomb.hpp and
// drucker_prager.hpp: small strain, isotropic linear elasticity (lambda,
// mu = G, K = lambda + 2 mu / 3), perfect plasticity with a friction angle
// phi, cohesion c, dilation angle psi (the flow potential is the yield
// function with psi for phi: non-associated unless psi = phi) and a tension
// cut-off T in [0, c cot phi], c cot phi the apex of the yield surface on the
// hydrostatic axis. Sign convention: tension positive.
// The stress turns with the material (rotation.hpp, Hughes-Winget), so a
// rigid rotation rotates it and does not load it; the isotropic expansion
// increment th takes no stress (the return sees d eps - th I,
// materials/expansion.hpp). Both returns are exact for the elastic trial
// (backward Euler on linear yield surfaces and potentials, so the returned
// stress is the closest point in the energy norm for associated flow).
// Stress states: 3D, plane strain and axisymmetric, where every strain
// component is known (eps_zz = 0 or the hoop strain v_r / r); plane stress
// and 1D uniaxial stress, whose out-of-plane strain would follow from the
// return on an apex or edge, are refused when the case is read (supports()).
// The state records, from the plastic strain increment
// d eps_p = C^-1 (sigma_trial - sigma) in principal axes, the plastic shear
// strain (the sum of max - min of the principal d eps_p, gamma_max), the
// plastic volumetric strain (the sum of tr d eps_p, dilation positive) and
// the energy dissipated, the sum of sigma : d eps_p with the returned
// stress (as von_mises.hpp).
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include <Eigen/Eigenvalues>

#include "core/voigt.hpp"
#include "materials/expansion.hpp"
#include "materials/lame.hpp"
#include "materials/material_input.hpp"
#include "materials/rotation.hpp"
#include "materials/state_variable.hpp"
#include "materials/stress_state.hpp"
#include "materials/transport_properties.hpp"

namespace flowmpm {

class ParameterTable;

struct FrictionalParameters {
  double density = 0.0;         // kg/m^3
  double youngs_modulus = 0.0;  // Pa
  double poisson_ratio = 0.0;   // -
  double friction_angle = 0.0;  // phi (rad)
  double cohesion = 0.0;        // c (Pa)
  double dilation_angle = 0.0;  // psi (rad)
  double tension_cutoff = 0.0;  // T (Pa)
  TransportProperties transport;
  Expansion expansion;

  // The apex of the yield surface, c cot phi (Pa; mean stress, tension positive).
  double apex() const { return cohesion / std::tan(friction_angle); }
};

// Reads and validates the keys both models share: the isotropic
// elasticity, friction_angle (degrees, in (0, 90)), cohesion (Pa, >= 0,
// default 0), dilation_angle (degrees, in [0, phi], default 0) and
// tension_cutoff (Pa, in [0, c cot phi], default the apex), then transport
// and expansion as the other isotropic models.
FrictionalParameters read_frictional(ParameterTable& t);

struct FrictionalState {
  double shear = 0.0;       // plastic shear strain, sum of max - min of the principal d eps_p (-)
  double volumetric = 0.0;  // plastic volumetric strain, sum of tr d eps_p (-; dilation positive)
  double dissipated = 0.0;  // plastic work sigma : d eps_p (J/m^3)
  double cell_length = 0.0;  // the particle's cell size (m), for mohr_coulomb's crack band softening; else 0
};

inline constexpr std::array<StateVariable, 3> frictional_state_variables{
    {{"plastic_shear_strain", "-"}, {"plastic_volumetric_strain", "-"}, {"dissipated_energy", "J/m^3"}}};
inline void frictional_state_values(const FrictionalState& s, double* out) {
  out[0] = s.shear;
  out[1] = s.volumetric;
  out[2] = s.dissipated;
}

// Plane stress and uniaxial stress are refused (header).
constexpr bool frictional_supports(StressState kind) {
  return kind != StressState::plane_stress && kind != StressState::uniaxial_stress;
}

// What both models are besides their yield surface and return: the
// parameters (P: FrictionalParameters or one derived from it), the elastic
// constants and the members the engine asks of every model
// (materials/material.hpp) that do not depend on the surface.
template <class P>
struct FrictionalModel {
  P parameters;
  double lambda = 0.0, mu = 0.0, K = 0.0;

  explicit FrictionalModel(const P& p)
      : parameters(p),
        lambda(lame_lambda(p.youngs_modulus, p.poisson_ratio)),
        mu(lame_mu(p.youngs_modulus, p.poisson_ratio)),
        K(lambda + 2.0 * mu / 3.0) {}

  static constexpr auto state_variables = frictional_state_variables;
  void state_values(const FrictionalState& s, double* out) const { frictional_state_values(s, out); }
  static constexpr bool supports(StressState kind) { return frictional_supports(kind); }

  double density() const { return parameters.density; }
  const TransportProperties& transport() const { return parameters.transport; }
  // P wave of the elastic material, sqrt((lambda + 2 mu) / rho) (m/s).
  double wave_speed() const { return std::sqrt((lambda + 2.0 * mu) / parameters.density); }

  double stored_energy(const FrictionalState&, const Voigt& sigma, const Voigt&) const {
    return isotropic_stored_energy(sigma, K, mu);
  }
  double dissipated_energy(const FrictionalState& state) const { return state.dissipated; }
  double expansion_work(const FrictionalState&, const Voigt& sigma, const MaterialInput& in) const {
    return parameters.expansion.isotropic_work(sigma, in);
  }
  bool expands() const { return parameters.expansion.any(); }
};

// The elastic trial of a step: the stress turned with the spin of dL, plus
// C d eps (every component of d eps known: 3D, plane strain, axisymmetric).
template <StressState Kind>
[[gnu::always_inline]] inline void elastic_trial(Voigt& sigma, const Voigt& deps, const Eigen::Matrix3d& dL,
                                                 double lambda, double mu) {
  rotate_with_spin<Kind>(sigma, dL);
  const double tr = deps[0] + deps[1] + deps[2];
  for (int i = 0; i < 3; ++i) sigma[i] += lambda * tr + 2.0 * mu * deps[i];
  for (int i = 3; i < 6; ++i) sigma[i] += 2.0 * mu * deps[i];
}

// J2 = s : s / 2 of a stress with mean stress p.
[[gnu::always_inline]] inline double deviatoric_j2(const Voigt& sigma, double p) {
  const double a = sigma[0] - p, b = sigma[1] - p, c = sigma[2] - p;
  return 0.5 * (a * a + b * b + c * c) + sigma[3] * sigma[3] + sigma[4] * sigma[4] + sigma[5] * sigma[5];
}

// The principal values of a symmetric tensor, largest first, and the
// coaxial tensor of new principal values. 3D: Eigen's closed-form
// eigensolver. Plane strain and axisymmetric: zz is principal (xz = yz = 0)
// and the in-plane pair is Mohr's circle, centre m, radius r, direction
// (cos 2 theta, sin 2 theta).
template <StressState Kind>
struct PrincipalAxes {
  std::array<double, 3> value{};  // descending
  std::array<int, 3> slot{};      // 3D: eigenvector column; 2D: 0 the circle's top, 1 its bottom, 2 zz
  Eigen::Matrix3d vectors;        // 3D only
  double c2 = 1.0, s2 = 0.0;      // 2D only

  explicit PrincipalAxes(const Voigt& a) {
    if constexpr (Kind == StressState::three_d) {
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver;
      solver.computeDirect(tensor_of(a));
      vectors = solver.eigenvectors();
      for (int i = 0; i < 3; ++i) value[i] = solver.eigenvalues()[2 - i], slot[i] = 2 - i;
    } else {
      const double m = 0.5 * (a[0] + a[1]), d = 0.5 * (a[0] - a[1]);
      const double r = std::hypot(d, a[5]);
      if (r > 0.0) c2 = d / r, s2 = a[5] / r;
      std::array<double, 3> v{m + r, m - r, a[2]};
      slot = {0, 1, 2};
      std::sort(slot.begin(), slot.end(), [&](int i, int j) { return v[i] > v[j]; });
      for (int i = 0; i < 3; ++i) value[i] = v[slot[i]];
    }
  }

  // a with its principal values changed to `to` (descending, as value):
  // a + sum_i (to_i - value_i) n_i n_i^T.
  void rebuild(Voigt& a, const std::array<double, 3>& to) const {
    if constexpr (Kind == StressState::three_d) {
      Eigen::Matrix3d change = Eigen::Matrix3d::Zero();
      for (int i = 0; i < 3; ++i) {
        const Eigen::Vector3d n = vectors.col(slot[i]);
        change += (to[i] - value[i]) * n * n.transpose();
      }
      const Voigt c = voigt_of(change);
      for (int i = 0; i < 6; ++i) a[i] += c[i];
    } else {
      std::array<double, 3> v{};
      for (int i = 0; i < 3; ++i) v[slot[i]] = to[i];
      const double m = 0.5 * (v[0] + v[1]), r = 0.5 * (v[0] - v[1]);
      a[0] = m + r * c2;
      a[1] = m - r * c2;
      a[5] = r * s2;
      a[2] = v[2];
    }
  }
};

// Adds a step's plastic strain to the state, from the principal stress
// change of the return, d sigma_i = trial_i - returned_i, and the returned
// principal stresses: d eps_p,i = ((1 + nu) d sigma_i - nu tr d sigma) / E.
inline void record_plastic_strain(FrictionalState& state, const std::array<double, 3>& trial,
                                  const std::array<double, 3>& returned, double E, double nu) {
  const double tr = (trial[0] - returned[0]) + (trial[1] - returned[1]) + (trial[2] - returned[2]);
  std::array<double, 3> e{};
  for (int i = 0; i < 3; ++i) e[i] = ((1.0 + nu) * (trial[i] - returned[i]) - nu * tr) / E;
  state.shear += *std::max_element(e.begin(), e.end()) - *std::min_element(e.begin(), e.end());
  state.volumetric += e[0] + e[1] + e[2];
  state.dissipated += returned[0] * e[0] + returned[1] * e[1] + returned[2] * e[2];
}

}  // namespace flowmpm
