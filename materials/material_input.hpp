// What one material update sees besides its state and the stress, and what
// a model's per-particle state is initialised from.
#pragma once
#include <array>

#include <Eigen/Core>

#include "core/voigt.hpp"

namespace flowmpm {

struct MaterialInput {
  double t = 0.0;   // time at the end of the increment (s)
  double dt = 0.0;  // time step (s)
  // Velocity gradient increment L dt (3 x 3; rows and columns of axes the
  // analysis does not have are 0): sym(dL) is the strain increment, skew(dL)
  // the rotation increment W dt that objective updates need.
  Eigen::Matrix3d dL = Eigen::Matrix3d::Zero();
  // Particle size (m): the cube root of its initial volume in 3D, the square
  // root of its area in 2D, its length in 1D; for size-dependent
  // regularisation (crack band).
  double length = 0.0;
  // The particle's own temperature and solvent, when the scene conducts heat
  // or diffuses solvent (tasks/transport.hpp); 0 otherwise. Models with
  // expansion take them from here unless they are driven by a uniform
  // function of time (materials/expansion.hpp).
  double temperature_change = 0.0;  // T - T_ref at the end of the increment (K)
  // The changes since the last update (since the stress-free state, T_ref
  // and c = 0, before the first): what the rate-form models subtract.
  double temperature_step = 0.0;    // change of T (K)
  double concentration = 0.0;       // c at the end of the increment (weight fraction)
  double concentration_step = 0.0;  // change of c
  // For a model asking for a nonlocal average (materials/nonlocal_model.hpp):
  // the weighted average of its neighbours' sources at the end of this step,
  // sum_{q != p} alpha_pq V_q s_q / sum_q alpha_pq V_q, and the particle's
  // own weight in it, V_p / sum_q alpha_pq V_q
  // (discretisation/nonlocal/nonlocal_average.hpp). Both 0 where no engine computes
  // them (a material point driven alone).
  double nonlocal_others = 0.0;
  double nonlocal_self_weight = 0.0;
};

struct ParticleInit {
  std::array<double, 3> position{};  // m
  // Material-axes rotation of the particle, in degrees, about z, y and x,
  // applied as R = Rz Ry Rx ([NairnMPM]'s convention): its body's
  // material_axes, plus its polar angle about material_axes_center if the
  // body has one. In 2D only the angle about z is used.
  std::array<double, 3> axes_degrees{};
  double length = 0.0;  // as MaterialInput::length
  // Cell size (m): the geometric mean of the cell's edges. With linear shape
  // functions the particles of one cell share their velocity gradient, so a
  // band of localised strain is a cell wide, however many particles per
  // cell (crack band regularisation).
  double cell_length = 0.0;
  // The particle's initial stress (Pa; the body's initial_stress or its
  // particle file's, else 0). Models whose stress is a function of a total
  // measure (a strain in material axes, F) start from the one that carries
  // it; the rate-form models start from the stress itself.
  Voigt stress{};
};

}  // namespace flowmpm
