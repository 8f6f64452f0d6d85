// Mass-weighted RMS of an error over particles and sample times:
//   e = sqrt( sum_t sum_p m_p |err_p(t)|^2 / sum_t sum_p m_p ) / scale,
// with `scale` the amplitude of the exact solution, so e is relative.
#pragma once
#include <cmath>
#include <limits>

#include "engine/model.hpp"
#include "io/case_reader.hpp"
#include "materials/linear_elastic.hpp"

namespace flowmpm {

struct RmsError {
  double sum_squares = 0.0, sum_weights = 0.0;
  void add(double weight, double error) {
    sum_squares += weight * error * error;
    sum_weights += weight;
  }
  // NaN before the first sample.
  double relative_to(double scale) const {
    if (sum_weights == 0.0) return std::numeric_limits<double>::quiet_NaN();
    return std::sqrt(sum_squares / sum_weights) / scale;
  }
};

// The linear elastic parameters of the first body: the analytical solutions
// are those of linear elasticity.
template <int D, class Shape>
const LinearElastic& elastic_material(const Model<D, Shape>& model, const char* reference) {
  const LinearElastic* m = std::get_if<LinearElastic>(&model.materials[model.batches.at(0).material]);
  if (!m) throw CaseError(std::string("reference \"") + reference + "\" needs a linear_elastic body");
  return *m;
}

}  // namespace flowmpm
