// The largest stable time step of a scheme and shape function, and the one
// accepted: dt <= f h_min / c_max with h_min the smallest cell, c_max the
// fastest P wave of the materials, and f the shape function's stable factor
// for the scheme and the particles per cell (docs/STABILITY.md: a von
// Neumann analysis of the update, checked on the vibrating bar and the 2D
// column; axisymmetric, a solid section on the axis), taken with a margin
// of 10 %. With dt = "auto" the particles'
// speed is added to c_max at every step. When the scene conducts heat or
// diffuses solvent, the explicit diffusion limit joins it, and an imperfect
// interface's springs join the wave limit (TimeStepLimit).
#pragma once
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <variant>

#include "discretisation/shapes/shape_functions.hpp"
#include "discretisation/system_spec.hpp"
#include "engine/schemes.hpp"

namespace flowmpm {

struct StableStep {
  double crossing = 0.0;  // h_min / c_max (s)
  std::string material;   // the material with the fastest wave
  double particles_per_cell = 1.0;  // along the densest axis of any body
  double factor = 0.0;    // f: the stable factor with its margin
  double dt() const { return factor * crossing; }  // the largest accepted dt (s)
};

inline constexpr double stability_margin = 0.9;

inline StableStep stable_time_step(const SystemSpec& spec, const Scheme& scheme) {
  StableStep s;
  double h_min = std::numeric_limits<double>::infinity();
  for (int d = 0; d < spec.dimension; ++d) h_min = std::min(h_min, spec.grid.cell_size[d]);
  s.crossing = std::numeric_limits<double>::infinity();
  for (const auto& m : spec.materials) {
    const double dt = h_min / wave_speed(m.model);
    if (dt < s.crossing) s.crossing = dt, s.material = m.name;
  }
  for (const BodySpec& body : spec.bodies) {
    // Particles from a file: the mean particle's size V^(1/D) as their spacing.
    double file_spacing = 0.0;
    if (body.particles) {
      for (const double v : body.particles->volume) file_spacing += v;
      file_spacing = std::pow(file_spacing / static_cast<double>(body.particles->size()), 1.0 / spec.dimension);
    }
    for (int d = 0; d < spec.dimension; ++d) {
      const double spacing = body.particles ? file_spacing : body.spacing[d];
      s.particles_per_cell = std::max(s.particles_per_cell, spec.grid.cell_size[d] / spacing);
    }
  }
  const int i = std::clamp(static_cast<int>(std::ceil(s.particles_per_cell - 1e-9)), 1, 4) - 1;
  s.factor = stability_margin * with_shape_function(spec.shape_function, [&]<class Shape>() {
               if constexpr (requires { Shape::stable_factor_usl_axisymmetric; }) {
                 if (spec.axisymmetric && scheme.wiring.stress_from_updated_grid())
                   return Shape::stable_factor_usl_axisymmetric[i];
               }
               return scheme.wiring.stress_from_updated_grid()
                        ? Shape::stable_factor_usl[i]
                        : Shape::stable_factor_remapped[i];
             });
  // Beyond 4 per cell, the trend of uGIMP's USL limit at a free surface
  // (|dN|^2 / N grows with the particles per cell); conservative for the others.
  if (s.particles_per_cell > 4.0) s.factor *= std::sqrt(4.0 / s.particles_per_cell);
  return s;
}

struct DiffusionStep {
  double dt = 0.0;          // s
  std::string material;     // the material with the largest diffusivity
  std::string field;        // "heat" or "solvent"
  double diffusivity = 0.0;  // its k / (rho C) or D (m^2/s)
};

// The explicit transport update (tasks/transport.hpp: forward Euler with
// the lumped capacities M and the conduction matrix K) is stable for
// dt <= 2 / lambda_max(M^-1 K). lambda_max is at most the largest principal
// diffusivity kappa times that of isotropic unit conduction, whose rows are
// bounded (Gershgorin) by 4 sum_d 1 / h_d^2 when the particles of a body
// sit on their lattice: per axis, the gradients of a particle's shape
// functions sum in absolute value to at most 2 / h_d (linear, uGIMP,
// B-splines). Hence
//   dt <= 1 / (2 kappa sum_d 1 / h_d^2)   (= h^2 / (2 D kappa) on cubic cells),
// kappa = k / (rho C) for heat and D for solvent, the largest along the
// material axes in the analysis' plane. A bound, not an estimate (the
// particle scheme is stable up to 3 times it: docs/theory/stability.md), so it
// takes no margin. None when nothing is transported.
inline std::optional<DiffusionStep> diffusion_time_step(const SystemSpec& spec) {
  double inverse_h2 = 0.0;
  for (int d = 0; d < spec.dimension; ++d) inverse_h2 += 1.0 / (spec.grid.cell_size[d] * spec.grid.cell_size[d]);
  std::optional<DiffusionStep> result;
  auto consider = [&](double kappa, const std::string& material, const char* field) {
    if (!(kappa > 0.0)) return;
    const double dt = 1.0 / (2.0 * kappa * inverse_h2);
    if (!result || dt < result->dt) result = DiffusionStep{dt, material, field, kappa};
  };
  for (const auto& m : spec.materials) {
    const TransportProperties& p = transport(m.model);
    if (p.conducts()) consider(p.heat_diffusivity(density(m.model), spec.dimension), m.name, "heat");
    if (p.diffuses()) consider(p.solvent_diffusivity(spec.dimension), m.name, "solvent");
  }
  return result;
}

struct InterfaceStep {
  double dt = 0.0;           // s, with the margin
  std::string contact;       // the interface that sets it, "a~b"
  double stiffness = 0.0;    // its larger D (Pa/m)
  double density_a = 0.0, density_b = 0.0;  // the lightest material on each side (kg/m^3)
};

// An interface (discretisation/contact/contact_law_interface.hpp) ties the
// masses m_a, m_b of its two bodies at a node by a spring k = D A_I, and
// the central difference is stable for that pair alone while
// dt <= 2 / sqrt(k (1 / m_a + 1 / m_b)) ([Belytschko 2000]). Estimated from
// the initial state at a node of a face along the grid, where the interface
// area is A_I = h^(D-1), with m = rho h^D / 4 on each side (h the smallest
// cell; D the larger of D_n and D_t; rho the lightest material on each
// side):
//   dt_i = sqrt(h / (D (1 / rho_a + 1 / rho_b))),
// taken with the wave limit's margin; the smallest over the interfaces.
// The node holds rho h^D / 2 of each body, but the interface's displacement
// fit reads the particle row next to the face with weights up to 1.5, and
// two bonded blocks (linear shape functions, 2 particles per cell) blow up
// from 0.85 of the limit with the whole nodal mass: a quarter keeps a
// margin (docs/theory/contact.md). None without interfaces.
inline std::optional<InterfaceStep> interface_time_step(const SystemSpec& spec) {
  double h_min = std::numeric_limits<double>::infinity();
  for (int d = 0; d < spec.dimension; ++d) h_min = std::min(h_min, spec.grid.cell_size[d]);
  // The lightest material of a body or of the contact group it stands for.
  const auto lightest = [&](int named) {
    double rho = std::numeric_limits<double>::infinity();
    const int group = spec.bodies[static_cast<std::size_t>(named)].contact_group;
    for (std::size_t b = 0; b < spec.bodies.size(); ++b) {
      if (static_cast<int>(b) != named && (group < 0 || spec.bodies[b].contact_group != group)) continue;
      rho = std::min(rho, density(spec.materials[static_cast<std::size_t>(spec.bodies[b].material)].model));
    }
    return rho;
  };
  std::optional<InterfaceStep> result;
  for (const ContactSpec& c : spec.contacts) {
    const auto* law = std::get_if<InterfaceLaw>(&c.law);
    if (!law) continue;
    const double stiffness = std::max(law->normal_stiffness, law->tangential_stiffness);
    if (!(stiffness > 0.0)) continue;
    const double rho_a = lightest(c.first), rho_b = lightest(c.second);
    const double dt = stability_margin * std::sqrt(h_min / (stiffness * (1.0 / rho_a + 1.0 / rho_b)));
    if (!result || dt < result->dt) result = InterfaceStep{dt, c.names[0] + "~" + c.names[1], stiffness, rho_a, rho_b};
  }
  return result;
}

// Two limits that act on the same nodes (the wave limit and an
// interface's): their stiffnesses add, and so do their squared frequencies
// (at most), 1 / dt^2 = 1 / dt_a^2 + 1 / dt_b^2.
inline double joined_dt(double dt_a, double dt_b) { return 1.0 / std::sqrt(1.0 / (dt_a * dt_a) + 1.0 / (dt_b * dt_b)); }

// The limits of a scene: the wave limit joined by the interfaces'
// (mechanical_dt); the accepted dt is the smaller of that and the
// diffusion limit.
struct TimeStepLimit {
  StableStep wave;
  std::optional<DiffusionStep> diffusion;  // with transport only
  std::optional<InterfaceStep> interface;  // with interfaces only

  double mechanical_dt() const { return interface ? joined_dt(wave.dt(), interface->dt) : wave.dt(); }
  double dt() const { return diffusion ? std::min(mechanical_dt(), diffusion->dt) : mechanical_dt(); }
  bool diffusion_governs() const { return diffusion && diffusion->dt < mechanical_dt(); }
};

inline TimeStepLimit time_step_limit(const SystemSpec& spec, const Scheme& scheme) {
  return {stable_time_step(spec, scheme), diffusion_time_step(spec), interface_time_step(spec)};
}

}  // namespace flowmpm
