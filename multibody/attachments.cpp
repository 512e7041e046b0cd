#include "multibody/attachments.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace multibody::detail {

namespace {

/// The hinge at `deg`, or std::invalid_argument naming `key`.
int hinge(const Chain& chain, double deg, const std::string& key) {
  if (!ring::on_node(deg, chain.anchor_deg(), chain.n()))
    throw std::invalid_argument("multibody: " + key + " (= " + std::to_string(deg) +
                                " deg) is not a hinge of the n = " + std::to_string(chain.n()) +
                                " chain (valid: anchor + 360 k / n)");
  return chain.hinge_at(deg);
}

/// d u_k / d q at the rest n-gon (2 x dofs): columns j < k are c_j = l e'(phi0_j); the
/// free ring's (x_0, y_0) columns are the identity.
Matrix hinge_map(const Chain& chain, int k) {
  Matrix P = Matrix::Zero(2, chain.dofs());
  for (int j = 0; j < k; ++j) P.col(j) << -chain.l() * std::sin(chain.phi0()[j]), chain.l() * std::cos(chain.phi0()[j]);
  if (chain.free()) P.rightCols(2).setIdentity();
  return P;
}

/// d(mean rotation of hinge h's two segments) / d q.
Vector mean_rotation_map(const Chain& chain, int h) {
  Vector a = Vector::Zero(chain.dofs());
  a[(h + chain.n() - 1) % chain.n()] += 0.5;
  a[h] += 0.5;
  return a;
}

/// sum_k P_k^T B[k] P_k through the suffix sums of B (file comment). O(n^2).
Matrix pull_back(const Chain& chain, const std::vector<Eigen::Matrix2d>& B) {
  const int n = chain.n(), N = chain.dofs();
  std::vector<Eigen::Matrix2d> S(n + 1, Eigen::Matrix2d::Zero());
  for (int k = n - 1; k >= 0; --k) S[k] = S[k + 1] + B[k];
  Eigen::Matrix2Xd c(2, n);
  for (int j = 0; j < n; ++j) c.col(j) << -chain.l() * std::sin(chain.phi0()[j]), chain.l() * std::cos(chain.phi0()[j]);
  Matrix K = Matrix::Zero(N, N);
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j <= i; ++j) K(i, j) = K(j, i) = c.col(i).dot(S[i + 1] * c.col(j));
    if (chain.free()) {
      const Eigen::RowVector2d r = c.col(i).transpose() * S[i + 1];
      K.block(i, n, 1, 2) = r;
      K.block(n, i, 2, 1) = r.transpose();
    }
  }
  if (chain.free()) K.bottomRightCorner(2, 2) = S[0];
  return K;
}

}  // namespace

LinearTerms linear_terms(const Chain& chain, const ring::RingSpec& spec) {
  const int n = chain.n(), N = chain.dofs();
  std::vector<Eigen::Matrix2d> stiff(n, Eigen::Matrix2d::Zero()), mass(n, Eigen::Matrix2d::Zero());
  std::vector<double> kr(n, 0.0);  // rotational springs to the ground, by hinge (a clamp: infinite)
  LinearTerms t;
  t.K = Matrix::Zero(N, N);
  t.M = Matrix::Zero(N, N);

  if (spec.foundation.any())
    for (int k = 0; k < n; ++k) {
      const Eigen::Vector2d r = chain.hinge_rest(k).normalized(), tan(-r.y(), r.x());
      stiff[k] += chain.l() * (spec.foundation.radial * r * r.transpose() +
                               spec.foundation.tangential * tan * tan.transpose());
    }
  for (std::size_t i = 0; i < spec.supports.springs.size(); ++i) {
    const ring::Spring& s = spec.supports.springs[i];
    const int h = hinge(chain, s.angle, "supports.springs[" + std::to_string(i + 1) + "]");
    stiff[h].diagonal() += Eigen::Vector2d(s.kx, s.ky);
    kr[h] += s.kr;
  }
  if (spec.supports.clamp) kr[hinge(chain, *spec.supports.clamp, "supports.clamp")] = HUGE_VAL;
  // The hinge's rotation psi, condensed: 4K and kr in series on the mean rotation (file comment).
  const double k4 = 4.0 * chain.K();
  for (int h = 0; h < n; ++h)
    if (kr[h] > 0.0) {
      const Vector a = mean_rotation_map(chain, h);
      t.K += (std::isinf(kr[h]) ? k4 : k4 * kr[h] / (k4 + kr[h])) * a * a.transpose();
    }
  for (std::size_t i = 0; i < spec.masses.size(); ++i) {
    const ring::PointMass& pm = spec.masses[i];
    const int h = hinge(chain, pm.angle, "masses[" + std::to_string(i + 1) + "]");
    mass[h].diagonal().array() += pm.mass;
    // psi = 4K / (4K + kr) times the mean rotation: all of it without a spring, none at a clamp.
    const double follows = std::isinf(kr[h]) ? 0.0 : k4 / (k4 + kr[h]);
    const Vector a = follows * mean_rotation_map(chain, h);
    t.M += pm.inertia * a * a.transpose();
  }
  t.K += pull_back(chain, stiff);
  t.M += pull_back(chain, mass);

  t.J.resize(2 * static_cast<Eigen::Index>(spec.supports.pins.size()), N);
  for (std::size_t i = 0; i < spec.supports.pins.size(); ++i)
    t.J.middleRows(2 * static_cast<Eigen::Index>(i), 2) = hinge_map(chain, hinge(chain, spec.supports.pins[i], "supports.pins"));
  return t;
}

}  // namespace multibody::detail
