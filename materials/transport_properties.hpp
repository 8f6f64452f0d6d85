// What a material contributes to heat conduction and solvent diffusion on
// the grid ([NairnMPM] "Orthotropic Material": conductivity and solvent
// diffusion per material axis; tasks/transport.hpp): the specific heat
// capacity, the conductivity and diffusivity tensors, diagonal along the
// material axes and turned with them like the stiffness
// (k = R diag(k_x, k_y, k_z) R^T), and the stress-free temperature that
// thermal expansion is measured from. Isotropic models give scalars.
//   heat:    rho C dT/dt = div(k grad T)
//   solvent: rho dc/dt = div(rho D grad c)   (c a weight fraction)
#pragma once
#include <optional>

#include <Eigen/Core>

#include "materials/axis_values.hpp"

namespace flowmpm {

class ParameterTable;

struct TransportProperties {
  double heat_capacity = 0.0;                                // C (J/(kg K)); 0: not given
  Eigen::Vector3d conductivity = Eigen::Vector3d::Zero();    // k along material x, y, z (W/(m K))
  Eigen::Vector3d diffusivity = Eigen::Vector3d::Zero();     // D along material x, y, z (m^2/s)
  std::optional<double> reference_temperature;               // T_ref, stress free (K)

  bool conducts() const { return conductivity.maxCoeff() > 0.0; }
  bool diffuses() const { return diffusivity.maxCoeff() > 0.0; }

  // The largest heat diffusivity k / (rho C) (m^2/s) along the material
  // axes that an analysis of `dimension` has in its plane (2D: the axes
  // turn about z, so material x and y span the plane; 1D: x).
  double heat_diffusivity(double density, int dimension) const {
    return largest(conductivity, dimension) / (density * heat_capacity);
  }
  double solvent_diffusivity(int dimension) const { return largest(diffusivity, dimension); }

  // Reads heat_capacity, conductivity, diffusivity and
  // reference_temperature (all optional), laid out per `layout`.
  // Conductivity and diffusivity must be >= 0, the heat capacity and the
  // reference temperature > 0; a conductivity needs a heat capacity.
  static TransportProperties read(ParameterTable& t, const AxisLayout& layout);

 private:
  static double largest(const Eigen::Vector3d& along_axes, int dimension) {
    return along_axes.head(dimension).maxCoeff();
  }
};

}  // namespace flowmpm
