// Axial vibration of a 1D elastic bar, fixed at x = x_f and free at
// x = x_f + L, in its n-th mode (uniaxial stress, c = sqrt(E / rho)):
//   v(X, t) = v0 sin(beta X) cos(omega t),  u(X, t) = v0 / omega sin(beta X) sin(omega t),
//   beta = (2n - 1) pi / (2 L),  omega = beta c,  X = x0 - x_f.
// The reference sets the initial velocity v(X, 0); errors are the RMS of
// displacement and velocity over particles and samples, relative to the
// amplitudes v0 / omega and v0, and of the stress
// sigma = E du/dX = rho c v0 cos(beta X) sin(omega t), relative to rho c v0:
// the stress norm shows the cell-crossing noise of linear shape functions.
// The explicit update moves velocities before positions (symplectic Euler,
// i.e. leapfrog), so a step's particle velocity belongs to t - dt/2 and is
// compared with the exact velocity there; compared at t it would show a
// spurious first-order error. Small v0 keeps particles inside their cells;
// large v0 makes them cross cells.
// Amplitude: the engine integrates the logarithmic strain
// (docs/theory/kinematics.md), so the bar obeys
// rho u_tt = E d/dX ln(1 + u_X) (nu = 0), not E u_XX: the laws differ by
// e / 2 at strain e, and the error norms have a floor of about 0.2 e,
// e = v0 / c, whatever the resolution (the measured floors are on that
// page). The small-amplitude case and the convergence tests run at
// e = 1e-5, far below their errors; the large-amplitude case (e = 5 %) is
// at its floor.
#pragma once
#include <cmath>
#include <cstdint>
#include <map>
#include <numbers>
#include <string>

#include "discretisation/discrete_system.hpp"
#include "verification/error_norm.hpp"
#include "verification/reference_context.hpp"

namespace flowmpm {

struct AxialVibration {
  static constexpr const char* type_name = "axial_vibration";
  double x_fixed = 0.0, length = 0.0, v0 = 0.0;
  int mode = 1;
  double beta = 0.0, omega = 0.0, stress_amplitude = 0.0;
  RmsError displacement, velocity, stress;

  static AxialVibration read(ParameterTable& t, const ReferenceContext& context) {
    t.require(context.system.dimension == 1, "type", "a 1D case (analysis.dimension = 1) for a bar reference");
    AxialVibration r;
    r.x_fixed = t.number("fixed_end");
    r.length = t.positive("length", "the bar length in m");
    r.v0 = t.positive("amplitude", "the velocity amplitude in m/s");
    const std::int64_t mode = t.integer_or("mode", 1);
    t.require(mode >= 1 && mode <= 1000000, "mode", "a mode number from 1 to 10^6");
    r.mode = static_cast<int>(mode);
    const LinearElastic& m = elastic_material(t, context);
    const double c = std::sqrt(m.parameters.youngs_modulus / m.parameters.density);
    r.beta = (2 * r.mode - 1) * std::numbers::pi / (2.0 * r.length);
    r.omega = r.beta * c;
    r.stress_amplitude = m.parameters.density * c * r.v0;
    return r;
  }

  template <int D, class Shape>
  void initialise(DiscreteSystem<D, Shape>& system) const {
    for (auto& b : system.batches)
      for (std::size_t p = 0; p < b.size(); ++p) b.v[p][0] = v0 * std::sin(beta * (b.x0[p][0] - x_fixed));
  }

  template <int D, class Shape>
  void sample(const DiscreteSystem<D, Shape>& system) {
    if (system.step == 0) return;  // the initial state is exact by construction
    const double t = system.t;
    for (const auto& b : system.batches) {
      for (std::size_t p = 0; p < b.size(); ++p) {
        const double X = b.x0[p][0] - x_fixed, shape = std::sin(beta * X);
        displacement.add(b.mass[p], b.x[p][0] - b.x0[p][0] - v0 / omega * shape * std::sin(omega * t));
        velocity.add(b.mass[p], b.v[p][0] - v0 * shape * std::cos(omega * (t - 0.5 * system.dt)));
        stress.add(b.mass[p], b.stress[p][0] - stress_amplitude * std::cos(beta * X) * std::sin(omega * t));
      }
    }
  }

  // What the samples have summed so far (Reference::visit_state).
  template <class F>
  void visit_state(F&& f) {
    f("displacement", displacement);
    f("velocity", velocity);
    f("stress", stress);
  }

  std::map<std::string, double> errors() const {
    return {{"displacement", displacement.relative_to(v0 / omega)},
            {"velocity", velocity.relative_to(v0)},
            {"stress", stress.relative_to(stress_amplitude)}};
  }
};

}  // namespace flowmpm
