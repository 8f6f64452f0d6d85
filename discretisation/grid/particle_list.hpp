// Particles given one by one, for geometry made elsewhere (io reads them
// from a CSV or HDF5 file, docs/guide/bodies.md): positions,
// volumes and, optionally, material axes and initial stress per particle.
#pragma once
#include <string>
#include <vector>

#include "core/vec.hpp"
#include "core/voigt.hpp"

namespace flowmpm {

struct ParticleList {
  std::string source;               // the file, for messages
  std::vector<Vec3> position;       // m; 0 on the axes the analysis does not have
  std::vector<double> volume;       // m^3 (per unit thickness in 2D, per unit cross-section in 1D)
  std::vector<Vec3> material_axes;  // degrees about z, y, x (R = Rz Ry Rx); empty: the body's
  std::vector<Voigt> stress;        // Pa, Voigt order; empty: the body's initial stress

  std::size_t size() const { return position.size(); }
};

}  // namespace flowmpm
