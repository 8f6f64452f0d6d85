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
// objective update; a no-op without spin). Once per particle and step in
// the isotropic models, so written out: with h = w / 2 and H = skew(h),
// dR = I + 2 / (1 + h.h) (H + H^2) (the rotation of the quaternion
// (1, h) / |.|), and the product uses the symmetry of a (14 ns a call
// against 38 through Eigen's 3 x 3 products, the same to round-off).
inline void rotate_with_spin(Voigt& a, const Eigen::Matrix3d& dL) {
  const double x = 0.25 * (dL(2, 1) - dL(1, 2)), y = 0.25 * (dL(0, 2) - dL(2, 0)), z = 0.25 * (dL(1, 0) - dL(0, 1));
  const double hh = x * x + y * y + z * z;
  if (hh == 0.0) return;
  const double k = 2.0 / (1.0 + hh);
  const double R[3][3] = {{1.0 - k * (y * y + z * z), k * (x * y - z), k * (x * z + y)},
                          {k * (x * y + z), 1.0 - k * (x * x + z * z), k * (y * z - x)},
                          {k * (x * z - y), k * (y * z + x), 1.0 - k * (x * x + y * y)}};
  const double A[3][3] = {{a[0], a[5], a[4]}, {a[5], a[1], a[3]}, {a[4], a[3], a[2]}};
  double T[3][3];  // A dR^T
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) T[i][j] = A[i][0] * R[j][0] + A[i][1] * R[j][1] + A[i][2] * R[j][2];
  auto turned = [&](int i, int j) { return R[i][0] * T[0][j] + R[i][1] * T[1][j] + R[i][2] * T[2][j]; };
  a = {turned(0, 0), turned(1, 1), turned(2, 2), turned(1, 2), turned(0, 2), turned(0, 1)};
}

}  // namespace flowmpm
