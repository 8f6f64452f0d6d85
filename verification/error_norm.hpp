// Mass-weighted RMS of an error over particles and sample times:
//   e = sqrt( sum_t sum_p m_p |err_p(t)|^2 / sum_t sum_p m_p ) / scale,
// with `scale` the amplitude of the exact solution, so e is relative.
#pragma once
#include <cmath>
#include <limits>

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

}  // namespace flowmpm
