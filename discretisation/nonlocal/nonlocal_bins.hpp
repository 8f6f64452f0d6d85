// The particles binned by their initial positions (x0) in cubes of the
// nonlocal cut-off radius, so that every particle within that radius of a
// point lies in the 3^D bins around the point's own
// (discretisation/nonlocal/nonlocal_average.hpp). Entries are (batch, particle
// index): a sort permutes the particles, so the bins are rebuilt after one
// (`sorts` records which arrangement they index).
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include "core/vec.hpp"
#include "discretisation/grid/particles.hpp"

namespace flowmpm {

// A particle within the cut-off of another, and its weight alpha (-).
struct NonlocalNeighbour {
  int batch;
  std::uint32_t particle;
  double alpha;
};

template <int D>
struct NonlocalBins {
  Vec<D> lo = Vec<D>::Zero();  // corner of the first bin (m)
  double size = 1.0;           // bin edge, the cut-off radius (m)
  Index<D> count{};            // bins per axis
  std::vector<std::uint32_t> start;                    // per bin, into `entries`
  std::vector<std::pair<int, std::uint32_t>> entries;  // (batch, particle)
  std::int64_t sorts = -1;     // the particle arrangement indexed

  NonlocalBins() = default;
  NonlocalBins(const std::vector<ParticleBatch<D>>& batches, double cutoff, std::int64_t sorts_)
      : size(cutoff), sorts(sorts_) {
    Vec<D> hi;
    lo.setConstant(std::numeric_limits<double>::infinity());
    hi.setConstant(-std::numeric_limits<double>::infinity());
    for (const auto& b : batches)
      for (const auto& x : b.x0) lo = lo.cwiseMin(x), hi = hi.cwiseMax(x);
    std::size_t bins = 1;
    for (int d = 0; d < D; ++d) {
      count[d] = std::max(1, static_cast<int>(std::floor((hi[d] - lo[d]) / size)) + 1);
      bins *= static_cast<std::size_t>(count[d]);
    }
    // A counting sort by bin, in batch and particle order.
    start.assign(bins + 1, 0);
    for (const auto& b : batches)
      for (const auto& x : b.x0) ++start[bin_of(x) + 1];
    for (std::size_t i = 0; i < bins; ++i) start[i + 1] += start[i];
    entries.resize(start.back());
    std::vector<std::uint32_t> next(start.begin(), start.end() - 1);
    for (int bi = 0; bi < static_cast<int>(batches.size()); ++bi) {
      const auto& b = batches[bi];
      for (std::uint32_t p = 0; p < b.x0.size(); ++p) entries[next[bin_of(b.x0[p])]++] = {bi, p};
    }
  }

  // f(batch, particle) for every particle in the bins around x, in a fixed order.
  template <class F>
  void for_each_near(const Vec<D>& x, F&& f) const {
    const Index<D> c = coords(x);
    Index<D> first, last;
    for (int d = 0; d < D; ++d) first[d] = std::max(0, c[d] - 1), last[d] = std::min(count[d] - 1, c[d] + 1);
    Index<D> k = first;
    while (true) {
      const std::size_t bin = index(k);
      for (std::uint32_t e = start[bin]; e < start[bin + 1]; ++e) f(entries[e].first, entries[e].second);
      int d = 0;
      while (d < D && ++k[d] > last[d]) k[d] = first[d], ++d;
      if (d == D) break;
    }
  }

 private:
  Index<D> coords(const Vec<D>& x) const {
    Index<D> c;
    for (int d = 0; d < D; ++d)
      c[d] = std::clamp(static_cast<int>(std::floor((x[d] - lo[d]) / size)), 0, count[d] - 1);
    return c;
  }
  std::size_t index(const Index<D>& c) const {
    std::size_t i = 0;
    for (int d = D - 1; d >= 0; --d) i = i * static_cast<std::size_t>(count[d]) + static_cast<std::size_t>(c[d]);
    return i;
  }
  std::size_t bin_of(const Vec<D>& x) const { return index(coords(x)); }
};

}  // namespace flowmpm
