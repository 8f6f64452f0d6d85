// Transient conduction or diffusion across a slab 0 <= X <= L, initially at
// u0 throughout, both faces held at u_b(t) ([Carslaw 1959] 3.3;
// [Crank 1975] ch. 4). For faces stepped to u_b at t = 0:
//   u(X, t) = u0 + (u_b - u0) U(X, t),
//   U(X, t) = 1 - sum_{n odd} c_n sin(k_n X) exp(-lambda_n t),
//   c_n = 4 / (n pi), k_n = n pi / L, lambda_n = kappa k_n^2,
// kappa the diffusivity along X (k / (rho C) for heat, D for solvent). For a
// piecewise-linear u_b(t) (a ramp, so that the mechanics it drives stays
// quasi-static), Duhamel's superposition of steps: a segment of slope s
// over [a, b] adds s (b - a) - s sum c_n sin(k_n X)
// (exp(-lambda_n (t - b)) - exp(-lambda_n (t - a))) / lambda_n.
#pragma once
#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/time_function.hpp"

namespace flowmpm {

struct SlabSeries {
  double length = 0.0;    // L (m)
  double kappa = 0.0;     // m^2/s
  double initial = 0.0;   // u0
  TimeFunction boundary;  // u_b(t), piecewise linear

  double operator()(double X, double t) const {
    if (t <= 0.0) return X > 0.0 && X < length ? initial : boundary(0.0);
    const double pi = std::numbers::pi;
    // The step at t = 0: terms until exp(-lambda_n t) < e^-40.
    double u = initial;
    const double jump = boundary(0.0) - initial;
    if (jump != 0.0) {
      const int last = static_cast<int>(std::ceil(length / pi * std::sqrt(40.0 / (kappa * t))));
      double sum = 0.0;
      for (int n = 1; n <= last; n += 2) {
        const double k = n * pi / length;
        sum += 4.0 / (n * pi) * std::sin(k * X) * std::exp(-kappa * k * k * t);
      }
      u += jump * (1.0 - sum);
    }
    // The ramps: their series fall as n^-3 (the segment that reaches t has
    // no exponential decay), 4001 terms leave 1e-8 of the ramp's rise.
    const auto& points = boundary.points;
    for (std::size_t i = 0; i + 1 < points.size(); ++i) {
      const double a = std::max(points[i].first, 0.0), b = std::min(points[i + 1].first, t);
      if (b <= a) continue;
      const double slope = (points[i + 1].second - points[i].second) / (points[i + 1].first - points[i].first);
      double sum = 0.0;
      for (int n = 1; n <= 4001; n += 2) {
        const double k = n * pi / length, lambda = kappa * k * k;
        sum += 4.0 / (n * pi) * std::sin(k * X) * (std::exp(-lambda * (t - b)) - std::exp(-lambda * (t - a))) / lambda;
      }
      u += slope * ((b - a) - sum);
    }
    return u;
  }
};

}  // namespace flowmpm
