// Bodies may not share space: a particle of one body inside another would
// double the mass there. A body that names others in `wins_over` takes
// the space it shares with them: their particles inside it are removed.
// Any other overlap is a CaseError naming both bodies and where they
// overlap. A body's space is its shape, less the space of the bodies that
// win over it; for particles from a file, the union of the particles'
// domains (cubes of side V^(1/D) about them).
#pragma once
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <unordered_map>
#include <vector>

#include "core/errors.hpp"
#include "discretisation/system_spec.hpp"

namespace flowmpm {

// Whether a point lies in a body's space.
class BodySpace {
 public:
  BodySpace(const BodySpec& body, const ParticleList& particles, int dimension) : dimension_(dimension) {
    if (!body.particles) {
      shape_ = &body.shape;
      return;
    }
    centres_ = particles.position;
    for (const double volume : particles.volume) half_.push_back(0.5 * std::pow(volume, 1.0 / dimension));
    cell_ = 2.0 * *std::max_element(half_.begin(), half_.end());
    for (std::size_t p = 0; p < centres_.size(); ++p) cells_[key(cell_index(centres_[p]))].push_back(p);
  }

  void exclude(const BodySpace* winner) { excluded_.push_back(winner); }

  bool contains(const Vec3& x) const {
    if (!contains_own(x)) return false;
    return std::none_of(excluded_.begin(), excluded_.end(), [&](const BodySpace* w) { return w->contains(x); });
  }

 private:
  bool contains_own(const Vec3& x) const {
    if (shape_) return shape_->contains(x);
    const std::array<long, 3> c = cell_index(x);
    std::array<long, 3> n{};
    const int reach[3] = {1, dimension_ > 1 ? 1 : 0, dimension_ > 2 ? 1 : 0};
    for (n[2] = c[2] - reach[2]; n[2] <= c[2] + reach[2]; ++n[2])
      for (n[1] = c[1] - reach[1]; n[1] <= c[1] + reach[1]; ++n[1])
        for (n[0] = c[0] - reach[0]; n[0] <= c[0] + reach[0]; ++n[0]) {
          const auto it = cells_.find(key(n));
          if (it == cells_.end()) continue;
          for (const std::size_t p : it->second) {
            bool inside = true;
            for (int d = 0; d < dimension_; ++d) inside = inside && std::abs(x[d] - centres_[p][d]) <= half_[p];
            if (inside) return true;
          }
        }
    return false;
  }
  std::array<long, 3> cell_index(const Vec3& x) const {
    std::array<long, 3> c{};
    for (int d = 0; d < dimension_; ++d) c[d] = static_cast<long>(std::floor(x[d] / cell_));
    return c;
  }
  static long long key(const std::array<long, 3>& c) {
    return (static_cast<long long>(c[0]) * 2097152 + c[1]) * 2097152 + c[2];
  }

  int dimension_;
  const BodyShape* shape_ = nullptr;
  std::vector<Vec3> centres_;  // particles from a file: their centres (m)
  std::vector<double> half_;   // and half their side (m)
  double cell_ = 0.0;          // the largest particle's side (m)
  std::unordered_map<long long, std::vector<std::size_t>> cells_;
  std::vector<const BodySpace*> excluded_;
};

// Removes the particles of the bodies that others win over, then fails on
// any remaining overlap. `particles` are the bodies' particles, by body.
inline void resolve_overlaps(const SystemSpec& spec, std::vector<ParticleList>& particles) {
  const std::size_t n = spec.bodies.size();
  std::vector<BodySpace> spaces;
  for (std::size_t i = 0; i < n; ++i) spaces.emplace_back(spec.bodies[i], particles[i], spec.dimension);
  for (std::size_t w = 0; w < n; ++w) {
    for (const int loser : spec.bodies[w].wins_over) spaces[loser].exclude(&spaces[w]);
  }
  // The particles each winner removes, from the bodies it wins over.
  for (std::size_t w = 0; w < n; ++w) {
    for (const int loser : spec.bodies[w].wins_over) {
      ParticleList& list = particles[loser];
      std::vector<std::size_t> keep;
      for (std::size_t p = 0; p < list.size(); ++p)
        if (!spaces[w].contains(list.position[p])) keep.push_back(p);
      auto select = [&](auto& column) {
        if (column.empty()) return;
        std::remove_reference_t<decltype(column)> kept;
        for (const std::size_t p : keep) kept.push_back(column[p]);
        column.swap(kept);
      };
      select(list.position);
      select(list.volume);
      select(list.material_axes);
      select(list.stress);
      if (list.size() == 0) {
        throw CaseError(spec.bodies[loser].where + ": no particles left: body \"" + spec.bodies[w].name +
                        "\" wins over all of them (wins_over)");
      }
    }
  }
  for (std::size_t a = 0; a < n; ++a) {
    for (std::size_t b = 0; b < n; ++b) {
      if (a == b) continue;
      std::size_t count = 0;
      Vec3 lo{}, hi{};
      lo.fill(std::numeric_limits<double>::infinity());
      hi.fill(-std::numeric_limits<double>::infinity());
      for (const Vec3& x : particles[b].position) {
        if (!spaces[a].contains(x)) continue;
        ++count;
        for (int d = 0; d < 3; ++d) lo[d] = std::min(lo[d], x[d]), hi[d] = std::max(hi[d], x[d]);
      }
      if (count == 0) continue;
      std::ostringstream s;
      s.precision(6);
      auto point = [&](const Vec3& x) {
        s << "(";
        for (int d = 0; d < spec.dimension; ++d) s << (d ? ", " : "") << x[d];
        s << ")";
      };
      s << spec.bodies[b].where << ": overlaps body \"" << spec.bodies[a].name << "\": " << count
        << " of its particles lie inside it, between ";
      point(lo);
      s << " and ";
      point(hi);
      s << " m; expected bodies apart, or the body that takes the shared space naming the other in wins_over "
           "(e.g. wins_over = [\""
        << spec.bodies[b].name << "\"] in body \"" << spec.bodies[a].name << "\")";
      throw CaseError(s.str());
    }
  }
}

}  // namespace flowmpm
