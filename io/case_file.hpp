// A case file (TOML) read into typed, validated structs. Nothing downstream
// looks up a string: the engine is built from this Case alone. Units are SI
// throughout (m, s, kg, Pa). See README.md "Case files" for every key.
#pragma once
#include <array>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "engine/time_function.hpp"
#include "io/snapshot.hpp"
#include "materials/material.hpp"

namespace flowmpm {

enum class Scheme { usf, usl, musl };
const char* scheme_name(Scheme s);

using Vec3 = std::array<double, 3>;  // a point or vector; unused axes are 0

struct GridSpec {
  Vec3 origin{};
  Vec3 cell_size{1.0, 1.0, 1.0};
  std::array<int, 3> cells{1, 1, 1};
};

struct BodySpec {
  std::string name;
  int material = 0;           // index into Case::materials
  Vec3 box_min{}, box_max{};  // the box filled with particles
  Vec3 spacing{};             // particle spacing per axis (m)
  Vec3 velocity{};            // initial velocity (m/s)
  // Rotation of the material axes (degrees) about z, y, x: R = Rz Ry Rx.
  Vec3 material_axes{};
  // Cylindrical material axes: each particle's angle about z gets
  // atan2(y - y_c, x - x_c) added, so that the material x axis points away
  // from the axis through (x_c, y_c) parallel to z (wood: radial, with the
  // material y tangential and z along the pith).
  std::optional<std::array<double, 2>> material_axes_center;
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
};

// An analytical solution to measure the run against ([reference] table;
// see engine/reference/ and README "Verification").
struct ReferenceSpec {
  std::string type;  // empty: none
  double origin = 0.0;    // fixed end, driven end or base (m)
  double length = 0.0;    // bar length or column height (m)
  double velocity = 0.0;  // vibration amplitude or driving velocity (m/s)
  double probe = 0.0;     // wave probe position (m)
  int mode = 1;           // vibration mode
  int axis = 0;           // loading axis
  std::int64_t samples = 0;  // error samples over the run (0: every step)
};

struct OutputSpec {
  std::filesystem::path directory;
  std::int64_t every = 0;  // steps between output steps (0: first and last only)
  OutputFields fields;
};

struct Case {
  std::string name;
  std::filesystem::path file;
  int dimension = 3;
  Scheme scheme = Scheme::usl;
  std::string shape_function = "linear";  // "linear", "gimp", "bspline2", "bspline3"
  bool plane_stress = false;              // 2D: plane stress instead of plane strain
  std::string velocity_update = "flip";
  double flip_fraction = 1.0;  // 1: FLIP, 0: PIC
  double dt = 0.0;             // s; with dt_auto, the first step's
  bool dt_auto = false;        // dt = cfl h_min / (c_max + |v|_max), every step
  double cfl = 0.5;            // with dt_auto
  std::int64_t steps = 0;      // 0 with dt_auto: run until end_time
  double end_time = 0.0;       // s
  // Blow-up guard: a particle faster than guard_speed_factor times the
  // fastest wave speed, or a non-finite value, stops the run; the state is
  // kept every guard_every steps (0: never) so that the last good one can
  // be written.
  double guard_speed_factor = 10.0;
  std::int64_t guard_every = 10;
  Vec3 gravity{};              // m/s^2
  GridSpec grid;
  std::vector<NamedMaterial> materials;
  std::vector<BodySpec> bodies;
  std::vector<NodeSetSpec> node_sets;
  OutputSpec output;
  ReferenceSpec reference;
};

// Reads and validates a case. `overrides` are "dotted.key=VALUE" strings
// (VALUE in TOML syntax) applied before validation, as from --set.
// Throws CaseError with a message naming file, line, key and what was
// expected.
Case read_case(const std::filesystem::path& file, const std::vector<std::string>& overrides = {});

// Largest stable time step h_min / c_max of a case (s), and the material
// that sets it.
struct StableStep {
  double dt;
  std::string material;
};
StableStep stable_time_step(const Case& c);

}  // namespace flowmpm
