// Transient radial conduction or diffusion in a long solid cylinder
// 0 <= r <= b, initially at u0 throughout, its surface held at u_b from
// t = 0 ([Carslaw 1959] 7.4; [Crank 1975] 5.3.2):
//   u(r, t) = u_b + (u0 - u_b) sum_n 2 / (j_n J1(j_n)) J0(j_n r / b) exp(-j_n^2 kappa t / b^2),
// j_n the positive zeros of J0, kappa the diffusivity along r (k / (rho C)
// for heat, D for solvent). The zeros come from McMahon's expansion
// refined by Newton's method on std::cyl_bessel_j (C++17 <cmath>); the
// terms run until j_n^2 kappa t / b^2 > 40 (e^-40 of the step left).
#pragma once
#include <cmath>
#include <cstddef>
#include <numbers>
#include <vector>

namespace flowmpm {

// The n-th positive zero of J0 (n >= 1): 2.404825557695773, 5.520078110286311, ...
inline double bessel_j0_zero(int n) {
  const double beta = (n - 0.25) * std::numbers::pi;
  double x = beta + 1.0 / (8.0 * beta) - 31.0 / (384.0 * beta * beta * beta);
  for (int k = 0; k < 8; ++k) {
    const double step = std::cyl_bessel_j(0.0, x) / std::cyl_bessel_j(1.0, x);  // J0' = -J1
    x += step;
    if (std::abs(step) < 1e-15 * x) break;
  }
  return x;
}

struct CylinderSeries {
  double radius = 0.0;    // b (m)
  double kappa = 0.0;     // m^2/s
  double initial = 0.0;   // u0
  double boundary = 0.0;  // u_b

  // u(r, t); grows the table of zeros as the time needs (not thread safe).
  double operator()(double r, double t) {
    if (t <= 0.0) return r < radius ? initial : boundary;
    const double tau = kappa * t / (radius * radius);
    const double largest = std::sqrt(40.0 / tau);
    while (zeros_.empty() || zeros_.back() < largest) {
      const double j = bessel_j0_zero(static_cast<int>(zeros_.size()) + 1);
      zeros_.push_back(j);
      weights_.push_back(2.0 / (j * std::cyl_bessel_j(1.0, j)));
    }
    double sum = 0.0;
    for (std::size_t n = 0; n < zeros_.size(); ++n) {
      const double j = zeros_[n];
      if (j > largest) break;
      sum += weights_[n] * std::cyl_bessel_j(0.0, j * r / radius) * std::exp(-j * j * tau);
    }
    return boundary + (initial - boundary) * sum;
  }

 private:
  std::vector<double> zeros_, weights_;  // j_n, 2 / (j_n J1(j_n))
};

}  // namespace flowmpm
