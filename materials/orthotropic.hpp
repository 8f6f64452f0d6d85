// Orthotropic linear elasticity, small strain, with thermal and solvent
// expansion ([NairnMPM] "Orthotropic Material"). In material
// axes x, y, z (Voigt order xx, yy, zz, yz, xz, xy, tensor shear):
//   eps = S sigma + alpha dT(t) + beta c(t),   sigma = C (eps - alpha dT - beta c),
//   S normal block [[1/Ex, -nu_yx/Ey, -nu_zx/Ez],
//                   [-nu_xy/Ex, 1/Ey, -nu_zy/Ez],
//                   [-nu_xz/Ex, -nu_yz/Ey, 1/Ez]],   C normal block = its inverse,
//   sigma_yz = 2 Gyz eps_yz, sigma_xz = 2 Gxz eps_xz, sigma_xy = 2 Gxy eps_xy,
// with nu_ij = -eps_j / eps_i under sigma_i alone and the reciprocity
// nu_ij / E_i = nu_ji / E_j. dT = T - T_ref and c at the end of the step are
// uniform functions of time or each particle's own conducted temperature
// and diffused solvent (materials/expansion.hpp). The conductivity and the
// diffusivity are diagonal along the material axes and turn with them
// (materials/transport_properties.hpp, material_axes()).
//
// Material axes and objectivity: the state holds the rotation R of the
// particle's material axes (columns: the axes in global coordinates) and
// the total strain eps_m in material axes. Each update (1) advances R by the
// Cayley increment of the spin skew(dL) (materials/rotation.hpp), (2) rotates
// the strain increment into material axes with the mid-step rotation,
// d eps_m = R_1/2^T d eps R_1/2, and adds it, (3) evaluates the stress in
// material axes, and (4) rotates it back, sigma = R sigma_m R^T. A rigid
// rotation (sym(dL) = 0) leaves eps_m unchanged and turns the stress and the
// axes with the body exactly; the spin is W = skew(L) (the Jaumann choice:
// under large shear the axes follow W, not the polar rotation).
//
// Reduced stress states: plane strain keeps eps_zz = 0 (sigma_zz follows);
// plane stress sets eps_zz from sigma_zz = 0; in 2D the axes turn about z
// only, so material z is global z and both are exact. Uniaxial stress (1D):
// sigma_xx = Ex (eps_xx - th_x), eps_yy = th_y - nu_xy (eps_xx - th_x),
// eps_zz = th_z - nu_xz (eps_xx - th_x); 1D cases have no material axes.
#pragma once
#include <array>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "core/voigt.hpp"
#include "materials/expansion.hpp"
#include "materials/material_input.hpp"
#include "materials/rotation.hpp"
#include "materials/stress_state.hpp"
#include "materials/transport_properties.hpp"

namespace flowmpm {

class ParameterTable;

struct Orthotropic {
  static constexpr const char* type_name = "orthotropic";

  struct Parameters {
    double density = 0.0;                 // kg/m^3
    double Ex = 0.0, Ey = 0.0, Ez = 0.0;  // Young's moduli along the material axes (Pa)
    double Gxy = 0.0, Gxz = 0.0, Gyz = 0.0;  // shear moduli (Pa)
    // Poisson ratios nu_xy, nu_xz, nu_yz (-); nu_yx, nu_zx, nu_zy follow by reciprocity.
    double nuxy = 0.0, nuxz = 0.0, nuyz = 0.0;
    TransportProperties transport;  // heat capacity, conductivity, diffusivity along the axes
    Expansion expansion;            // alpha, beta along the axes and what drives them
  };

  struct State {
    Voigt eps{};  // total strain in material axes
    Eigen::Quaterniond axes = Eigen::Quaterniond::Identity();  // R, material to global
  };

  Parameters parameters;
  Eigen::Matrix3d S_n;   // normal block of the compliance in material axes (1/Pa)
  Eigen::Matrix3d C_n;   // normal block of the stiffness, S_n^-1 (Pa)
  double c_max = 0.0;    // fastest wave speed (m/s), see wave_speed()

  explicit Orthotropic(const Parameters& p);

  // Reads and validates [materials.NAME] (type = "orthotropic").
  static Orthotropic read(ParameterTable& table);
  // Reads the transport properties and the expansion, laid out per `layout`.
  static void read_transport_and_expansion(ParameterTable& t, Parameters& p, const AxisLayout& layout);

  // The normal block of the compliance S in material axes (1/Pa).
  static Eigen::Matrix3d compliance(const Parameters& p);

  // The particle's axes, and the strain in material axes that carries its
  // initial stress, eps_m = S sigma_m (0 without one): the stress it holds
  // from the first update on.
  State initial_state(const ParticleInit& init) const {
    State state{{}, axes_rotation(init.axes_degrees)};
    const Voigt m = to_material(state.axes.toRotationMatrix(), init.stress);
    const Eigen::Vector3d n = S_n * Eigen::Vector3d(m[0], m[1], m[2]);
    const Parameters& p = parameters;
    state.eps = {n[0], n[1], n[2], m[3] / (2.0 * p.Gyz), m[4] / (2.0 * p.Gxz), m[5] / (2.0 * p.Gxy)};
    return state;
  }

  double density() const { return parameters.density; }
  const TransportProperties& transport() const { return parameters.transport; }
  // R, the rotation from material to global axes: the conductivity and the
  // diffusivity turn with it.
  Eigen::Quaterniond material_axes(const State& state) const { return state.axes; }

  // The fastest plane wave in any direction: max over unit n of
  // sqrt(lambda_max(Gamma(n)) / rho), Gamma_ik = C_ijkl n_j n_l the acoustic
  // tensor (quasi-P wave). Independent of the axes' rotation; at least the
  // largest sqrt(C_ii / rho) of the stiffness diagonal.
  double wave_speed() const { return c_max; }

  // sigma = C (eps_m - th) in material axes.
  Voigt material_stress(const Voigt& e, const Eigen::Vector3d& th) const {
    const Eigen::Vector3d s = C_n * Eigen::Vector3d(e[0] - th[0], e[1] - th[1], e[2] - th[2]);
    return {s[0], s[1], s[2], 2.0 * parameters.Gyz * e[3], 2.0 * parameters.Gxz * e[4],
            2.0 * parameters.Gxy * e[5]};
  }

  template <StressState Kind>
  void update(State& state, Voigt& sigma, Voigt& deps, const MaterialInput& in) const {
    const Eigen::Vector3d th = parameters.expansion.strain(in);  // alpha dT + beta c, material axes
    Voigt& e = state.eps;
    if constexpr (Kind == StressState::uniaxial_stress) {
      e[0] += deps[0];
      const double e_mech = e[0] - th[0];
      deps[1] = th[1] - parameters.nuxy * e_mech - e[1];
      deps[2] = th[2] - parameters.nuxz * e_mech - e[2];
      e[1] += deps[1];
      e[2] += deps[2];
      sigma = {parameters.Ex * e_mech, 0.0, 0.0, 0.0, 0.0, 0.0};
    } else {
      const Eigen::Vector3d w = spin_axial(in.dL);
      const Eigen::Matrix3d R_mid = (cayley(0.5 * w) * state.axes).toRotationMatrix();
      state.axes = (cayley(w) * state.axes).normalized();
      const Voigt de = to_material(R_mid, deps);
      for (int i = 0; i < 6; ++i) e[i] += de[i];
      if constexpr (Kind == StressState::plane_stress) {
        // sigma_zz = C_31 (e_x - th_x) + C_32 (e_y - th_y) + C_33 (e_z - th_z) = 0
        const double e_z =
            th[2] - (C_n(2, 0) * (e[0] - th[0]) + C_n(2, 1) * (e[1] - th[1])) / C_n(2, 2);
        deps[2] = e_z - e[2];
        e[2] = e_z;
      }
      sigma = to_global(state.axes.toRotationMatrix(), material_stress(e, th));
      if constexpr (Kind == StressState::plane_stress) sigma[2] = 0.0;  // round-off only
    }
  }

  // Work done on the body by the expansion strains over one increment per
  // unit volume (J/m^3): -sigma_m . (th(t) - th(t - dt)) (th driven by the
  // uniform functions or the particle's own T and c), sigma_m the normal
  // stresses in material axes (the expansion strains have no shear). Held
  // fully, the strain th becomes elastic strain -th: the stored energy
  // grows by what the expansion did, -sigma : d th.
  double expansion_work(const State& state, const Voigt& sigma, const MaterialInput& in) const {
    if (!parameters.expansion.any()) return 0.0;
    const Voigt s = to_material(state.axes.toRotationMatrix(), sigma);
    const Eigen::Vector3d d_th = parameters.expansion.strain(in) - parameters.expansion.strain_at_start(in);
    return -(s[0] * d_th[0] + s[1] * d_th[1] + s[2] * d_th[2]);
  }

  // Elastic strain energy per unit volume, sigma_m : S : sigma_m / 2 with
  // sigma_m the stress in material axes: the expansion strains store none.
  double stored_energy(const State& state, const Voigt& sigma, const Voigt&) const {
    const Voigt s = to_material(state.axes.toRotationMatrix(), sigma);
    const Eigen::Vector3d n(s[0], s[1], s[2]);
    const Parameters& p = parameters;
    return 0.5 * n.dot(S_n * n) + s[3] * s[3] / (2.0 * p.Gyz) + s[4] * s[4] / (2.0 * p.Gxz) +
           s[5] * s[5] / (2.0 * p.Gxy);
  }
};

}  // namespace flowmpm
