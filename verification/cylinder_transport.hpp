// Heat conduction or solvent diffusion in a long solid cylinder of radius
// `radius` whose surface is held at `boundary` from t = 0, in axisymmetric
// analysis (x = r; the faces across the axis insulated, so the field
// depends on r alone): the temperature or concentration of every particle
// against the Bessel series (verification/cylinder_series.hpp) at its
// initial radius x0_r. kappa is the diffusivity along r of the first
// body's material with its material axes (slab_transport.hpp's
// diffusivity_along); the hoop conductivity does not enter (no gradient
// along theta). Error: the mass-weighted (here per radian, so r-weighted)
// RMS over the particles and the samples, relative to |u_b - u0|.
#pragma once
#include <cmath>
#include <map>
#include <string>

#include "discretisation/discrete_system.hpp"
#include "verification/cylinder_series.hpp"
#include "verification/error_norm.hpp"
#include "verification/reference_context.hpp"
#include "verification/slab_transport.hpp"

namespace flowmpm {

struct CylinderTransport {
  static constexpr const char* type_name = "cylinder_transport";
  bool heat = true;  // temperature, or concentration
  CylinderSeries exact;
  RmsError error;

  static CylinderTransport read(ParameterTable& t, const ReferenceContext& context) {
    t.require(context.system.axisymmetric, "type",
              "an axisymmetric case (analysis.stress_state = \"axisymmetric\") for cylinder_transport");
    CylinderTransport r;
    r.heat = t.choice("field", {"temperature", "concentration"}) == "temperature";
    r.exact.radius = t.positive("radius", "the cylinder's radius in m");
    r.exact.initial = t.number("initial");
    r.exact.boundary = t.number("boundary");
    t.require(r.exact.boundary != r.exact.initial, "boundary", "a surface value other than the initial one");
    r.exact.kappa = diffusivity_along(t, context, r.heat, 0);
    return r;
  }

  template <int D, class Shape>
  void initialise(DiscreteSystem<D, Shape>&) const {}

  template <int D, class Shape>
  void sample(const DiscreteSystem<D, Shape>& system) {
    if (system.step == 0) return;  // the initial state is exact by construction
    for (const auto& b : system.batches) {
      const std::vector<double>& u = heat ? b.temperature : b.concentration;
      for (std::size_t p = 0; p < b.size(); ++p) error.add(b.mass[p], u[p] - exact(b.x0[p][0], system.t));
    }
  }

  // What the samples have summed so far (Reference::visit_state).
  template <class F>
  void visit_state(F&& f) {
    f("error", error);
  }

  std::map<std::string, double> errors() const {
    return {{heat ? "temperature" : "concentration", error.relative_to(std::abs(exact.boundary - exact.initial))}};
  }
};

}  // namespace flowmpm
