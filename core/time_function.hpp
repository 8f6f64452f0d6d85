// A piecewise-linear function of time through points (t_k, f_k), held
// constant before the first and after the last point; one point is a
// constant.
#pragma once
#include <utility>
#include <vector>

namespace flowmpm {

struct TimeFunction {
  std::vector<std::pair<double, double>> points;  // (t, value), t increasing

  double operator()(double t) const {
    if (t <= points.front().first) return points.front().second;
    for (std::size_t k = 1; k < points.size(); ++k) {
      const auto [t1, f1] = points[k];
      if (t <= t1) {
        const auto [t0, f0] = points[k - 1];
        return f0 + (f1 - f0) * (t - t0) / (t1 - t0);
      }
    }
    return points.back().second;
  }
};

}  // namespace flowmpm
