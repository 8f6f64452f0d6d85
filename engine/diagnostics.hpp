// What the time series and the summary report of a model's state: kinetic
// and strain energy, and per body the volume-weighted mean stress and strain.
// Serial, in particle order, so the numbers do not depend on the thread count.
#pragma once
#include "engine/model.hpp"
#include "io/timeseries_csv.hpp"

namespace flowmpm {

// `body_count`: the case's bodies (one batch each).
template <int D, class Shape>
TimeseriesRow diagnostics(const Model<D, Shape>& model, std::size_t body_count) {
  TimeseriesRow row;
  row.step = model.step;
  row.time = model.t;
  row.bodies.resize(body_count);
  std::vector<double> body_volume(body_count, 0.0);
  for (const auto& b : model.batches) {
    BodyMeans& means = row.bodies[b.body];
    for (std::size_t p = 0; p < b.size(); ++p) {
      row.kinetic_energy += 0.5 * b.mass[p] * b.v[p].squaredNorm();
      // Elastic strain energy density sigma : eps / 2 (small strain).
      row.strain_energy += 0.5 * b.volume[p] * double_contraction(b.stress[p], b.strain[p]);
      for (int i = 0; i < 6; ++i) {
        means.stress[i] += b.volume[p] * b.stress[p][i];
        means.strain[i] += b.volume[p] * b.strain[p][i];
      }
      body_volume[b.body] += b.volume[p];
    }
  }
  for (std::size_t i = 0; i < body_count; ++i) {
    for (int k = 0; k < 6; ++k) {
      row.bodies[i].stress[k] /= body_volume[i];
      row.bodies[i].strain[k] /= body_volume[i];
    }
  }
  return row;
}

}  // namespace flowmpm
