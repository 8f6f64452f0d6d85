// A body set spinning at angular velocity omega (bodies[].angular_velocity)
// with nothing acting on it turns rigidly: after t seconds by the angle
// |omega| t about the axis of omega, its angular momentum about its centre
// of mass L = sum m (x - x_c) x v unchanged.
// The body's measured angle is that of the rotation R that best maps the
// particles' initial positions (about their centre of mass) to their
// current ones, sum m |R a - b|^2 least (Kabsch's solution: R from the SVD
// of sum m b a^T, [Kabsch 1976]; in 2D R is a turn about z,
// angle = atan2(sum m a x b, sum m a . b)).
// Errors, at the last sample: angle = |angle_h - |omega| t| / (|omega| t)
// and angular_momentum = |L - L0| / |L0|, L0 at the first sample.
// Measures: angle and expected (rad).
#pragma once
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <string>

#include <Eigen/Geometry>
#include <Eigen/SVD>

#include "verification/reference_context.hpp"

namespace flowmpm {

struct RigidRotation {
  static constexpr const char* type_name = "rigid_rotation";
  int body = 0;
  double rate = 0.0;  // |omega| (rad/s)
  double t0 = std::numeric_limits<double>::quiet_NaN();
  double time = 0.0, angle = 0.0;
  Eigen::Vector3d L0 = Eigen::Vector3d::Zero(), L = Eigen::Vector3d::Zero();

  static RigidRotation read(ParameterTable& t, const ReferenceContext& context) {
    const SystemSpec& s = context.system;
    RigidRotation r;
    std::vector<std::string> names;
    for (const BodySpec& b : s.bodies) names.push_back(b.name);
    const std::string name = t.choice("body", names, names.front());
    r.body = static_cast<int>(std::ranges::find(names, name) - names.begin());
    const Vec3& omega = s.bodies[r.body].angular_velocity;
    r.rate = std::hypot(omega[0], omega[1], omega[2]);
    t.require(r.rate > 0.0, "body", "a body with an angular_velocity for rigid_rotation");
    t.require(!s.bodies[r.body].rigid(), "body", "a deformable body for rigid_rotation");
    return r;
  }

  template <int D, class Shape>
  void initialise(DiscreteSystem<D, Shape>&) const {}

  template <int D, class Shape>
  void sample(const DiscreteSystem<D, Shape>& system) {
    // Centres of mass, initial and current.
    Eigen::Vector3d c0 = Eigen::Vector3d::Zero(), c = Eigen::Vector3d::Zero();
    double m = 0.0;
    auto lift = [](const Vec<D>& v) {
      Eigen::Vector3d w = Eigen::Vector3d::Zero();
      for (int d = 0; d < D; ++d) w[d] = v[d];
      return w;
    };
    for (const auto& b : system.batches) {
      if (b.body != body) continue;
      for (std::size_t p = 0; p < b.size(); ++p) {
        c0 += b.mass[p] * lift(b.x0[p]);
        c += b.mass[p] * lift(b.x[p]);
        m += b.mass[p];
      }
    }
    c0 /= m;
    c /= m;
    Eigen::Matrix3d H = Eigen::Matrix3d::Zero();  // sum m b a^T
    Eigen::Vector3d momentum = Eigen::Vector3d::Zero();
    for (const auto& b : system.batches) {
      if (b.body != body) continue;
      for (std::size_t p = 0; p < b.size(); ++p) {
        const Eigen::Vector3d a = lift(b.x0[p]) - c0, r = lift(b.x[p]) - c;
        H += b.mass[p] * r * a.transpose();
        momentum += b.mass[p] * r.cross(lift(b.v[p]));
      }
    }
    if constexpr (D == 2) {
      angle = std::atan2(H(1, 0) - H(0, 1), H(0, 0) + H(1, 1));
    } else {
      const Eigen::JacobiSVD<Eigen::Matrix3d> svd(H, Eigen::ComputeFullU | Eigen::ComputeFullV);
      Eigen::Matrix3d S = Eigen::Matrix3d::Identity();
      S(2, 2) = (svd.matrixU() * svd.matrixV().transpose()).determinant() < 0.0 ? -1.0 : 1.0;
      const Eigen::Matrix3d R = svd.matrixU() * S * svd.matrixV().transpose();
      angle = std::acos(std::clamp(0.5 * (R.trace() - 1.0), -1.0, 1.0));
    }
    if (std::isnan(t0)) t0 = system.t, L0 = momentum;
    L = momentum;
    time = system.t - t0;
  }

  template <class F>
  void visit_state(F&& f) {
    f("t0", t0);
    f("time", time);
    f("angle", angle);
    for (int i = 0; i < 3; ++i) f("L0_" + std::to_string(i), L0[i]);
    for (int i = 0; i < 3; ++i) f("L_" + std::to_string(i), L[i]);
  }

  std::map<std::string, double> errors() const {
    const double expected = rate * time;
    return {{"angle", expected > 0.0 ? std::abs(angle - expected) / expected : 0.0},
            {"angular_momentum", (L - L0).norm() / L0.norm()}};
  }
  std::map<std::string, double> measures() const { return {{"angle", angle}, {"expected", rate * time}}; }
};

}  // namespace flowmpm
