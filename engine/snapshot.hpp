// A flat, dimension-independent copy of chosen particle fields at one output
// step, handed from the engine to the writers (HDF5, XDMF). Vectors are
// padded to 3 components (x, y, z; missing axes are 0) and tensors are 6 in
// Voigt order (xx, yy, zz, yz, xz, xy; tensor shear), so that every file
// opens the same way in ParaView. SI units.
#pragma once
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace flowmpm {

// A particle field the engine can write (output.fields).
struct OutputField {
  const char* name;
  int components;     // per particle: 1, 3 (vector) or 6 (Voigt tensor)
  const char* units;  // nullptr: none (an index)
  bool integer;       // stored as 32-bit integers, not doubles
};

// Every field that can be written, in the order they are written.
inline constexpr OutputField output_fields[] = {
    {"position", 3, "m", false}, {"velocity", 3, "m/s", false}, {"stress", 6, "Pa", false},
    {"strain", 6, "-", false},   {"volume", 1, "m^3", false},   {"mass", 1, "kg", false},
    {"material", 1, nullptr, true},  // index into the case's materials
    // Only in scenes that conduct heat / diffuse solvent (tasks/transport.hpp).
    {"temperature", 1, "K", false},  {"concentration", 1, "-", false},  // weight fraction
};

inline std::vector<std::string> output_field_names() {
  std::vector<std::string> names;
  for (const OutputField& f : output_fields) names.emplace_back(f.name);
  return names;
}

struct SnapshotField {
  OutputField field;
  std::vector<double> real;           // count * components values (real fields)
  std::vector<std::int32_t> integer;  // count values (integer fields)
};

// All particles of all batches, concatenated.
struct ParticleSnapshot {
  std::int64_t step = 0;
  double time = 0.0;  // s
  std::size_t count = 0;
  std::vector<SnapshotField> fields;  // in the order of output_fields

  const SnapshotField* find(std::string_view name) const {
    for (const SnapshotField& f : fields)
      if (std::string_view(f.field.name) == name) return &f;
    return nullptr;
  }
};

}  // namespace flowmpm
