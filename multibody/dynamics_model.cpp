#include "multibody/dynamics_model.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace multibody::detail {

Kinematic evaluate(const Chain& chain, const Vector& q) {
  const int n = chain.dofs();
  Kinematic k;
  k.M = chain.mass_matrix(q);
  // xi(q, v) = sum_k S(:, k) v_k^2, so a unit velocity of segment k alone gives column k.
  k.S.resize(n, n);
  Vector e = Vector::Zero(n);
  for (int c = 0; c < n; ++c) {
    e[c] = 1.0;
    k.S.col(c) = chain.quadratic_velocity(q, e);
    e[c] = 0.0;
  }
  k.G = chain.constraint_jacobian(q);
  k.g = chain.constraints(q);
  // Jdot qd = sum_j (d^2 g / d phi_j^2) qd_j^2 when the Hessians are diagonal.
  const int c_rows = chain.constraint_count();
  k.hess_g.resize(c_rows, n);
  for (int c = 0; c < n; ++c) {
    e[c] = 1.0;
    k.hess_g.col(c) = chain.constraint_jdot_qdot(q, e);
    e[c] = 0.0;
  }
  return k;
}

void load_forces(const Chain& chain, const DeadLoad& load, const Vector& q, Vector& phi,
                 Vector& dphi_diag) {
  phi = chain.point_load_forces(q, load.hinge, load.force);
  // Phi_j = l e'(phi_j) . F for j < hinge, so dPhi_j/dphi_j = -l e(phi_j) . F, and the
  // segment direction e(phi_j) is (p_{j+1} - p_j) / l.
  const Eigen::Matrix2Xd p = chain.hinge_positions(q);
  const int n = chain.n();
  dphi_diag = Vector::Zero(chain.dofs());
  for (int j = 0; j < load.hinge; ++j) {
    const Eigen::Vector2d d = p.col((j + 1) % n) - p.col(j);
    dphi_diag[j] = -d.dot(load.force);
  }
}

Vector quadratic_velocity(const Kinematic& k, const Vector& v) {
  return k.S * v.cwiseAbs2();
}

void inertia_tangent(const Kinematic& k, const Vector& v, const Vector& qdd, Matrix& dq,
                     Matrix& dv) {
  // M_jk = C_jk cos(phi_j - phi_k) (+ Jr on the diagonal), S_jk = C_jk sin(phi_j - phi_k).
  // d(M a)_j/dphi_i = -delta_ij (S a)_j + S_ji a_i;
  // xi_j = sum_{k != j} S_jk v_k^2, d xi_j/dphi_i = delta_ij sum_{k!=j} M_jk v_k^2 - M_ji v_i^2
  // (i != j), d xi_j / dv_i = 2 S_ji v_i.
  const Vector v2 = v.cwiseAbs2();
  Matrix Moff = k.M;
  Moff.diagonal().setZero();
  dq = k.S * qdd.asDiagonal();
  dq.diagonal() -= k.S * qdd;
  dq.noalias() -= Moff * v2.asDiagonal();
  dq.diagonal() += Moff * v2;
  dv = 2.0 * k.S * v.asDiagonal();
}

ClosestPair closest_nonadjacent(const Eigen::Matrix2Xd& p, int min_gap, double reach) {
  const int n = static_cast<int>(p.cols());
  ClosestPair best{reach, -1, -1};
  // Bounding boxes of the segments i = (p_i, p_{i+1}).
  std::vector<Eigen::Vector2d> lo(n), hi(n);
  for (int i = 0; i < n; ++i) {
    const auto a = p.col(i), b = p.col((i + 1) % n);
    lo[i] = a.cwiseMin(b);
    hi[i] = a.cwiseMax(b);
  }
  auto point_segment = [](const Eigen::Vector2d& x, const Eigen::Vector2d& a,
                          const Eigen::Vector2d& b) {
    const Eigen::Vector2d ab = b - a;
    const double t = std::clamp((x - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
    return (a + t * ab - x).norm();
  };
  auto cross = [](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return a.x() * b.y() - a.y() * b.x();
  };
  for (int i = 0; i < n; ++i) {
    for (int j = i + min_gap; j < n; ++j) {
      if (n - (j - i) < min_gap) break;  // cyclic gap
      if (lo[j].x() > hi[i].x() + reach || lo[i].x() > hi[j].x() + reach ||
          lo[j].y() > hi[i].y() + reach || lo[i].y() > hi[j].y() + reach)
        continue;
      const Eigen::Vector2d a = p.col(i), b = p.col((i + 1) % n);
      const Eigen::Vector2d c = p.col(j), d = p.col((j + 1) % n);
      double dist;
      const double d1 = cross(b - a, c - a), d2 = cross(b - a, d - a);
      const double d3 = cross(d - c, a - c), d4 = cross(d - c, b - c);
      if (((d1 > 0) != (d2 > 0)) && ((d3 > 0) != (d4 > 0))) {
        dist = 0.0;  // the centre lines cross
      } else {
        dist = std::min({point_segment(a, c, d), point_segment(b, c, d), point_segment(c, a, b),
                         point_segment(d, a, b)});
      }
      if (dist < best.distance) best = {dist, i, j};
    }
  }
  return best;
}

int contact_gap(const Chain& chain, double depth) {
  return 2 + static_cast<int>(std::floor(2.0 * depth / chain.l()));
}

}  // namespace multibody::detail
