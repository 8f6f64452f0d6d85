// How the out-of-plane components follow from the in-plane strain rate of a
// 1D or 2D analysis; 3D needs no assumption.
#pragma once

namespace flowmpm {

enum class StressState {
  three_d,          // all six components from the 3D velocity gradient
  plane_strain,     // 2D: eps_zz = eps_yz = eps_xz = 0, sigma_zz follows
  plane_stress,     // 2D: sigma_zz = sigma_yz = sigma_xz = 0, eps_zz follows
  uniaxial_stress,  // 1D: sigma_yy = sigma_zz = 0, the lateral strains follow
  axisymmetric,     // 2D (r, z): x the radius, y the axis; zz the hoop component (theta), eps_tt = v_r / r
};

constexpr const char* stress_state_name(StressState s) {
  switch (s) {
    case StressState::three_d: return "3D";
    case StressState::plane_strain: return "plane strain";
    case StressState::plane_stress: return "plane stress";
    case StressState::uniaxial_stress: return "uniaxial stress";
    case StressState::axisymmetric: return "axisymmetric";
  }
  return "?";
}

}  // namespace flowmpm
