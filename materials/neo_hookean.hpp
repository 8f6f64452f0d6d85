// Compressible neo-Hookean hyperelasticity ([Bonet 2008], section 6.4.3):
// stored energy per unit reference volume and Cauchy stress
//   W(F) = mu/2 (tr b - 3) - mu ln J + lambda/2 (ln J)^2,
//   sigma = (mu / J) (b - I) + (lambda ln J / J) I,
// b = F F^T, J = det F, with the Lamé constants lambda, mu of E and nu
// (materials/lame.hpp): its small-strain limit is linear_elastic.
//
// The state is the deformation gradient F. Each step advances it by the
// midpoint rule for dF/dt = L F with L constant over the step,
//   F <- (I - dL / 2)^-1 (I + dL / 2) F,
// second-order accurate; for a pure spin (dL skew) the factor is the Cayley
// rotation of the other models (materials/rotation.hpp), orthogonal for
// any dt, so a rigid rotation turns F, and the stress, exactly. The stress
// is a function of F alone: no rate, so objective by construction.
//
// Reduced stress states (the out-of-plane rows of dL are 0):
//   plane strain: F_zz keeps its initial value (1 unless an initial stress
//     set it), sigma_zz follows;
//   plane stress: F_zz solves sigma_zz = 0, mu (F_zz^2 - 1) + lambda
//     ln(J_xy F_zz) = 0 with J_xy the in-plane determinant;
//   uniaxial stress (1D): F = diag(F_xx, s, s), s solving mu (s^2 - 1) +
//     lambda ln(F_xx s^2) = 0; then sigma_xx = mu (F_xx^2 - s^2) / J.
// Both are Newton iterations on ln s (the residual increases with it), to
// |step| <= newton_tolerance; not converging in newton_iterations is a
// std::runtime_error. The model sets the out-of-plane strain increments
// of deps to the change of ln F_zz (ln s).
//
// Initial stress: F starts at the symmetric stretch V (no rotation) whose
// stress is the particle's initial stress (initial_state, neo_hookean.cpp).
// No thermal or solvent expansion: the reader refuses alpha and beta.
#pragma once
#include <array>
#include <cmath>

#include <Eigen/Core>
#include <Eigen/LU>

#include "core/voigt.hpp"
#include "materials/lame.hpp"
#include "materials/material_input.hpp"
#include "materials/rotation.hpp"
#include "materials/state_variable.hpp"
#include "materials/stress_state.hpp"
#include "materials/transport_properties.hpp"

namespace flowmpm {

class ParameterTable;

struct NeoHookean {
  static constexpr const char* type_name = "neo_hookean";
  static constexpr double newton_tolerance = 1e-14;  // |step of ln s|
  static constexpr int newton_iterations = 50;

  struct Parameters {
    double density = 0.0;         // kg/m^3
    double youngs_modulus = 0.0;  // Pa, small-strain
    double poisson_ratio = 0.0;   // -, small-strain
    TransportProperties transport;  // heat capacity, conductivity, diffusivity (scalars)
  };
  struct State {
    Eigen::Matrix3d F = Eigen::Matrix3d::Identity();  // deformation gradient
  };

  static constexpr std::array<StateVariable, 1> state_variables{{{"volume_ratio", "-"}}};
  void state_values(const State& s, double* out) const { out[0] = s.F.determinant(); }

  Parameters parameters;
  double lambda = 0.0, mu = 0.0;

  explicit NeoHookean(const Parameters& p)
      : parameters(p),
        lambda(lame_lambda(p.youngs_modulus, p.poisson_ratio)),
        mu(lame_mu(p.youngs_modulus, p.poisson_ratio)) {}

  // Reads and validates [materials.NAME] (type = "neo_hookean").
  static NeoHookean read(ParameterTable& table);

  // F = V, the stretch that carries the initial stress (identity without one).
  State initial_state(const ParticleInit& init) const;

  double density() const { return parameters.density; }
  const TransportProperties& transport() const { return parameters.transport; }

  // The P wave of the undeformed material, sqrt((lambda + 2 mu) / rho) (m/s).
  // Compression stiffens the material: with the spatial elasticity tensor
  // lambda / J I (x) I + 2 (mu - lambda ln J) / J I ([Bonet 2008], section
  // 6.4.3) and the current density rho / J, the P wave is sqrt((lambda +
  // 2 mu - 2 lambda ln J) / rho), 9 % faster at J = 0.8 with nu = 0.3; the
  // CFL number's margin has to cover it.
  double wave_speed() const { return std::sqrt((lambda + 2.0 * mu) / parameters.density); }

  // The Cauchy stress of F.
  Voigt stress(const Eigen::Matrix3d& F) const {
    const double J = F.determinant();
    Voigt s = voigt_of((mu / J) * (F * F.transpose()));
    const double p = (lambda * std::log(J) - mu) / J;
    for (int i = 0; i < 3; ++i) s[i] += p;
    return s;
  }

  template <StressState Kind>
  void update(State& state, Voigt& sigma, Voigt& deps, const MaterialInput& in) const {
    Eigen::Matrix3d& F = state.F;
    if constexpr (Kind == StressState::uniaxial_stress) {
      const double d = in.dL(0, 0);
      F(0, 0) *= (1.0 + 0.5 * d) / (1.0 - 0.5 * d);
      const double before = F(1, 1);
      F(1, 1) = F(2, 2) = std::exp(lateral_log_stretch(std::log(F(0, 0)), 2.0, std::log(before)));
      deps[1] = deps[2] = std::log(F(1, 1) / before);
      const double J = F(0, 0) * F(1, 1) * F(2, 2);
      sigma = {mu * (F(0, 0) * F(0, 0) - F(1, 1) * F(1, 1)) / J, 0.0, 0.0, 0.0, 0.0, 0.0};
    } else {
      const Eigen::Matrix3d half = 0.5 * in.dL;
      F = (Eigen::Matrix3d::Identity() - half).inverse() * ((Eigen::Matrix3d::Identity() + half) * F);
      if constexpr (Kind == StressState::plane_stress) {
        const double before = F(2, 2), J_xy = F(0, 0) * F(1, 1) - F(0, 1) * F(1, 0);
        F(2, 2) = std::exp(lateral_log_stretch(std::log(J_xy), 1.0, std::log(before)));
        deps[2] = std::log(F(2, 2) / before);
      }
      sigma = stress(F);
      if constexpr (Kind == StressState::plane_stress) sigma[2] = 0.0;  // round-off only
    }
  }

  // W(F) / J: the stored energy per unit current volume (J/m^3), which the
  // engine multiplies by the particle's current volume. Exact for the
  // model, whatever the path; its round-off is about 1e-16 mu absolute.
  double stored_energy(const State& state, const Voigt&, const Voigt&) const {
    const Eigen::Matrix3d& F = state.F;
    const double J = F.determinant(), lnJ = std::log(J);
    return (0.5 * mu * (F.squaredNorm() - 3.0) - mu * lnJ + 0.5 * lambda * lnJ * lnJ) / J;
  }

  // y = ln s solving mu (e^(2y) - 1) + lambda (a + k y) = 0: the lateral
  // stretch s whose stress is zero, a the log of the rest of J, k the
  // number of lateral directions; Newton from y0.
  double lateral_log_stretch(double a, double k, double y0) const {
    double y = y0;
    for (int it = 0; it < newton_iterations; ++it) {
      const double e = std::exp(2.0 * y);
      const double step = (mu * (e - 1.0) + lambda * (a + k * y)) / (2.0 * mu * e + k * lambda);
      y -= step;
      if (std::abs(step) <= newton_tolerance) return y;
    }
    newton_failure(a, y);
  }

  // Throws the std::runtime_error of a lateral stretch that did not converge.
  [[noreturn]] static void newton_failure(double a, double y);
};

}  // namespace flowmpm
