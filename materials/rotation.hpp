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
#include "materials/stress_state.hpp"

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
// the isotropic models, so written out: with h = w / 2, H = skew(h) and
// M = H + H^2, dR = I + k M, k = 2 / (1 + h.h) (the rotation of the
// quaternion (1, h) / |.|), and
//   dR a dR^T = a + k (M a + a M^T) + k^2 M a M^T,
// whose products need not wait for the division that gives k (the
// particle loop's longest chain otherwise), and which adds the change to
// a instead of rebuilding it.
[[gnu::always_inline]] inline void rotate_with_spin(Voigt& a, const Eigen::Matrix3d& dL) {
  const double x = 0.25 * (dL(2, 1) - dL(1, 2)), y = 0.25 * (dL(0, 2) - dL(2, 0)), z = 0.25 * (dL(1, 0) - dL(0, 1));
  const double hh = x * x + y * y + z * z;
  if (hh == 0.0) return;
  const double k = 2.0 / (1.0 + hh);
  // M = skew(h) + h h^T - (h.h) I
  const double M[3][3] = {{x * x - hh, x * y - z, x * z + y},
                          {x * y + z, y * y - hh, y * z - x},
                          {x * z - y, y * z + x, z * z - hh}};
  const double A[3][3] = {{a[0], a[5], a[4]}, {a[5], a[1], a[3]}, {a[4], a[3], a[2]}};
  double P[3][3];  // M a
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) P[i][j] = M[i][0] * A[0][j] + M[i][1] * A[1][j] + M[i][2] * A[2][j];
  auto turned = [&](int i, int j) {
    const double once = P[i][j] + P[j][i];                                       // (M a + a M^T)_ij
    const double twice = P[i][0] * M[j][0] + P[i][1] * M[j][1] + P[i][2] * M[j][2];  // (M a M^T)_ij
    return A[i][j] + k * (once + k * twice);
  };
  a = {turned(0, 0), turned(1, 1), turned(2, 2), turned(1, 2), turned(0, 2), turned(0, 1)};
}

// The same in a 2D analysis, whose spin is about z alone (dL has no
// out-of-plane part): dR turns the (x, y) plane by c = 1 - k z^2,
// s = k z, the hoop or out-of-plane zz stays; a fifth of the 3D work.
// 1D has no spin.
template <StressState Kind>
[[gnu::always_inline]] inline void rotate_with_spin(Voigt& a, const Eigen::Matrix3d& dL) {
  if constexpr (Kind == StressState::three_d) {
    rotate_with_spin(a, dL);
  } else if constexpr (Kind != StressState::uniaxial_stress) {
    const double z = 0.25 * (dL(1, 0) - dL(0, 1));
    if (z == 0.0) return;
    const double k = 2.0 / (1.0 + z * z);
    const double dc = -k * z * z, s = k * z;  // c = 1 + dc
    const double d = dc * (2.0 + dc), cs = (1.0 + dc) * s, s2 = s * s;  // d = c^2 - 1
    const double xx = a[0], yy = a[1], yz = a[3], xz = a[4], xy = a[5];
    a[0] = xx + (d * xx - 2.0 * cs * xy + s2 * yy);
    a[1] = yy + (d * yy + 2.0 * cs * xy + s2 * xx);
    a[5] = xy + (cs * (xx - yy) + (d - s2) * xy);
    a[4] = xz + (dc * xz - s * yz);
    a[3] = yz + (s * xz + dc * yz);
  }
}

}  // namespace flowmpm
