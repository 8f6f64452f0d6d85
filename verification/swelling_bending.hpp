// A free strip wetted (or dried) from one face warps: the face that swells
// more grows longer and the strip bends. 2D plane strain, the strip across
// `axis` (its thickness H, from `from` to `from + H`), its face at
// from + H held at the concentration u_b(t) (a node set of the case), the
// other faces insulated; an orthotropic (or transversely isotropic)
// material with its axes aligned with the global ones. Quasi-static closed
// forms:
//  - the concentration: the insulated face is a plane of symmetry, so c is
//    the series of a slab of thickness 2 H held on both faces
//    (verification/slab_series.hpp) at X = y - from + H;
//  - the curvature, by beam theory ([Timoshenko 1970], thermal bending of
//    a free beam, beta c for alpha dT): with sigma across the strip 0 and
//    eps_zz = 0 (plane strain), the eigenstrain along the strip is
//    eps* = (beta_x + nu_zx beta_z) c (nu_zx = -S_13 / S_33, as the thermal
//    block's alpha_x + nu_zx alpha_z) and the modulus uniform, so
//      kappa(t) = 12 / H^3 integral_0^H eps*(y, t) (y - H / 2) dy,
//    positive when the wetted face grows longer (the strip's ends then bend
//    away from it: u_axis = -kappa x^2 / 2).
// Measured: each row of particles (one initial position across the strip)
// in the middle `span` of the strip's length gets a least-squares parabola
// u_axis = a + b x + q x^2 of its displacement along the axis against its
// initial position x along the strip; kappa = -2 q, the rows averaged by
// mass. Errors: `concentration` (mass-weighted RMS over the particles and
// the samples, relative to the largest |u_b - u0|) and `curvature` (RMS
// over the samples of kappa - kappa_beam, relative to the largest
// |kappa_beam|).
#pragma once
#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Dense>

#include "discretisation/discrete_system.hpp"
#include "verification/error_norm.hpp"
#include "verification/reference_context.hpp"
#include "verification/slab_transport.hpp"

namespace flowmpm {

struct SwellingBending {
  static constexpr const char* type_name = "swelling_bending";
  int axis = 1, along = 0;  // across the strip (its thickness), along it
  double from = 0.0, thickness = 0.0, span = 0.5;
  double centre = 0.0, half_length = 0.0;  // of the strip along `along` (m)
  SlabSeries exact;  // of the slab of thickness 2 H
  double eigenstrain_per_c = 0.0;  // beta_x + nu_zx beta_z
  double amplitude = 0.0;
  RmsError concentration;
  std::vector<double> measured, beam;  // curvature per sample (1/m)

  static SwellingBending read(ParameterTable& t, const ReferenceContext& context) {
    const SystemSpec& s = context.system;
    t.require(s.dimension == 2 && !s.plane_stress, "type", "a 2D plane-strain case for swelling_bending");
    SwellingBending r;
    r.axis = read_axis(t, "axis", s.dimension);
    r.along = 1 - r.axis;
    r.from = t.number("from");
    r.thickness = t.positive("thickness", "the strip's thickness along the axis in m");
    r.span = t.number_or("span", 0.5);
    t.require(r.span > 0.0 && r.span <= 1.0, "span", "the fraction of the strip's length measured, in (0, 1]");
    r.exact.length = 2.0 * r.thickness;
    r.exact.initial = t.number("initial");
    r.exact.boundary = t.time_function("boundary", "the concentration the wetted face is held at");
    for (const auto& [time, value] : r.exact.boundary.points)
      r.amplitude = std::max(r.amplitude, std::abs(value - r.exact.initial));
    t.require(r.amplitude > 0.0, "boundary", "a face concentration other than the initial one");
    const BodySpec& body = s.bodies.at(0);
    for (double angle : body.material_axes) t.require(angle == 0.0, "type", "a first body with unturned material axes");
    r.exact.kappa = diffusivity_along(t, context, false, r.axis);
    const Orthotropic* m = std::get_if<Orthotropic>(&s.materials.at(body.material).model);
    if (!m) m = std::get_if<TransverselyIsotropic>(&s.materials.at(body.material).model);
    if (!m || !m->parameters.expansion.solvent || m->parameters.expansion.concentration) {
      t.fail("type", "a first body of an orthotropic or transversely isotropic material that swells with the "
                     "diffused solvent (beta and a diffusivity)");
    }
    const double nu_zx = -m->S_n(r.along, 2) / m->S_n(2, 2);
    const auto& beta = m->parameters.expansion.beta;
    r.eigenstrain_per_c = beta[r.along] + nu_zx * beta[2];
    if (body.particles || body.shape.type() != std::string_view("box")) {
      t.fail("type", "a first body that is a box (the strip)");
    }
    const BoxShape box = body.shape.bounds();
    r.centre = 0.5 * (box.min[r.along] + box.max[r.along]);
    r.half_length = 0.5 * (box.max[r.along] - box.min[r.along]);
    return r;
  }

  template <int D, class Shape>
  void initialise(DiscreteSystem<D, Shape>&) const {}

  // c(y, t) of the strip: the slab of thickness 2 H, mirrored about the
  // insulated face.
  double concentration_at(double y, double t) const { return exact(y - from + thickness, t); }

  // kappa_beam(t) by Simpson's rule over the thickness.
  double beam_curvature(double t) const {
    const int n = 200;
    const double dy = thickness / n;
    double sum = 0.0;
    for (int i = 0; i <= n; ++i) {
      const double y = i * dy, w = i == 0 || i == n ? 1.0 : i % 2 ? 4.0 : 2.0;
      sum += w * eigenstrain_per_c * concentration_at(from + y, t) * (y - 0.5 * thickness);
    }
    return 12.0 / (thickness * thickness * thickness) * sum * dy / 3.0;
  }

  template <int D, class Shape>
  void sample(const DiscreteSystem<D, Shape>& system) {
    if (system.step == 0) return;  // the initial state is exact by construction
    // Least-squares parabola per row of particles (one initial position
    // across the strip): sums of 1, x, x^2, x^3, x^4 and of u, u x, u x^2.
    struct Row {
      double mass = 0.0;
      Eigen::Matrix3d A = Eigen::Matrix3d::Zero();
      Eigen::Vector3d b = Eigen::Vector3d::Zero();
    };
    std::map<double, Row> rows;
    std::map<double, double> c_at;
    for (const auto& bt : system.batches) {
      for (std::size_t p = 0; p < bt.size(); ++p) {
        const double y = bt.x0[p][axis];
        auto [at, missing] = c_at.try_emplace(y, 0.0);
        if (missing) at->second = concentration_at(y, system.t);
        concentration.add(bt.mass[p], bt.concentration[p] - at->second);
        const double x = bt.x0[p][along] - centre;
        if (std::abs(x) > span * half_length) continue;
        const Eigen::Vector3d f(1.0, x, x * x);
        Row& row = rows[y];
        row.mass += bt.mass[p];
        row.A += f * f.transpose();
        row.b += f * (bt.x[p][axis] - bt.x0[p][axis]);
      }
    }
    double kappa = 0.0, mass = 0.0;
    for (const auto& [y, row] : rows) {
      kappa += row.mass * -2.0 * row.A.ldlt().solve(row.b)[2];
      mass += row.mass;
    }
    measured.push_back(kappa / mass);
    beam.push_back(beam_curvature(system.t));
  }

  // What the samples have summed so far and the curvatures sampled (Reference::visit_state).
  template <class F>
  void visit_state(F&& f) {
    f("concentration", concentration);
    f("measured", measured);
    f("beam", beam);
  }

  std::map<std::string, double> errors() const {
    double squares = 0.0, largest = 0.0;
    for (std::size_t k = 0; k < beam.size(); ++k) {
      squares += (measured[k] - beam[k]) * (measured[k] - beam[k]);
      largest = std::max(largest, std::abs(beam[k]));
    }
    return {{"concentration", concentration.relative_to(amplitude)},
            {"curvature", beam.empty() ? std::nan("") : std::sqrt(squares / beam.size()) / largest}};
  }
};

}  // namespace flowmpm
