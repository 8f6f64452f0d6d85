// Heat conduction or solvent diffusion across a slab whose two faces are
// held at `boundary` (a value or a function of time, as the node sets of
// the case hold them): the temperature or concentration of every particle
// against the series solution (verification/slab_series.hpp) at its
// initial position X = x0_axis - from. kappa is the diffusivity along
// the slab's axis of the first body's material with its material axes R:
// k_aa / (rho C) with k = R diag(k_x, k_y, k_z) R^T for heat, so that axes
// turned by theta about z give k_xx = k_x cos^2 theta + k_y sin^2 theta; D_aa
// for solvent. The series is exact for a slab unbounded across the axis;
// `min` and `max` (optional) restrict the measure to the particles that
// start inside that box, away from the insulated edges of a finite block
// (with axes turned, the conduction across the axis, k_xy dT/dx, is what
// those edges stop). Error: the mass-weighted RMS over those particles and
// the samples, relative to the largest |u_b - u0|.
#pragma once
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include "discretisation/discrete_system.hpp"
#include "materials/rotation.hpp"
#include "verification/error_norm.hpp"
#include "verification/reference_context.hpp"
#include "verification/slab_series.hpp"

namespace flowmpm {

// The diffusivity along `axis` of the first body's material, with its
// material axes: heat (k_aa / (rho C)) or solvent (D_aa).
inline double diffusivity_along(ParameterTable& t, const ReferenceContext& context, bool heat, int axis) {
  const SystemSpec& s = context.system;
  const BodySpec& body = s.bodies.at(0);
  const Material& m = s.materials.at(body.material).model;
  const TransportProperties& p = transport(m);
  if (heat ? !p.conducts() : !p.diffuses()) {
    t.fail("field", std::string("a case whose first body's material ") +
                        (heat ? "conducts heat (conductivity)" : "diffuses solvent (diffusivity)"));
  }
  if (body.material_axes_center) t.fail("type", "a first body with uniform material axes (no material_axes_center)");
  const Eigen::Matrix3d R = axes_rotation(body.material_axes).toRotationMatrix();
  const Eigen::Matrix3d along = R * (heat ? p.conductivity : p.diffusivity).asDiagonal() * R.transpose();
  return heat ? along(axis, axis) / (density(m) * p.heat_capacity) : along(axis, axis);
}

struct SlabTransport {
  static constexpr const char* type_name = "slab_transport";
  bool heat = true;  // temperature, or concentration
  int axis = 0;
  double from = 0.0;
  SlabSeries exact;
  Vec3 box_min{}, box_max{};
  RmsError error;

  static SlabTransport read(ParameterTable& t, const ReferenceContext& context) {
    const SystemSpec& s = context.system;
    SlabTransport r;
    r.heat = t.choice("field", {"temperature", "concentration"}) == "temperature";
    r.axis = read_axis(t, "axis", s.dimension);
    r.from = t.number("from");
    r.exact.length = t.positive("length", "the slab thickness along the axis in m");
    r.exact.initial = t.number("initial");
    r.exact.boundary = t.time_function("boundary", "the value the faces are held at (K or weight fraction)");
    t.require(r.amplitude() > 0.0, "boundary", "a face value other than the initial one");
    r.exact.kappa = diffusivity_along(t, context, r.heat, r.axis);
    for (int d = 0; d < 3; ++d) {
      r.box_min[d] = -std::numeric_limits<double>::infinity();
      r.box_max[d] = std::numeric_limits<double>::infinity();
    }
    for (const char* key : {"min", "max"}) {
      if (!t.has(key)) continue;
      const std::vector<double> corner = t.numbers(key, static_cast<std::size_t>(s.dimension));
      for (int d = 0; d < s.dimension; ++d) (key[1] == 'i' ? r.box_min : r.box_max)[d] = corner[d];
    }
    return r;
  }

  template <int D, class Shape>
  void initialise(DiscreteSystem<D, Shape>&) const {}

  template <int D, class Shape>
  void sample(const DiscreteSystem<D, Shape>& system) {
    if (system.step == 0) return;  // the initial state is exact by construction
    for (const auto& b : system.batches) {
      const std::vector<double>& u = heat ? b.temperature : b.concentration;
      for (std::size_t p = 0; p < b.size(); ++p) {
        bool inside = true;
        for (int d = 0; d < D; ++d) inside = inside && b.x0[p][d] >= box_min[d] && b.x0[p][d] <= box_max[d];
        if (inside) error.add(b.mass[p], u[p] - exact(b.x0[p][axis] - from, system.t));
      }
    }
  }

  // The largest difference between the faces and the initial value.
  double amplitude() const {
    double a = 0.0;
    for (const auto& [time, value] : exact.boundary.points) a = std::max(a, std::abs(value - exact.initial));
    return a;
  }

  // What the samples have summed so far (Reference::visit_state).
  template <class F>
  void visit_state(F&& f) {
    f("error", error);
  }

  std::map<std::string, double> errors() const {
    return {{heat ? "temperature" : "concentration", error.relative_to(amplitude())}};
  }
};

}  // namespace flowmpm
