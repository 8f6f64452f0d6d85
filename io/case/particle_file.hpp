// Reads particles made elsewhere from a CSV or an HDF5 file (by the file's
// extension: .csv, .h5 or .hdf5), docs/guide/bodies.md:
//   CSV: a header line naming the columns, then one particle per line,
//        comma-separated; lines starting with # and blank lines skipped.
//        Columns: x (and y, z up to the dimension) in m, volume in m^3
//        (m^2 per unit thickness in 2D, m per unit cross-section in 1D);
//        optional material_axes_z (2D; also _y and _x in 3D) in degrees;
//        optional stress_xx, stress_yy, stress_zz, stress_yz, stress_xz,
//        stress_xy in Pa (all six).
//   HDF5: datasets position (n x dimension), volume (n), optional
//        material_axes (n x 1 in 2D, n x 3 in 3D, degrees about z, y, x)
//        and stress (n x 6, Pa), all doubles.
// Missing or unknown columns, a value that is not a finite number, a
// volume <= 0 or an empty file throw CaseError naming the file (and the
// line and column in a CSV file).
#pragma once
#include <filesystem>

#include "discretisation/grid/particle_list.hpp"

namespace flowmpm {

ParticleList read_particle_file(const std::filesystem::path& file, int dimension);

}  // namespace flowmpm
