// A material point driven the way the engine drives it (tasks/g2p.hpp):
// update<Kind> once per increment with deps = sym(dL), dL = L dt, t at the end
// of the increment; for the material tests. Mixed control: increments whose
// free components are solved, by Newton with a finite-difference Jacobian on
// copies of the state, so that their stresses stay zero.
#pragma once
#include <cmath>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Dense>

#include "io/case/case_reader.hpp"
#include "materials/material.hpp"
#include "materials/rotation.hpp"

namespace flowmpm::testing {

// A model read from the text of one [materials.NAME] table (without the
// header), through the case reader.
inline Material material_from_text(const std::string& text) {
  const toml::table table = toml::parse(std::string_view(text), std::string_view("material.toml"));
  TableReader reader(table, "materials.m", "material.toml");
  Material m = read_material(reader);
  reader.reject_unknown_keys();
  return m;
}

// The message with which reading `text` as a material fails ("no error"
// if it does not).
inline std::string material_error(const std::string& text) {
  try {
    material_from_text(text);
  } catch (const CaseError& e) {
    return e.what();
  }
  return "no error";
}

template <class Model, StressState Kind>
struct MaterialPoint {
  const Model& model;
  typename Model::State state;
  Voigt sigma{}, eps{};  // stress (Pa) and total strain, global axes
  double t = 0.0;        // s
  double length = 0.0;   // particle size passed to the model (m)

  explicit MaterialPoint(const Model& m, const ParticleInit& init = {})
      : model(m), state(m.initial_state(init)), length(init.length) {}

  // One increment of the velocity gradient dL = L dt over dt.
  void step(const Eigen::Matrix3d& dL, double dt = 1.0) {
    Voigt deps = voigt_of(0.5 * (dL + dL.transpose()));
    apply(state, sigma, deps, dL, t + dt);
    for (int i = 0; i < 6; ++i) eps[i] += deps[i];
    t += dt;
  }

  // One strain increment without spin.
  void strain(const Voigt& deps, double dt = 1.0) { step(tensor_of(deps), dt); }

  // A strain increment whose components `free` are chosen so that their
  // stresses are `target`'s (zero unless given) at the end of it
  // (|sigma_free - target_free| <= 1e-13 of the largest stress component).
  void mixed(Voigt deps, const std::vector<int>& free, double dt = 1.0, const Voigt& target = {}) {
    const int n = static_cast<int>(free.size());
    Eigen::VectorXd x = Eigen::VectorXd::Zero(n);
    double scale = 0.0;
    for (double d : deps) scale = std::max(scale, std::abs(d));
    const double h = 1e-7 * (scale > 0.0 ? scale : 1.0);
    auto residual = [&](const Eigen::VectorXd& v, Voigt* sig_out = nullptr) {
      Voigt d = deps;
      for (int k = 0; k < n; ++k) d[free[k]] = v[k];
      auto s = state;
      Voigt sig = sigma;
      apply(s, sig, d, tensor_of(d), t + dt);
      Eigen::VectorXd r(n);
      for (int k = 0; k < n; ++k) r[k] = sig[free[k]] - target[free[k]];
      if (sig_out) *sig_out = sig;
      return r;
    };
    for (int it = 0; it < 30; ++it) {
      Voigt sig;
      const Eigen::VectorXd r = residual(x, &sig);
      double largest = 0.0;
      for (double s : sig) largest = std::max(largest, std::abs(s));
      if (r.lpNorm<Eigen::Infinity>() <= 1e-13 * largest) break;
      Eigen::MatrixXd J(n, n);
      for (int k = 0; k < n; ++k) {
        Eigen::VectorXd xk = x;
        xk[k] += h;
        J.col(k) = (residual(xk) - r) / h;
      }
      x -= J.fullPivLu().solve(r);
    }
    for (int k = 0; k < n; ++k) deps[free[k]] = x[k];
    strain(deps, dt);
  }

 private:
  void apply(typename Model::State& s, Voigt& sig, Voigt& deps, const Eigen::Matrix3d& dL, double t_end) const {
    MaterialInput in;
    in.t = t_end;
    in.dt = t_end - t;
    in.dL = dL;
    in.length = length;
    model.template update<Kind>(s, sig, deps, in);
  }
};

}  // namespace flowmpm::testing
