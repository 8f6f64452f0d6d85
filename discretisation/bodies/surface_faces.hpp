// The surface of a body filled from a shape, on its lattice: a particle's
// face towards +-axis is on the surface when the lattice point beyond it is
// outside the lattice or outside the shape. A traction or a pressure acts
// on these faces (a staircase on a curved surface: the force on a surface
// is then its load times its projected area, to the lattice resolution).
#pragma once
#include <optional>
#include <vector>

#include "discretisation/loads/external_loads.hpp"
#include "discretisation/bodies/lattice.hpp"
#include "discretisation/grid/particles.hpp"

namespace flowmpm {

// The surface faces of `batch`'s particles whose centres lie in `region`
// (all without one); only faces with outward normal sign e_axis when
// `face` is given as (axis, sign).
template <int D>
std::vector<LoadedFace<D>> surface_faces(const ParticleBatch<D>& batch, const BodyShape& shape, const Lattice& lattice,
                                         const std::optional<BodyShape>& region,
                                         std::optional<std::pair<int, double>> face) {
  std::vector<LoadedFace<D>> faces;
  for (std::size_t p = 0; p < batch.size(); ++p) {
    Vec3 x{};
    for (int d = 0; d < D; ++d) x[d] = batch.x[p][d];
    if (region && !region->contains(x)) continue;
    const std::array<int, 3> i = lattice.nearest(x);
    for (int axis = 0; axis < D; ++axis) {
      for (const double sign : {-1.0, 1.0}) {
        if (face && (face->first != axis || face->second != sign)) continue;
        std::array<int, 3> beyond = i;
        beyond[axis] += static_cast<int>(sign);
        const bool outside = beyond[axis] < 0 || beyond[axis] >= lattice.count[axis] ||
                             !shape.contains(lattice.point(beyond));
        if (!outside) continue;
        LoadedFace<D> f;
        f.particle = static_cast<std::uint32_t>(p);
        f.offset[axis] = 0.5 * sign * lattice.spacing[axis];
        f.axis = axis;
        f.sign = sign;
        f.area = lattice.cell_volume() / lattice.spacing[axis];
        faces.push_back(f);
      }
    }
  }
  return faces;
}

}  // namespace flowmpm
