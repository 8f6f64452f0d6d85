// A traction (Pa per axis, each a number or [[t, value], ...]) on one face
// direction of a body's surface ("+x", "-y", ...): on each surface face of
// that direction (surface_faces.hpp), optionally only those of particles
// inside `region` (a shape table), the force is the traction times the
// face's area (m^2; m per unit thickness in 2D, so N/m; 1 in 1D).
#pragma once
#include <optional>

#include "discretisation/loads/load_context.hpp"
#include "discretisation/bodies/surface_faces.hpp"

namespace flowmpm {

// "-x", "+x", "-y", ... up to the dimension.
inline std::vector<std::string> face_names(int dimension) {
  std::vector<std::string> names;
  for (int d = 0; d < dimension; ++d) {
    names.push_back(std::string("-") + "xyz"[d]);
    names.push_back(std::string("+") + "xyz"[d]);
  }
  return names;
}

// The region of a surface load: a shape table, or none.
inline std::optional<BodyShape> read_region(ParameterTable& t, int dimension) {
  if (!t.has("region")) return std::nullopt;
  std::optional<BodyShape> region;
  t.read_table("region", [&](ParameterTable& r) { region = BodyShape::read(r, {dimension}); });
  return region;
}

struct TractionLoad {
  static constexpr const char* type_name = "traction";
  int body = 0;
  int axis = 0;
  double sign = 1.0;
  std::optional<BodyShape> region;
  AxisFunctions traction;  // Pa
  std::string where;       // "file:line: loads[k].face", for messages when it is attached

  static TractionLoad read(ParameterTable& t, const LoadReadContext& c) {
    TractionLoad l;
    l.body = read_body_name(t, "body", c, true);
    const std::string face = t.choice("face", face_names(c.dimension));
    l.sign = face[0] == '+' ? 1.0 : -1.0;
    l.axis = face[1] - 'x';
    l.traction = read_axis_functions(t, "traction", c.dimension, "a traction in Pa");
    l.region = read_region(t, c.dimension);
    l.where = t.where(l.region ? "region" : "face");
    return l;
  }

  template <int D, class Shape>
  void attach(LoadSite<D, Shape>& site) const {
    const std::string& body_name = site.body_names[body];
    const BodyGeometry& g = site.bodies[body];
    SurfaceLoad<D> load;
    load.batch = body;
    load.faces = surface_faces<D>(site.system.batches[body], *g.shape, *g.lattice, region, std::pair{axis, sign});
    if (load.faces.empty()) {
      throw CaseError(where + ": expected " + (region ? "a region holding" : "a face with") + " particles of body \"" +
                      body_name + "\" on its " + (sign > 0 ? "+" : "-") + "xyz"[axis] +
                      " surface, got none: the traction would act on nothing");
    }
    load.traction = traction;
    load.description = "traction " + axis_functions_text(traction, "Pa") + " on " + std::to_string(load.faces.size()) +
                       " faces of body '" + body_name + "' (" + (sign > 0 ? "+" : "-") + "xyz"[axis] + ")";
    site.system.loads.surface.push_back(std::move(load));
  }
};

}  // namespace flowmpm
