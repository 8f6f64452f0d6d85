// Transversely isotropic linear elasticity with thermal and solvent
// expansion ([NairnMPM] "Transverse 1" and "Transverse 2"): an
// orthotropic material (materials/orthotropic.hpp) isotropic in the plane
// normal to its axial direction A, which lies along material z (axis = "z")
// or material y (axis = "y"). Parameters: EA, ET, GA = G_AT, one of
// nuAT = -eps_T / eps_A under sigma_A and nuTA (nuAT / EA = nuTA / ET), and
// nuT, the Poisson ratio in the transverse plane; GT = ET / (2 (1 + nuT)).
// Axis z: Ex = Ey = ET, Ez = EA, Gxz = Gyz = GA, Gxy = GT, nu_xy = nuT,
//         nu_zx = nu_zy = nuAT.
// Axis y: Ex = Ez = ET, Ey = EA, Gxy = Gyz = GA, Gxz = GT, nu_xz = nuT,
//         nu_yx = nu_yz = nuAT.
// The expansion coefficients alpha, beta, the conductivity and the
// diffusivity are given as [axial, transverse].
// In 2D the axes turn about z only: axis "z" puts A normal to the plane,
// axis "y" (with the body's material_axes angle) in the plane.
#pragma once
#include "materials/orthotropic.hpp"

namespace flowmpm {

struct TransverselyIsotropic : Orthotropic {
  static constexpr const char* type_name = "transversely_isotropic";

  // A type of its own, so that the engine's per-model state arrays differ.
  struct State : Orthotropic::State {};

  explicit TransverselyIsotropic(const Orthotropic& o) : Orthotropic(o) {}

  // Reads and validates [materials.NAME] (type = "transversely_isotropic").
  static TransverselyIsotropic read(ParameterTable& table);

  State initial_state(const ParticleInit& init) const { return {Orthotropic::initial_state(init)}; }
};

}  // namespace flowmpm
