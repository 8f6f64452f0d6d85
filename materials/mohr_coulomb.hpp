// Mohr-Coulomb perfect plasticity with a Rankine tension cut-off, small
// strain, isotropic elasticity (materials/frictional.hpp for what it shares
// with drucker_prager). Principal stresses sigma_1 >= sigma_2 >= sigma_3,
// tension positive; s_phi = sin phi, s_psi = sin psi.
//   Yield ([de Souza Neto 2008], section 6.4, in principal stresses):
//     f_ij = (sigma_i - sigma_j) + (sigma_i + sigma_j) s_phi - 2 c cos phi <= 0,
//     the main plane f_13, and f_12, f_23, which meet it on the edges
//     sigma_2 = sigma_3 and sigma_1 = sigma_2, and all three at the apex
//     sigma_i = c cot phi.
//   Flow potential: g_ij, the same with psi for phi; its gradient
//     n_ij = (1 + s_psi) e_i - (1 - s_psi) e_j, so that on the main plane
//     d eps_p,v / (d eps_p,1 - d eps_p,3) = s_psi (the dilatancy of psi).
//   Tension cut-off (Rankine, on the major principal stress): r_i =
//     sigma_i - T <= 0, associated (n = e_i). MC alone implies sigma_1 <= c
//     cot phi, so T = c cot phi (the default) leaves the surface unchanged
//     and T = 0 is a soil that bears no tension in any direction.
// Return ([de Souza Neto 2008], Boxes 8.4-8.5, extended to the cut-off as a
// multisurface return, [Clausen 2007]): the elastic trial sigma* is split
// into principal values (frictional.hpp, PrincipalAxes); every surface and
// potential is linear in them and the material perfectly plastic, so the
// return to a set A of active surfaces is the linear system
//   sum_{j in A} (a_i . D n_j) dgamma_j = f_i(sigma*),  i in A,
//   sigma = sigma* - sum_j dgamma_j D n_j,  D n = lambda tr(n) 1 + 2 G n,
// (a_i the gradient of f_i). The candidate sets are tried in the order of
// Box 8.5 (main plane, the two edges), then the cut-off (its plane, its
// edge sigma_1 = sigma_2 = T, the main plane with it, on the edge
// sigma_2 = sigma_3 with it, on the edge sigma_1 = sigma_2 = T with it),
// and the first with every dgamma >= 0 whose stress keeps the ordering,
// f_13 <= 0 and sigma_1 <= T (which imply the other surfaces) is taken;
// none: the apex of the cut surface, sigma_i = T (with T = c cot phi the
// apex of Box 8.5). Associated flow (psi = phi) makes this the closest point
// in the energy norm; the stress then rebuilds from the principal axes of
// the trial (an isotropic return is coaxial).
// Softening (optional, as CB-Geo's mohr_coulomb [CB-Geo]): phi, c and
// psi fall linearly from their peak values to residual ones as the plastic
// shear strain gamma_p (FrictionalState::shear) goes from gamma_0 to
// gamma_r, and stay residual beyond; T follows as min(T, c cot phi). With
// the crack band [Bazant 1983] the range is given as a plastic shear
// displacement delta across a band one cell wide, gamma_p h = delta (h the
// cell size, ParticleInit::cell_length), so that a shear band softens over
// the same slip on any grid. The surface of a step is the one of gamma_p at
// its start (explicit in the softening).
#pragma once
#include <algorithm>
#include <array>
#include <cmath>

#include "core/voigt.hpp"
#include "materials/frictional.hpp"

namespace flowmpm {

class ParameterTable;

// The residual strength and the range it is reached over (header).
struct MohrCoulombSoftening {
  bool on = false;
  double friction_angle = 0.0;  // residual phi (rad)
  double cohesion = 0.0;        // residual c (Pa)
  double dilation_angle = 0.0;  // residual psi (rad)
  double start = 0.0, end = 0.0;  // gamma_0, gamma_r (-), or delta_0, delta_r (m) with crack_band
  bool crack_band = false;
};

struct MohrCoulombParameters : FrictionalParameters {
  MohrCoulombSoftening softening;
};

// The yield surface and flow potential of one phi, c, psi and T.
struct MohrCoulombSurface {
  double sin_phi = 0.0, sin_psi = 0.0, strength = 0.0;  // strength = 2 c cos phi
  double cohesion = 0.0, tension = 0.0;                 // c, T (Pa)
  // The Drucker-Prager cone inscribed in the pyramid, J + eta p <= xi c
  // (drucker_prager.hpp): a stress inside it, with p + 2 J / sqrt 3 (the
  // largest sigma_1 of its p and J) <= T, is inside the surface whatever its
  // principal values, which the update then need not compute.
  double inner_eta = 0.0, inner_strength = 0.0;

  MohrCoulombSurface() = default;
  MohrCoulombSurface(double phi, double c, double psi, double T)
      : sin_phi(std::sin(phi)),
        sin_psi(std::sin(psi)),
        strength(2.0 * c * std::cos(phi)),
        cohesion(c),
        tension(T),
        inner_eta(3.0 * sin_phi / std::sqrt(9.0 + 3.0 * sin_phi * sin_phi)),
        inner_strength(3.0 * c * std::cos(phi) / std::sqrt(9.0 + 3.0 * sin_phi * sin_phi)) {}

  // The main plane f_13 of the principal stresses (descending).
  double yield_function(const std::array<double, 3>& s) const {
    return (s[0] - s[2]) + (s[0] + s[2]) * sin_phi - strength;
  }
};

struct MohrCoulomb : FrictionalModel<MohrCoulombParameters> {
  static constexpr const char* type_name = "mohr_coulomb";

  using Parameters = MohrCoulombParameters;
  using Surface = MohrCoulombSurface;
  // Its own type (the engine keeps one state array per model): frictional.hpp.
  struct State : FrictionalState {};
  State initial_state(const ParticleInit& init) const {
    State s;
    s.cell_length = init.cell_length;
    return s;
  }

  Surface peak;  // the surface without softening

  explicit MohrCoulomb(const Parameters& p)
      : FrictionalModel(p), peak(p.friction_angle, p.cohesion, p.dilation_angle, p.tension_cutoff) {}

  // Reads and validates [materials.NAME] (type = "mohr_coulomb").
  static MohrCoulomb read(ParameterTable& table);

  // The surface of a particle's state: the peak one, or softened (header).
  Surface surface(const State& state) const {
    const MohrCoulombSoftening& s = parameters.softening;
    if (!s.on) return peak;
    const double measure = s.crack_band ? state.shear * state.cell_length : state.shear;
    const double r = std::clamp((measure - s.start) / (s.end - s.start), 0.0, 1.0);
    const double phi = parameters.friction_angle + r * (s.friction_angle - parameters.friction_angle);
    const double c = parameters.cohesion + r * (s.cohesion - parameters.cohesion);
    const double psi = parameters.dilation_angle + r * (s.dilation_angle - parameters.dilation_angle);
    return Surface(phi, c, psi, std::min(parameters.tension_cutoff, c / std::tan(phi)));
  }

  template <StressState Kind>
  void update(State& state, Voigt& sigma, Voigt& deps, const MaterialInput& in) const {
    if constexpr (!supports(Kind)) {
      unsupported(Kind);
    } else {
      parameters.expansion.with_mechanical_increment(deps, in, [&] {
        elastic_trial<Kind>(sigma, deps, in.dL, lambda, mu);
        const Surface f = surface(state);
        const double p = (sigma[0] + sigma[1] + sigma[2]) / 3.0;
        const double J = std::sqrt(deviatoric_j2(sigma, p));
        if (J + f.inner_eta * p <= f.inner_strength && p + 2.0 / std::numbers::sqrt3 * J <= f.tension) return;
        const PrincipalAxes<Kind> axes(sigma);
        if (f.yield_function(axes.value) <= 0.0 && axes.value[0] <= f.tension) return;
        const std::array<double, 3> returned = principal_return(axes.value, f);
        axes.rebuild(sigma, returned);
        record_plastic_strain(state, axes.value, returned, parameters.youngs_modulus, parameters.poisson_ratio);
      });
    }
  }

  // The returned principal stresses of a trial outside surface f (header).
  std::array<double, 3> principal_return(const std::array<double, 3>& trial, const Surface& f) const;

  // Thrown if the engine ever updates a stress state the reader refused.
  [[noreturn]] static void unsupported(StressState kind);

};

}  // namespace flowmpm
