// Internal to multibody/: the loads of a static analysis on the chain (ring/spec.hpp, Loads:
// point loads, uniform pressure of the three kinds, gravity), written once as a potential
// Pi(q) of the hinge positions with its gradient and Hessian in the chain's coordinates; the
// O(n) statics takes the same hinge gradient and blocks on hinge positions (hinge_gradient).
// Equilibrium at load factor s: dV/dq + s dPi/dq + G^T lambda = 0.
//
// ## The loads on straight rigid segments (segment j from hinge p_j to p_{j+1}, length
// l = 2 pi R / n: the undeformed arc it stands for)
// A dead force density along a rigid segment does the work of its two end resultants, since a
// point at s on the segment is (1 - s/l) p_j + (s/l) p_{j+1}. So three of the loads are
// exactly constant forces f_k at the hinges, Pi = -sum_k f_k . (p_k - P_k):
// - point loads: F at their hinge;
// - gravity: rho A l g / 2 at each end of every segment (the segment's centre of mass is its
//   midpoint), plus m g at a point mass's hinge;
// - dead pressure: p n0_j l / 2 at each end of segment j, n0_j the inward normal of the rest
//   segment (the undeformed polygon's normal: all three kinds equal p n0 on it).
// The other two depend on the deformed shape:
// - follower pressure: Pi = p A, A the area the closed polygon p_0 .. p_n encloses
//   (A = 1/2 sum_k p_k x p_{k+1}, the pair (n, 0) closing it): exact for straight segments,
//   the force -p dA/dp_k is p times the inward normal of the deformed neighbours;
// - central pressure: Pi = p sum_j int_0^l |x(s)| ds, x(s) on the deformed segment, by
//   4-point Gauss-Legendre (error O((l/R)^8) against the segment's O((l/R)^2)).
// - the centrifugal body force of a spinning ring (spec.rotation, in the frame turning with
//   it): Pi = -speed^2 / 2 (sum_j m |c_j|^2 + sum_k m_k |p_k|^2), c_j = (p_j + p_{j+1}) / 2 the
//   segment's centroid (a rigid segment's centrifugal force is m speed^2 c_j, through c_j; its
//   rotary inertia adds a constant), m_k the point masses. Quadratic in the hinge positions:
//   blocks -speed^2 m / 4 on (j, j), (j, j + 1), (j + 1, j), (j + 1, j + 1) and -speed^2 m_k
//   at hinge k, i.e. the centrifugal softening -speed^2 M_trans (the translations' mass). It
//   is part of every Loading of a spinning spec, scaled by the load factor like the others
//   (the spin's equilibrium, spin.hpp); the analyses that do not take a spin refuse it
//   (checks.hpp).
// Hinge p_n is the chain's far end (p_0 when the closure holds). On an arch the polygon
// p_0 .. p_n closes through its ends: with both ends pinned that side is constant, and p A is
// the follower pressure's potential exactly (refused otherwise).
//
// ## Pull-back to the angles (as attachments.hpp)
// p_k = p_0 + l sum_{j<k} e(phi_j), so with c_j = l e'(phi_j), hinge gradients g_k and hinge
// Hessian blocks H_km:
//   dPi/dphi_j = c_j . sum_{k>j} g_k,
//   d2Pi/dphi_i dphi_j = c_i^T S(i+1, j+1) c_j - delta_ij l e(phi_j) . sum_{k>j} g_k,
// S(a, b) = sum_{k>=a, m>=b} H_km (two-dimensional suffix sums), and the identity in the
// free ring's (x_0, y_0). O(n) for the gradient, O(n^2) for the Hessian (the dense path).
#pragma once

#include <Eigen/Dense>
#include <utility>
#include <vector>

#include "multibody/chain.hpp"
#include "ring/spec.hpp"

namespace multibody::detail {

class Loading {
 public:
  /// `section` names the keys in messages ("static", "response"). Throws
  /// std::invalid_argument naming the key when a point load is not a hinge. O(n).
  Loading(const Chain& chain, const ring::RingSpec& spec, const ring::Loads& loads, const std::string& section);

  /// Pi(q) - Pi(q0) at load factor 1: minus the loads' work from rest, J. O(n).
  double potential(const Vector& q) const;
  /// Generalized forces -dPi/dq (dofs). O(n).
  Vector forces(const Vector& q) const;
  /// Adds s d2Pi/dq2 (the load stiffness; zero for constant hinge forces in the hinges,
  /// not in the angles) to `hess` (dofs x dofs). O(n^2).
  void add_stiffness(const Vector& q, double s, Eigen::Ref<Matrix> hess) const;
  /// d2Pi/dq2 when no load is shape-dependent (constant hinge forces): diagonal in the angles
  /// (the curvature of the hinge positions), this diagonal (dofs; 0 on a free ring's x0, y0),
  /// for the O(n) response (newton_backend.hpp). Throws std::logic_error if shape_dependent().
  /// O(n).
  Vector constant_stiffness_diagonal(const Vector& q) const;

  // The loads on hinge positions, the one place they are written (file comment): the
  // angles' members above pull them back, the O(n) statics (statics_natural.cpp) takes them
  // as they are, with p_n = p_0.

  /// A 2 x 2 block d2Pi / dp_k dp_m.
  struct Block {
    int k, m;
    Eigen::Matrix2d h;
  };
  /// Hinge gradients g_k = dPi/dp_k at load factor 1 (2 x (n + 1)) at hinge positions p
  /// (2 x (n + 1)) and, if `H` is not null, the non-zero Hessian blocks (O(n) of them:
  /// hinge k with k and k + 1, and the closing pair (n, 0)). O(n).
  Eigen::Matrix2Xd hinge_gradient(const Eigen::Matrix2Xd& p, std::vector<Block>* H) const;
  /// True when Pi has a Hessian in the hinge positions (follower or central pressure, the
  /// centrifugal force).
  bool shape_dependent() const { return follower_ != 0.0 || central_ != 0.0 || spin2_ != 0.0; }

 private:
  /// Hinge positions p_0 .. p_n (2 x (n + 1)). O(n).
  Eigen::Matrix2Xd positions(const Vector& q) const;
  /// -l e(phi_j) . sum_{k > j} g_k: the hinge gradients g pulled through the curvature of
  /// the hinge positions in the angles (d2 p_k / d phi_j^2 = -l e(phi_j), j < k). O(n).
  Vector angle_curvature(const Vector& q, const Eigen::Matrix2Xd& g) const;
  /// The shape-dependent part of Pi (follower and central pressure, the centrifugal force)
  /// at hinge positions p.
  double shape_potential(const Eigen::Matrix2Xd& p) const;

  const Chain& chain_;
  Eigen::Matrix2Xd f_;     ///< constant hinge forces f_0 .. f_n, N
  Eigen::Matrix2Xd rest_;  ///< rest positions P_0 .. P_n
  double follower_ = 0.0;  ///< p of follower pressure, N/m
  double central_ = 0.0;   ///< p of central pressure, N/m
  double spin2_ = 0.0;     ///< speed^2 of a spinning spec (the centrifugal force), rad^2/s^2
  double segment_mass_ = 0.0;                        ///< m = rho A l, kg
  std::vector<std::pair<int, double>> point_masses_;  ///< (hinge, kg): their centrifugal force
  double rest_shape_ = 0.0;  ///< follower p A + central p int |x| ds0 of the rest polygon, J
};

}  // namespace multibody::detail
