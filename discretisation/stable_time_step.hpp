// The largest stable time step of the explicit update: the time a P wave
// takes to cross the smallest cell, h_min / c_max (CFL number 1); and, when
// the scene conducts heat or diffuses solvent, the explicit diffusion limit.
#pragma once
#include <algorithm>
#include <limits>
#include <optional>
#include <string>

#include "discretisation/system_spec.hpp"

namespace flowmpm {

struct StableStep {
  double dt;             // s
  std::string material;  // the material with the fastest wave
};

inline StableStep stable_time_step(const SystemSpec& spec) {
  double h_min = std::numeric_limits<double>::infinity();
  for (int d = 0; d < spec.dimension; ++d) h_min = std::min(h_min, spec.grid.cell_size[d]);
  StableStep result{std::numeric_limits<double>::infinity(), ""};
  for (const auto& m : spec.materials) {
    const double dt = h_min / wave_speed(m.model);
    if (dt < result.dt) result = {dt, m.name};
  }
  return result;
}

struct DiffusionStep {
  double dt;              // s
  std::string material;   // the material with the largest diffusivity
  std::string field;      // "heat" or "solvent"
  double diffusivity;     // its k / (rho C) or D (m^2/s)
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
// material axes in the analysis' plane. None when nothing is transported.
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

}  // namespace flowmpm
