// Rotations shared by the models: material axes from the case's angles,
// the rotation increment of a step, and symmetric tensors between Voigt
// order (xx, yy, zz, yz, xz, xy; tensor shear) and 3 x 3 matrices.
//
// Convention: R maps material axes to global axes (its columns are the
// material axes in global coordinates), so a tensor a_m in material axes is
// a = R a_m R^T globally. Rotation rate: the spin W = skew(L); over a step
// the increment W dt = skew(dL) is integrated with the Cayley map
// dR = (I - W dt / 2)^-1 (I + W dt / 2) (Hughes and Winget 1980), which is
// orthogonal for any dt and second-order accurate. As a quaternion,
// dR = (1, w / 2) / |(1, w / 2)|, w the axial vector of W dt.
#pragma once
#include <array>
#include <cmath>
#include <numbers>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "core/voigt.hpp"

namespace flowmpm {

inline Eigen::Matrix3d tensor_of(const Voigt& a) {
  Eigen::Matrix3d m;
  m << a[0], a[5], a[4],
       a[5], a[1], a[3],
       a[4], a[3], a[2];
  return m;
}

inline Voigt voigt_of(const Eigen::Matrix3d& m) {
  return {m(0, 0), m(1, 1), m(2, 2), m(1, 2), m(0, 2), m(0, 1)};
}

// R a R^T: a from material to global axes.
inline Voigt to_global(const Eigen::Matrix3d& R, const Voigt& a) {
  return voigt_of(R * tensor_of(a) * R.transpose());
}

// R^T a R: a from global to material axes.
inline Voigt to_material(const Eigen::Matrix3d& R, const Voigt& a) {
  return voigt_of(R.transpose() * tensor_of(a) * R);
}

// Material axes of a particle: R = Rz Ry Rx from the angles (degrees)
// about z, y and x (ParticleInit::axes_degrees; NairnMPM's convention).
inline Eigen::Quaterniond axes_rotation(const std::array<double, 3>& degrees) {
  const double to_rad = std::numbers::pi / 180.0;
  return Eigen::AngleAxisd(degrees[0] * to_rad, Eigen::Vector3d::UnitZ()) *
         Eigen::AngleAxisd(degrees[1] * to_rad, Eigen::Vector3d::UnitY()) *
         Eigen::AngleAxisd(degrees[2] * to_rad, Eigen::Vector3d::UnitX());
}

// The axial vector w of the spin increment W dt = skew(dL): W a = w x a.
inline Eigen::Vector3d spin_axial(const Eigen::Matrix3d& dL) {
  return {0.5 * (dL(2, 1) - dL(1, 2)), 0.5 * (dL(0, 2) - dL(2, 0)), 0.5 * (dL(1, 0) - dL(0, 1))};
}

// Cayley rotation of the spin increment with axial vector `w`.
inline Eigen::Quaterniond cayley(const Eigen::Vector3d& w) {
  Eigen::Quaterniond q(1.0, 0.5 * w.x(), 0.5 * w.y(), 0.5 * w.z());
  q.normalize();
  return q;
}

// Turns a tensor stored in global axes with the material over a step:
// a <- dR a dR^T, dR the Cayley increment of skew(dL) (Hughes-Winget
// objective update; a no-op without spin).
inline void rotate_with_spin(Voigt& a, const Eigen::Matrix3d& dL) {
  const Eigen::Vector3d w = spin_axial(dL);
  if (w.squaredNorm() == 0.0) return;
  a = to_global(cayley(w).toRotationMatrix(), a);
}

}  // namespace flowmpm
