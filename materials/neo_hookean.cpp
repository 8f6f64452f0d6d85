#include "materials/neo_hookean.hpp"

#include <sstream>
#include <stdexcept>

#include <Eigen/Eigenvalues>

#include "core/errors.hpp"
#include "core/parameter_table.hpp"
#include "materials/parameter_reading.hpp"

namespace flowmpm {

void NeoHookean::newton_failure(double a, double y) {
  std::ostringstream s;
  s << "neo_hookean: the lateral stretch of zero stress did not converge to |step of ln s| <= "
    << newton_tolerance << " in " << newton_iterations << " iterations (ln of the rest of J = " << a
    << ", ln s = " << y << ")";
  throw std::runtime_error(s.str());
}

NeoHookean NeoHookean::read(ParameterTable& t) {
  Parameters p;
  std::tie(p.density, p.youngs_modulus, p.poisson_ratio) = read_isotropic_elasticity(t);
  for (const char* key : {"alpha", "beta", "temperature_change", "concentration"}) {
    if (t.has(key)) {
      t.fail(key, "no expansion key: neo_hookean has no thermal or solvent expansion (linear_elastic, "
                  "von_mises and the orthotropic models have)");
    }
  }
  p.transport = TransportProperties::read(t, isotropic_axes);
  return NeoHookean(p);
}

// The principal stretches l_i = e^(x_i) of sigma's principal values s_i
// (V shares sigma's principal axes): J sigma = mu (b - I) + lambda ln J I
// reads r_i = mu (e^(2 x_i) - 1) + lambda S - s_i e^S = 0, S = sum x_i =
// ln J. Newton on x from 0 (the Jacobian 2 mu e^(2 x_i) delta_ij + lambda -
// s_i e^S), to |r| <= 1e-13 (2 mu + |lambda| + max |s_i|).
NeoHookean::State NeoHookean::initial_state(const ParticleInit& init) const {
  State state;
  const Eigen::Matrix3d sigma = tensor_of(init.stress);
  if (sigma.isZero(0.0)) return state;
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> principal(sigma);
  const Eigen::Vector3d s = principal.eigenvalues();
  const double scale = 2.0 * mu + std::abs(lambda) + s.cwiseAbs().maxCoeff();
  Eigen::Vector3d x = Eigen::Vector3d::Zero();
  for (int it = 0; it < newton_iterations; ++it) {
    const double S = x.sum(), J = std::exp(S);
    Eigen::Vector3d r;
    Eigen::Matrix3d jacobian;
    for (int i = 0; i < 3; ++i) {
      r[i] = mu * (std::exp(2.0 * x[i]) - 1.0) + lambda * S - s[i] * J;
      for (int j = 0; j < 3; ++j) jacobian(i, j) = lambda - s[i] * J + (i == j ? 2.0 * mu * std::exp(2.0 * x[i]) : 0.0);
    }
    if (r.cwiseAbs().maxCoeff() <= 1e-13 * scale) {
      const Eigen::Matrix3d& Q = principal.eigenvectors();
      state.F = Q * x.array().exp().matrix().asDiagonal() * Q.transpose();
      return state;
    }
    x -= jacobian.partialPivLu().solve(r);
  }
  std::ostringstream m;
  m << "neo_hookean: no stretch found whose stress is the initial stress (principal stresses " << s[0] << ", "
    << s[1] << ", " << s[2] << " Pa) in " << newton_iterations << " Newton iterations";
  throw CaseError(m.str());
}

}  // namespace flowmpm
