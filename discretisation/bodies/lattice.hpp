// The regular lattice a body's shape is filled on: points at the given
// spacing per axis, as many whole spacings as fit in the shape's bounds,
// centred in them; a body's particles are the points inside its shape
// (centres inside), each with the lattice cell as its volume. For a box
// this is the lattice of a box body, point for point and bit for bit.
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "discretisation/bodies/body_shape.hpp"

namespace flowmpm {

struct Lattice {
  int dimension = 3;
  Vec3 corner{};   // bounds.min + margin: the corner of the first lattice cell (m)
  Vec3 spacing{};  // m
  std::array<int, 3> count{1, 1, 1};

  Lattice(const BoxShape& bounds, const Vec3& spacing_, int dimension_) : dimension(dimension_), spacing(spacing_) {
    for (int d = 0; d < dimension; ++d) {
      const double extent = bounds.max[d] - bounds.min[d];
      count[d] = std::max(1, static_cast<int>(std::floor(extent / spacing[d] + 1e-9)));
      const double margin = 0.5 * (extent - count[d] * spacing[d]);
      corner[d] = bounds.min[d] + margin;
    }
  }

  std::size_t size() const {
    std::size_t n = 1;
    for (int d = 0; d < dimension; ++d) n *= static_cast<std::size_t>(count[d]);
    return n;
  }

  // Point i along each axis; an index outside [0, count) gives a point
  // outside the bounds.
  Vec3 point(const std::array<int, 3>& i) const {
    Vec3 x{};
    for (int d = 0; d < dimension; ++d) x[d] = corner[d] + (i[d] + 0.5) * spacing[d];
    return x;
  }
  // The index of lattice point p, x fastest (the order of fill()).
  std::array<int, 3> index(std::size_t p) const {
    std::array<int, 3> i{};
    for (int d = 0; d < dimension; ++d) {
      i[d] = static_cast<int>(p % static_cast<std::size_t>(count[d]));
      p /= static_cast<std::size_t>(count[d]);
    }
    return i;
  }
  // The index of the lattice point nearest x.
  std::array<int, 3> nearest(const Vec3& x) const {
    std::array<int, 3> i{};
    for (int d = 0; d < dimension; ++d) i[d] = static_cast<int>(std::lround((x[d] - corner[d]) / spacing[d] - 0.5));
    return i;
  }
  // The volume of a lattice cell (m^3; per unit thickness in 2D, per unit
  // cross-section in 1D).
  double cell_volume() const {
    double v = 1.0;
    for (int d = 0; d < dimension; ++d) v *= spacing[d];
    return v;
  }
};

// The lattice points inside `shape`, in lattice order (x fastest), the
// indices counted up rather than divided out of each point's number
// (index(): three 64-bit divisions per point).
inline std::vector<Vec3> fill(const BodyShape& shape, const Lattice& lattice) {
  std::vector<Vec3> points;
  points.reserve(lattice.size());
  std::array<int, 3> i{};  // count is 1 along the axes the analysis does not have
  for (i[2] = 0; i[2] < lattice.count[2]; ++i[2])
    for (i[1] = 0; i[1] < lattice.count[1]; ++i[1])
      for (i[0] = 0; i[0] < lattice.count[0]; ++i[0]) {
        const Vec3 x = lattice.point(i);
        if (shape.contains(x)) points.push_back(x);
      }
  return points;
}

}  // namespace flowmpm
