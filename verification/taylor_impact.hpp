// A Taylor impact: a von_mises bar (the first body) moving along `axis`
// into a rigid, frictionless wall at `wall` (a constrained node plane of
// the case). No closed form for the final shape; the energy balance is:
// the wall does no work, so kinetic energy + stored elastic energy +
// plastic dissipation stays the initial kinetic energy E_0. The plastic
// dissipation of a particle is its volume times the work of the yield
// stress along its plastic strain, int_0^eps_p sigma_Y de:
// linear hardening sigma_0 eps_p + H eps_p^2 / 2, power law
// sigma_0 eps_0 / (n + 1) ((1 + eps_p / eps_0)^(n + 1) - 1).
// Error, over the samples: energy, max |E_k + E_s + W_p - E_0| / E_0.
// Measures at the end: final_length (the highest particle's distance from
// the wall plus half a particle), foot_radius (half the caliper width of
// the particles that started in the layer at the wall, along the grid axes
// normal to the bar's: the largest |x_k - center_k| plus half a particle,
// averaged over those axes), their ratios to `length` and `radius`, and
// plastic_work (W_p / E_0). A caliper along the grid axes, not the largest
// distance from the axis: a Cartesian lattice fills a round bar as a
// staircase whose corners stand up to half a particle beyond its radius
// between the axes, while along them its outermost particles lie at the
// radius less half a particle, so the measure starts at the bar's radius
// in 2D, axisymmetric and 3D alike.
#pragma once
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <string>

#include "engine/diagnostics.hpp"
#include "verification/reference_context.hpp"

namespace flowmpm {

struct TaylorImpact {
  static constexpr const char* type_name = "taylor_impact";
  int axis = 1;
  double wall = 0.0, length0 = 0.0, radius0 = 0.0;
  Vec3 center{};
  VonMises::Parameters material{};
  double energy0 = std::numeric_limits<double>::quiet_NaN();
  double energy_error = 0.0, length = 0.0, foot = 0.0, plastic = 0.0;

  static TaylorImpact read(ParameterTable& t, const ReferenceContext& context) {
    const SystemSpec& s = context.system;
    TaylorImpact r;
    const auto* m = s.bodies.at(0).rigid() ? nullptr : std::get_if<VonMises>(&s.materials.at(s.bodies.at(0).material).model);
    if (!m) t.fail("type", "a case whose first body is von_mises for taylor_impact");
    r.material = m->parameters;
    r.axis = read_axis(t, "axis", s.dimension);
    r.wall = t.number("wall");
    r.length0 = t.positive("length", "the bar's initial length in m");
    r.radius0 = t.positive("radius", "the bar's initial radius (half-width in 2D) in m");
    const std::vector<double> c = t.numbers("center", static_cast<std::size_t>(s.dimension));
    std::copy(c.begin(), c.end(), r.center.begin());
    return r;
  }

  // int_0^eps_p sigma_Y(e) de (J/m^3).
  double plastic_work_density(double eps_p) const {
    const VonMises::Parameters& m = material;
    if (m.hardening == VonMises::Hardening::linear) {
      return m.yield_stress * eps_p + 0.5 * m.hardening_modulus * eps_p * eps_p;
    }
    const double n = m.hardening_exponent, e0 = m.reference_strain;
    return m.yield_stress * e0 / (n + 1.0) * (std::pow(1.0 + eps_p / e0, n + 1.0) - 1.0);
  }

  template <int D, class Shape>
  void initialise(DiscreteSystem<D, Shape>&) const {}

  template <int D, class Shape>
  void sample(const DiscreteSystem<D, Shape>& system) {
    const Diagnostics d = diagnostics(system, 1);
    double work = 0.0, top = -std::numeric_limits<double>::infinity();
    Vec3 half_width{};  // along each grid axis, of the wall layer
    for (const auto& b : system.batches) {
      const double half = 0.5 * b.particle_length;
      if (const auto* states = std::get_if<StateArray<VonMises>>(&b.states)) {
        for (std::size_t p = 0; p < states->size(); ++p) work += b.volume[p] * plastic_work_density((*states)[p].eps_p);
      }
      for (std::size_t p = 0; p < b.size(); ++p) {
        top = std::max(top, std::abs(b.x[p][axis] - wall) + half);
        if (std::abs(b.x0[p][axis] - wall) < b.particle_length) {
          for (int k = 0; k < D; ++k) half_width[k] = std::max(half_width[k], std::abs(b.x[p][k] - center[k]) + half);
        }
      }
    }
    const double energy = d.kinetic_energy + d.stored_energy + work;
    if (std::isnan(energy0)) energy0 = energy;
    energy_error = std::max(energy_error, std::abs(energy - energy0) / energy0);
    length = top;
    foot = 0.0;
    for (int k = 0; k < D; ++k)
      if (k != axis) foot += half_width[k] / (D - 1);
    plastic = work / energy0;
  }

  // The energy at the first sample, the largest error so far and the last sample (Reference::visit_state).
  template <class F>
  void visit_state(F&& f) {
    f("energy0", energy0);
    f("energy_error", energy_error);
    f("length", length);
    f("foot", foot);
    f("plastic", plastic);
  }

  std::map<std::string, double> errors() const { return {{"energy", energy_error}}; }
  std::map<std::string, double> measures() const {
    return {{"final_length", length},
            {"foot_radius", foot},
            {"length_ratio", length / length0},
            {"foot_ratio", foot / radius0},
            {"plastic_work", plastic}};
  }
};

}  // namespace flowmpm
