// A pressure (Pa, a number or [[t, value], ...]; positive pushes into the
// body) on a body's surface, optionally only on the surface of particles
// inside `region` (a shape table): on each surface face (surface_faces.hpp)
// with outward normal n the force is -p n times the face's area. On a
// curved surface the faces form a staircase, so the force on any part of
// the surface is p times its projected area, to the lattice resolution.
#pragma once
#include "discretisation/loads/load_traction.hpp"

namespace flowmpm {

struct PressureLoad {
  static constexpr const char* type_name = "pressure";
  int body = 0;
  std::optional<BodyShape> region;
  TimeFunction pressure;  // Pa
  std::string where;

  static PressureLoad read(ParameterTable& t, const LoadReadContext& c) {
    PressureLoad l;
    l.body = read_body_name(t, "body", c, true);
    l.pressure = t.time_function("pressure", "a pressure in Pa");
    l.region = read_region(t, c.dimension);
    l.where = t.where(l.region ? "region" : "body");
    return l;
  }

  template <int D, class Shape>
  void attach(LoadSite<D, Shape>& site) const {
    const std::string& body_name = site.body_names[body];
    const BodyGeometry& g = site.bodies[body];
    SurfaceLoad<D> load;
    load.batch = body;
    load.faces = surface_faces<D>(site.system.batches[body], *g.shape, *g.lattice, region, std::nullopt);
    if (load.faces.empty()) {
      throw CaseError(where + ": expected a region holding surface particles of body \"" + body_name +
                      "\", got none: the pressure would act on nothing");
    }
    load.pressure = pressure;
    load.description = "pressure " + axis_functions_text({pressure}, "Pa").substr(2) + " on " +
                       std::to_string(load.faces.size()) + " faces of body '" + body_name + "'";
    site.system.loads.surface.push_back(std::move(load));
  }
};

}  // namespace flowmpm
