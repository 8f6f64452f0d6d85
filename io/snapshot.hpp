// A flat, dimension-independent copy of the particle fields at one output
// step, handed from the engine to the writers (HDF5, XDMF, CSV).
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace flowmpm {

// Which particle fields a case asks to be written.
struct OutputFields {
  bool position = true;
  bool velocity = true;
  bool stress = true;
  bool strain = true;
  bool volume = true;
  bool mass = true;
  bool material = true;
};

// All particles of all batches, concatenated. Vectors and tensors are padded
// to 3D so that every file opens the same way in ParaView:
// position and velocity hold n*3 values (x, y, z; missing axes are 0),
// stress and strain n*6 in Voigt order (xx, yy, zz, yz, xz, xy), tensor
// (not engineering) shear components. SI units: m, m/s, Pa, m^3, kg.
struct ParticleSnapshot {
  std::int64_t step = 0;
  double time = 0.0;  // s
  std::size_t count = 0;
  std::vector<double> position, velocity, stress, strain, volume, mass;
  std::vector<std::int32_t> material;  // index into the case's material list
};

}  // namespace flowmpm
