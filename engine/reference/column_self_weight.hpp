// An elastic column of height H on a fixed base at Y = 0, its sides on
// rollers (uniaxial strain, constrained modulus M = lambda + 2 mu), loaded
// by gravity g switched on at t = 0. With f(Y) = H Y - Y^2 / 2, the modal
// solution of the 1D wave equation u_tt = c^2 u_YY - g, c = sqrt(M / rho):
//   u(Y, t) = -(rho g / M) [ f(Y) - sum_n 2 / (H beta_n^3) sin(beta_n Y) cos(omega_n t) ],
//   beta_n = (2n - 1) pi / (2 H),  omega_n = beta_n c,
// (the series is f's sine series, so u(Y, 0) = 0): the column oscillates
// about the static solution -(rho g / M) f(Y). Error: RMS of the vertical
// displacement over particles and samples, relative to the static top
// displacement rho g H^2 / (2 M). 2D (plane strain) or 3D.
#pragma once
#include <map>
#include <numbers>
#include <string>
#include <vector>

#include "engine/reference/error_norm.hpp"
#include "io/case_file.hpp"

namespace flowmpm {

struct ColumnSelfWeight {
  static constexpr int terms = 200;  // series truncation: term n ~ n^-3
  int axis;
  double base, height;
  double g = 0.0, static_scale = 0.0;  // rho g / M
  std::vector<double> beta, omega, coefficient;  // per term; coefficient 2 / (H beta^3)
  std::vector<double> cos_omega_t;              // per term, at the current sample
  RmsError displacement;

  explicit ColumnSelfWeight(const ReferenceSpec& r) : axis(r.axis), base(r.origin), height(r.length) {}

  template <int D, class Shape>
  void initialise(Model<D, Shape>& model, double /*end_time*/) {
    const LinearElastic& m = elastic_material(model, "column_self_weight");
    if (model.stress_state == StressState::plane_stress) {
      throw CaseError("reference column_self_weight: needs plane strain in 2D (uniaxial strain)");
    }
    const double M = m.lambda + 2.0 * m.mu, rho = m.parameters.density;
    g = -model.gravity[axis];
    static_scale = rho * g / M;
    for (int n = 1; n <= terms; ++n) {
      beta.push_back((2 * n - 1) * std::numbers::pi / (2.0 * height));
      omega.push_back(beta.back() * std::sqrt(M / rho));
      coefficient.push_back(2.0 / (height * beta.back() * beta.back() * beta.back()));
    }
    cos_omega_t.resize(terms);
  }

  // u(Y, t), with cos(omega_n t) of the current sample in cos_omega_t.
  double exact(double Y) const {
    double series = 0.0;
    for (int n = 0; n < terms; ++n) series += coefficient[n] * std::sin(beta[n] * Y) * cos_omega_t[n];
    return -static_scale * (height * Y - 0.5 * Y * Y - series);
  }

  template <int D, class Shape>
  void sample(const Model<D, Shape>& model) {
    for (int n = 0; n < terms; ++n) cos_omega_t[n] = std::cos(omega[n] * model.t);
    for (const auto& b : model.batches) {
      for (std::size_t p = 0; p < b.size(); ++p) {
        const double Y = b.x0[p][axis] - base;
        displacement.add(b.mass[p], b.x[p][axis] - b.x0[p][axis] - exact(Y));
      }
    }
  }

  std::map<std::string, double> errors() const {
    return {{"displacement", displacement.relative_to(0.5 * static_scale * height * height)}};
  }
};

}  // namespace flowmpm
