#include "materials/orthotropic.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include <Eigen/Eigenvalues>
#include <Eigen/LU>

#include "core/number_text.hpp"
#include "core/parameter_table.hpp"
#include "materials/parameter_reading.hpp"

namespace flowmpm {

namespace {

// The largest eigenvalue of the acoustic tensor of an orthotropic stiffness
// for the propagation direction (sin th cos ph, sin th sin ph, cos th):
//   Gamma_11 = C11 n1^2 + C66 n2^2 + C55 n3^2, Gamma_12 = (C12 + C66) n1 n2, ...
// (C44 = Gyz, C55 = Gxz, C66 = Gxy in engineering Voigt form).
double acoustic_max(const Eigen::Matrix3d& C, double Gyz, double Gxz, double Gxy, double th,
                    double ph) {
  const double n1 = std::sin(th) * std::cos(ph), n2 = std::sin(th) * std::sin(ph), n3 = std::cos(th);
  Eigen::Matrix3d G;
  G(0, 0) = C(0, 0) * n1 * n1 + Gxy * n2 * n2 + Gxz * n3 * n3;
  G(1, 1) = Gxy * n1 * n1 + C(1, 1) * n2 * n2 + Gyz * n3 * n3;
  G(2, 2) = Gxz * n1 * n1 + Gyz * n2 * n2 + C(2, 2) * n3 * n3;
  G(0, 1) = G(1, 0) = (C(0, 1) + Gxy) * n1 * n2;
  G(0, 2) = G(2, 0) = (C(0, 2) + Gxz) * n1 * n3;
  G(1, 2) = G(2, 1) = (C(1, 2) + Gyz) * n2 * n3;
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(G, Eigen::EigenvaluesOnly);
  return eig.eigenvalues()[2];
}

// max over directions of lambda_max(Gamma): the octant suffices (the
// material's symmetry planes), searched on a 1 degree grid, then on grids
// ten times finer around the best point down to 1e-7 rad.
double max_acoustic_eigenvalue(const Eigen::Matrix3d& C, double Gyz, double Gxz, double Gxy) {
  const double half_pi = 0.5 * std::numbers::pi;
  double step = std::numbers::pi / 180.0, best = 0.0, best_th = 0.0, best_ph = 0.0;
  for (int i = 0; i <= 90; ++i) {
    for (int j = 0; j <= 90; ++j) {
      const double v = acoustic_max(C, Gyz, Gxz, Gxy, i * step, j * step);
      if (v > best) best = v, best_th = i * step, best_ph = j * step;
    }
  }
  while (step > 1e-7) {
    const double th0 = best_th, ph0 = best_ph;
    step /= 10.0;
    for (int i = -10; i <= 10; ++i) {
      for (int j = -10; j <= 10; ++j) {
        const double th = std::clamp(th0 + i * step, 0.0, half_pi);
        const double ph = std::clamp(ph0 + j * step, 0.0, half_pi);
        const double v = acoustic_max(C, Gyz, Gxz, Gxy, th, ph);
        if (v > best) best = v, best_th = th, best_ph = ph;
      }
    }
  }
  return best;
}

// nu_ij from whichever of (nu_ij, nu_ji) is given, by nu_ij / E_i = nu_ji / E_j.
double poisson_pair(ParameterTable& t, const char* ij, const char* ji, double Ei, double Ej) {
  const std::string pair = std::string(ij) + " or " + ji;
  if (t.has(ij) && t.has(ji)) {
    t.fail(ji, std::string("only one of ") + ij + " and " + ji +
                   " (the other follows from the reciprocity nu_ij / E_i = nu_ji / E_j)");
  }
  if (!t.has(ij) && !t.has(ji)) t.fail(ij, "one Poisson ratio of the pair, " + pair);
  return t.has(ij) ? t.number(ij) : t.number(ji) * Ei / Ej;
}

}  // namespace

Eigen::Matrix3d Orthotropic::compliance(const Parameters& p) {
  // S_ij = -nu_ij / E_i = -nu_ji / E_j (reciprocity makes S symmetric).
  Eigen::Matrix3d S;
  S << 1.0 / p.Ex, -p.nuxy / p.Ex, -p.nuxz / p.Ex,
       -p.nuxy / p.Ex, 1.0 / p.Ey, -p.nuyz / p.Ey,
       -p.nuxz / p.Ex, -p.nuyz / p.Ey, 1.0 / p.Ez;
  return S;
}

Orthotropic::Orthotropic(const Parameters& p) : parameters(p), S_n(compliance(p)), C_n(S_n.inverse()) {
  c_max = std::sqrt(max_acoustic_eigenvalue(C_n, p.Gyz, p.Gxz, p.Gxy) / p.density);
}

void Orthotropic::read_transport_and_expansion(ParameterTable& t, Parameters& p, const AxisLayout& layout) {
  p.transport = TransportProperties::read(t, layout);
  p.expansion = Expansion::read(t, layout, p.transport);
}

Orthotropic Orthotropic::read(ParameterTable& t) {
  Parameters p;
  p.density = t.number("density");
  t.require(p.density > 0.0, "density", "a positive density in kg/m^3");
  auto modulus = [&](const char* key, const char* what) {
    const double v = t.number(key);
    t.require(v > 0.0, key, std::string("a positive ") + what + " in Pa");
    return v;
  };
  p.Ex = modulus("Ex", "Young's modulus");
  p.Ey = modulus("Ey", "Young's modulus");
  p.Ez = modulus("Ez", "Young's modulus");
  p.Gxy = modulus("Gxy", "shear modulus");
  p.Gxz = modulus("Gxz", "shear modulus");
  p.Gyz = modulus("Gyz", "shear modulus");
  p.nuxy = poisson_pair(t, "nuxy", "nuyx", p.Ex, p.Ey);
  p.nuxz = poisson_pair(t, "nuxz", "nuzx", p.Ex, p.Ez);
  p.nuyz = poisson_pair(t, "nuyz", "nuzy", p.Ey, p.Ez);

  // Positive definite compliance (Sylvester): nu_ij nu_ji < 1 for each pair
  // and 1 - nu_xy nu_yx - nu_yz nu_zy - nu_xz nu_zx - 2 nu_yx nu_zy nu_xz > 0.
  const double nuyx = p.nuxy * p.Ey / p.Ex, nuzx = p.nuxz * p.Ez / p.Ex, nuzy = p.nuyz * p.Ez / p.Ey;
  const struct {
    const char *ij, *ji;
    double product;
  } pairs[3] = {{"nuxy", "nuyx", p.nuxy * nuyx}, {"nuxz", "nuzx", p.nuxz * nuzx}, {"nuyz", "nuzy", p.nuyz * nuzy}};
  for (const auto& pr : pairs) {
    if (pr.product >= 1.0) {
      t.fail(t.has(pr.ij) ? pr.ij : pr.ji,
             std::string("Poisson ratios with ") + pr.ij + " * " + pr.ji + " < 1 (here " + readable_text(pr.product) +
                 "): otherwise the compliance is not positive definite");
    }
  }
  const double det = 1.0 - p.nuxy * nuyx - p.nuyz * nuzy - p.nuxz * nuzx - 2.0 * nuyx * nuzy * p.nuxz;
  if (det <= 0.0) {
    t.fail_table("the compliance is not positive definite: 1 - nuxy nuyx - nuyz nuzy - nuxz nuzx - "
                 "2 nuyx nuzy nuxz = " + readable_text(det) + " must be > 0; reduce the Poisson ratios");
  }
  read_transport_and_expansion(t, p, orthotropic_axes);
  return Orthotropic(p);
}

}  // namespace flowmpm
