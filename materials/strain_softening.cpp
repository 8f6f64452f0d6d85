#include "materials/strain_softening.hpp"

#include <sstream>

#include "core/errors.hpp"
#include "core/parameter_table.hpp"
#include "materials/parameter_reading.hpp"

namespace flowmpm {

StrainSoftening StrainSoftening::read(ParameterTable& t) {
  Parameters p;
  std::tie(p.density, p.youngs_modulus, p.poisson_ratio) = read_isotropic_elasticity(t);
  p.initiation_strain = t.number("initiation_strain");
  t.require(p.initiation_strain > 0.0, "initiation_strain", "a positive damage initiation strain eps_i");
  if (t.has("failure_strain") == t.has("fracture_energy")) {
    t.fail_table("give exactly one of failure_strain (eps_f, the same for every particle) and "
                 "fracture_energy (G_c in J/m^2, eps_f = 2 G_c / (E eps_i h) per particle size h)");
  }
  if (t.has("failure_strain")) {
    p.failure_strain = t.number("failure_strain");
    t.require(*p.failure_strain > p.initiation_strain, "failure_strain",
              "a failure strain eps_f above initiation_strain");
  } else {
    p.fracture_energy = t.number("fracture_energy");
    t.require(*p.fracture_energy > 0.0, "fracture_energy", "a positive fracture energy G_c in J/m^2");
  }
  p.transport = TransportProperties::read(t, isotropic_axes);
  if (t.has("nonlocal_length")) {
    const double l = t.number("nonlocal_length");
    t.require(p.fracture_energy.has_value(), "nonlocal_length",
              "fracture_energy beside it, not failure_strain (l measures the crack band's opening, "
              "against w_c = 2 G_c / (E eps_i))");
    t.require(l >= 0.0, "nonlocal_length",
              "a nonlocal length l >= 0 in m (0: the crack band of one cell, for a band that localises in a cell)");
    if (l > 0.0) p.nonlocal_length = l;
  } else if (p.fracture_energy) {
    p.nonlocal_length = default_nonlocal_length(p);
  }
  return StrainSoftening(p);
}

StrainSoftening::State StrainSoftening::initial_state(const ParticleInit& init) const {
  State s;
  // The strain that carries the initial stress, C^-1 sigma = ((1 + nu) sigma
  // - nu tr(sigma) I) / E (0 without one), so that the stress, a function
  // of the total strain, starts from it.
  const double E = parameters.youngs_modulus, nu = parameters.poisson_ratio;
  const double tr = init.stress[0] + init.stress[1] + init.stress[2];
  for (int i = 0; i < 6; ++i) s.eps[i] = ((1.0 + nu) * init.stress[i] - (i < 3 ? nu * tr : 0.0)) / E;
  if (parameters.failure_strain) {
    s.eps_f = *parameters.failure_strain;
    return s;
  }
  const double eps_i = parameters.initiation_strain;
  const double G_c = *parameters.fracture_energy;
  s.eps_f = init.cell_length > 0.0 ? 2.0 * G_c / (E * eps_i * init.cell_length) : 0.0;
  if (!(s.eps_f > eps_i)) {
    std::ostringstream m;
    m.precision(6);
    m << "strain_softening: cells of size h = " << init.cell_length << " m are too large for the crack band of "
      << "fracture_energy = " << G_c << " J/m^2: eps_f = 2 G_c / (E eps_i h) = " << s.eps_f
      << " is not above initiation_strain = " << eps_i << " (the band would snap back); use "
      << "cells smaller than 2 G_c / (E eps_i^2) = " << 2.0 * G_c / (E * eps_i * eps_i) << " m";
    throw CaseError(m.str());
  }
  if (parameters.nonlocal_length && *parameters.nonlocal_length < init.cell_length) {
    std::ostringstream m;
    m.precision(6);
    m << "strain_softening: nonlocal_length = " << *parameters.nonlocal_length << " m is below the cell size h = "
      << init.cell_length << " m: the particles would not resolve the Gaussian weight; use a nonlocal_length of "
      << "at least the cell size (about twice the width of the band that forms)";
    throw CaseError(m.str());
  }
  return s;
}

}  // namespace flowmpm
