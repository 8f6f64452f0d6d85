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
// a instead of rebuilding it. Written out in scalars: with arrays and a
// helper lambda GCC left the lambda out of line in the particle loop (a
// call per component).
[[gnu::always_inline]] inline void rotate_with_spin(Voigt& a, const Eigen::Matrix3d& dL) {
  const double x = 0.25 * (dL(2, 1) - dL(1, 2)), y = 0.25 * (dL(0, 2) - dL(2, 0)), z = 0.25 * (dL(1, 0) - dL(0, 1));
  const double xx = x * x, yy = y * y, zz = z * z, hh = xx + yy + zz;
  if (hh == 0.0) return;
  const double k = 2.0 / (1.0 + hh);
  // M = skew(h) + h h^T - (h.h) I
  const double xy = x * y, xz = x * z, yz = y * z;
  const double m00 = xx - hh, m11 = yy - hh, m22 = zz - hh;
  const double m01 = xy - z, m10 = xy + z, m02 = xz + y, m20 = xz - y, m12 = yz - x, m21 = yz + x;
  const double a00 = a[0], a11 = a[1], a22 = a[2], a12 = a[3], a02 = a[4], a01 = a[5];
  // P = M a
  const double p00 = m00 * a00 + m01 * a01 + m02 * a02, p01 = m00 * a01 + m01 * a11 + m02 * a12,
               p02 = m00 * a02 + m01 * a12 + m02 * a22;
  const double p10 = m10 * a00 + m11 * a01 + m12 * a02, p11 = m10 * a01 + m11 * a11 + m12 * a12,
               p12 = m10 * a02 + m11 * a12 + m12 * a22;
  const double p20 = m20 * a00 + m21 * a01 + m22 * a02, p21 = m20 * a01 + m21 * a11 + m22 * a12,
               p22 = m20 * a02 + m21 * a12 + m22 * a22;
  // a_ij + k ((M a + a M^T)_ij + k (M a M^T)_ij)
  a[0] = a00 + k * (2.0 * p00 + k * (p00 * m00 + p01 * m01 + p02 * m02));
  a[1] = a11 + k * (2.0 * p11 + k * (p10 * m10 + p11 * m11 + p12 * m12));
  a[2] = a22 + k * (2.0 * p22 + k * (p20 * m20 + p21 * m21 + p22 * m22));
  a[3] = a12 + k * (p12 + p21 + k * (p10 * m20 + p11 * m21 + p12 * m22));
  a[4] = a02 + k * (p02 + p20 + k * (p00 * m20 + p01 * m21 + p02 * m22));
  a[5] = a01 + k * (p01 + p10 + k * (p00 * m10 + p01 * m11 + p02 * m12));
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
