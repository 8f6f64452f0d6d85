// Axial vibration of a 1D elastic bar, fixed at x = x_f and free at
// x = x_f + L, in its n-th mode (uniaxial stress, c = sqrt(E / rho)):
//   v(X, t) = v0 sin(beta X) cos(omega t),  u(X, t) = v0 / omega sin(beta X) sin(omega t),
//   beta = (2n - 1) pi / (2 L),  omega = beta c,  X = x0 - x_f.
// The reference sets the initial velocity v(X, 0); errors are the RMS of
// displacement and velocity over particles and samples, relative to the
// amplitudes v0 / omega and v0, and of the stress
// sigma = E du/dX = rho c v0 cos(beta X) sin(omega t), relative to rho c v0:
// the stress norm shows the cell-crossing noise of linear shape functions.
// The explicit update moves velocities before
// positions (symplectic Euler, i.e. leapfrog), so a step's particle velocity
// belongs to t - dt/2 and is compared with the exact velocity there;
// compared at t it would show a spurious first-order error. Small v0 keeps particles inside their cells;
// large v0 makes them cross cells.
#pragma once
#include <map>
#include <numbers>
#include <string>

#include "engine/reference/error_norm.hpp"
#include "io/case_file.hpp"

namespace flowmpm {

struct AxialVibration {
  double x_fixed, length, v0;
  int mode;
  double beta = 0.0, omega = 0.0, stress_amplitude = 0.0;
  RmsError displacement, velocity, stress;

  explicit AxialVibration(const ReferenceSpec& r)
      : x_fixed(r.origin), length(r.length), v0(r.velocity), mode(r.mode) {}

  template <int D, class Shape>
  void initialise(Model<D, Shape>& model, double /*end_time*/) {
    const LinearElastic& m = elastic_material(model, "axial_vibration");
    const double c = std::sqrt(m.parameters.youngs_modulus / m.parameters.density);
    beta = (2 * mode - 1) * std::numbers::pi / (2.0 * length);
    omega = beta * c;
    stress_amplitude = m.parameters.density * c * v0;
    for (auto& b : model.batches)
      for (std::size_t p = 0; p < b.size(); ++p) b.v[p][0] = v0 * std::sin(beta * (b.x0[p][0] - x_fixed));
  }

  template <int D, class Shape>
  void sample(const Model<D, Shape>& model) {
    if (model.step == 0) return;  // the initial state is exact by construction
    const double t = model.t;
    for (const auto& b : model.batches) {
      for (std::size_t p = 0; p < b.size(); ++p) {
        const double X = b.x0[p][0] - x_fixed, shape = std::sin(beta * X);
        displacement.add(b.mass[p], b.x[p][0] - b.x0[p][0] - v0 / omega * shape * std::sin(omega * t));
        velocity.add(b.mass[p], b.v[p][0] - v0 * shape * std::cos(omega * (t - 0.5 * model.dt)));
        stress.add(b.mass[p], b.stress[p][0] - stress_amplitude * std::cos(beta * X) * std::sin(omega * t));
      }
    }
  }

  std::map<std::string, double> errors() const {
    return {{"displacement", displacement.relative_to(v0 / omega)},
            {"velocity", velocity.relative_to(v0)},
            {"stress", stress.relative_to(stress_amplitude)}};
  }
};

}  // namespace flowmpm
