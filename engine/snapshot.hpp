// A flat, dimension-independent copy of chosen particle fields at one output
// step, handed from the engine to the writers (HDF5, XDMF). Rows are in
// particle id order (the order particles were made at set-up), so a row is
// the same particle at every step, whatever the sorts did in between.
// Vectors are padded to 3 components (x, y, z; missing axes are 0).
// Symmetric tensors have 6 components in the order xx, yy, zz, xy, yz, xz:
// VTK's order, under which ParaView labels 6-component arrays (the engine
// keeps Voigt order xx, yy, zz, yz, xz, xy inside). SI units.
#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace flowmpm {

// A particle field the engine can write (output.fields).
struct OutputField {
  const char* name;
  int components;     // per particle: 1, 3 (vector) or 6 (symmetric tensor)
  const char* units;  // nullptr: none (an index)
  bool integer;       // stored as 32-bit integers, not doubles
};

// The built-in fields, in the order they are written; the models' state
// variables (materials/state_variable.hpp) follow them.
inline constexpr OutputField builtin_output_fields[] = {
    {"id", 1, nullptr, true},  // the particle's id: its row
    {"position", 3, "m", false},
    {"displacement", 3, "m", false},  // position - initial position
    {"velocity", 3, "m/s", false},
    {"stress", 6, "Pa", false},
    {"strain", 6, "-", false},
    {"von_mises", 1, "Pa", false},  // sqrt(3/2 s : s), s the stress deviator
    {"pressure", 1, "Pa", false},   // -tr(sigma) / 3, positive in compression
    {"volume", 1, "m^3", false},
    {"mass", 1, "kg", false},
    {"material", 1, nullptr, true},  // index into the case's materials
    // Only in scenes that conduct heat / diffuse solvent (tasks/transport.hpp).
    {"temperature", 1, "K", false},
    {"concentration", 1, "-", false},  // weight fraction
    {"initial_position", 3, "m", false},
};

// The fields written when a case does not choose: everything but what can be
// derived from them (von_mises, pressure, initial_position) and the models'
// state variables.
inline std::vector<std::string> default_output_fields() {
  return {"id", "position", "displacement", "velocity", "stress", "strain", "volume", "mass", "material"};
}

// Voigt slot of tensor output component k (xx, yy, zz, xy, yz, xz).
inline constexpr std::array<int, 6> tensor_output_order = {0, 1, 2, 5, 3, 4};
inline constexpr const char* tensor_output_components = "xx yy zz xy yz xz";
// The same names for a stress state (stress_state_name): axisymmetric, x is
// the radius r, y the axial z and z the hoop direction theta.
inline const char* tensor_output_components_of(std::string_view stress_state) {
  return stress_state == "axisymmetric" ? "rr zz tt rz zt rt" : tensor_output_components;
}
inline const char* vector_output_components_of(std::string_view stress_state) {
  return stress_state == "axisymmetric" ? "r z (theta, 0)" : "x y z (padded with 0 below 3D)";
}

struct SnapshotField {
  OutputField field;
  std::vector<double> real;           // count * components values (real fields)
  std::vector<std::int32_t> integer;  // count values (integer fields)
};

// All particles of all batches, in id order.
struct ParticleSnapshot {
  std::int64_t step = 0;
  double time = 0.0;  // s
  std::size_t count = 0;
  std::vector<SnapshotField> fields;

  const SnapshotField* find(std::string_view name) const {
    for (const SnapshotField& f : fields)
      if (std::string_view(f.field.name) == name) return &f;
    return nullptr;
  }
};

}  // namespace flowmpm
