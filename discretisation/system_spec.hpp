// What a discrete system is built from (build_system.hpp): the grid, the
// bodies with their materials, the node sets and the analysis choices, as
// plain validated structs. io fills them from a case file; the tests and the
// bench may fill them directly. SI units: m, s, kg, Pa.
#pragma once
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "core/time_function.hpp"
#include "core/vec.hpp"
#include "discretisation/bodies/body_shape.hpp"
#include "discretisation/contact/contact_laws.hpp"
#include "discretisation/loads/external_loads.hpp"
#include "discretisation/bodies/initial_stress.hpp"
#include "discretisation/loads/loads.hpp"
#include "discretisation/grid/particle_list.hpp"
#include "discretisation/shapes/shape_functions.hpp"
#include "materials/material.hpp"

namespace flowmpm {

// How the particles' velocity is updated from the grid (docs/theory/step.md): FLIP adds the grid's velocity change, PIC takes the grid's
// velocity, blend mixes them by flip_fraction.
enum class VelocityUpdate { flip, pic, blend };
inline const char* velocity_update_name(VelocityUpdate u) {
  switch (u) {
    case VelocityUpdate::flip: return "flip";
    case VelocityUpdate::pic: return "pic";
    case VelocityUpdate::blend: return "blend";
  }
  return "";
}

struct GridSpec {
  Vec3 origin{};
  Vec3 cell_size{1.0, 1.0, 1.0};
  std::array<int, 3> cells{1, 1, 1};
};

struct BodySpec {
  std::string name;
  std::string where;  // "file:line: bodies[k]", for messages once the case is read
  int material = 0;   // index into SystemSpec::materials
  // The particles: the points of the lattice at `spacing` (m per axis)
  // inside `shape` (lattice.hpp), or, when given, `particles` (from a file).
  BodyShape shape;
  Vec3 spacing{};
  std::optional<ParticleList> particles;
  Vec3 velocity{};  // initial velocity (m/s)
  // Initial angular velocity (rad/s) about the centroid of the body's
  // particles: v_p = velocity + omega x (x_p - x_c). In 2D only z.
  Vec3 angular_velocity{};
  // Initial stress (Pa); particles from a file may carry their own instead.
  std::optional<InitialStressVariant> initial_stress;
  // Bodies (indices into SystemSpec::bodies) that lose their particles
  // where they overlap this one; any other overlap is an error.
  std::vector<int> wins_over;
  // Rotation of the material axes (degrees) about z, y, x: R = Rz Ry Rx.
  Vec3 material_axes{};
  // Cylindrical material axes: each particle's angle about z gets
  // atan2(y - y_c, x - x_c) added, so that the material x axis points away
  // from the axis through (x_c, y_c) parallel to z (wood: radial, with the
  // material y tangential and z along the pith).
  std::optional<std::array<double, 2>> material_axes_center;
  // Initial temperature (K) and solvent concentration (weight fraction) of
  // the particles, used when the scene conducts heat (diffuses solvent).
  double temperature = 0.0;
  double concentration = 0.0;
  // A rigid body (contact): its particles move with this velocity (m/s per
  // axis, absent = 0) and carry no mass, no material and no stress.
  std::optional<AxisFunctions> rigid_velocity;
  bool rigid() const { return rigid_velocity.has_value(); }
  // Its contact group (an index into SystemSpec::contact_groups; -1 none):
  // the bodies of a group share one velocity field.
  int contact_group = -1;
};

// Two bodies in contact and the law between them
// (discretisation/contact/contact_fields.hpp).
struct ContactSpec {
  std::string where;          // "file:line: contacts[k]", for messages once the case is read
  // Indices into SystemSpec::bodies, of a body or of the first body of a
  // contact group (its field is the group's); second may be rigid, first not.
  int first = 0, second = 1;
  std::array<std::string, 2> names;  // the bodies or groups as the case names them
  ContactLaw law;
  double touch_fraction = 0.6;
};

struct NodeSetSpec {
  std::string name;
  // Nodes with x_axis == at (plane), or inside [box_min, box_max] (box).
  bool is_plane = true;
  int axis = 0;
  double at = 0.0;
  Vec3 box_min{}, box_max{};
  // Prescribed velocity per axis (m/s) as a function of time; absent = free.
  std::array<std::optional<TimeFunction>, 3> velocity;
  // Prescribed temperature (K) and concentration (weight fraction) as
  // functions of time; absent = insulated (no flux through the grid edge).
  std::optional<TimeFunction> temperature, concentration;
  // A wall (a plane only): instead of prescribing `velocity`, the plane
  // moves with it (absent axes 0) and acts on the material by this contact
  // law, holding it only in compression (tasks/wall.hpp).
  std::optional<ContactLaw> wall;

  bool constrains_velocity() const {
    if (wall) return false;
    for (const auto& v : velocity)
      if (v) return true;
    return false;
  }
};

// A flux into a body through one face of its box, carried by the layer of
// particles on that face (as NairnMPM's particle-based flux conditions):
// each adds N_Ip q A_p to the nodal flow, A_p the face area it represents.
struct SurfaceFluxSpec {
  std::string name;
  int body = 0;  // index into SystemSpec::bodies
  int axis = 0;  // the face's normal axis
  int side = -1;  // -1: the face at the box's min, +1: at its max
  std::optional<TimeFunction> heat;     // W/m^2 into the body
  std::optional<TimeFunction> solvent;  // kg/(m^2 s) of solvent into the body
};

struct SystemSpec {
  std::string source;  // where it was read from (the case file), for messages
  int dimension = 3;
  bool plane_stress = false;              // 2D: plane stress instead of plane strain
  ShapeChoice shape_function;             // the shape function (discretisation/shapes/shape_functions.hpp)
  VelocityUpdate velocity_update = VelocityUpdate::flip;
  double flip_fraction = 1.0;             // 1: FLIP, 0: PIC
  Vec3 gravity{};                         // m/s^2
  double dt = 0.0;                        // the first step's time step (s)
  bool keep_initial_positions = false;    // store x0 (a reference measures from it)
  GridSpec grid;
  std::vector<NamedMaterial> materials;
  std::vector<BodySpec> bodies;
  std::vector<NodeSetSpec> node_sets;
  std::vector<SurfaceFluxSpec> surface_fluxes;
  std::vector<ContactSpec> contacts;  // empty: no contact, one velocity field
  std::vector<std::string> contact_groups;  // names of groups of bodies sharing a field (BodySpec::contact_group)

  // The particles carry a temperature when some material conducts heat, a
  // concentration when some material diffuses solvent; nothing otherwise.
  bool conducts_heat() const {
    for (const auto& m : materials)
      if (transport(m.model).conducts()) return true;
    return false;
  }
  bool diffuses_solvent() const {
    for (const auto& m : materials)
      if (transport(m.model).diffuses()) return true;
    return false;
  }
  std::vector<Load> loads;          // docs/guide/loads.md
  std::optional<Damping> damping;   // quasi-static damping, if any
};

}  // namespace flowmpm
