// Internal to multibody/dynamics.cpp and statics.cpp: the nonlinear residual of the
// constrained chain and its analytic tangent, assembled from multibody::Chain only.
//
//   r(q, v, qdd, lambda, s) = M(q) qdd + xi(q, v) + C v + K theta + G(q)^T lambda - s Phi(q)
//   g(q) = constraints (closure [+ roller]), m
//
// Tangent pieces (derivations in the comments of dynamics_model.cpp, each one checked
// against central differences of the Chain's own functions in test_dynamics_model.cpp):
//   d(M qdd)/dq = S diag(qdd) - diag(S qdd),  S_jk = m l^2 (L^T L)_jk sin(phi_j - phi_k)
//                                              (column k of S = quadratic_velocity(q, e_k))
//   d xi/dq     = diag(M' v^2) - M' diag(v^2),  M' = M with its diagonal removed
//   d xi/dv     = 2 S diag(v)
//   d(G^T lambda)/dq = diag_j(lambda . constraint_jdot_qdot(q, e_j))  (g is a sum of
//                      functions of single angles, so its Hessians are diagonal)
//   d Phi/dq    = diag_j(-l e(phi_j) . F) for the segments before the loaded hinge.
#pragma once

#include <Eigen/Dense>
#include <optional>

#include "multibody/chain.hpp"

namespace multibody::detail {

/// A dead point load: force F (N, ring-centred frame) at hinge `hinge`.
struct DeadLoad {
  int hinge = 0;
  Eigen::Vector2d force{0.0, 0.0};
};

/// Everything that depends on q alone, evaluated once per Newton iteration. O(n^2).
struct Kinematic {
  Matrix M;       ///< mass matrix
  Matrix S;       ///< S_jk = m l^2 (L^T L)_jk sin(phi_j - phi_k) (antisymmetric)
  Matrix G;       ///< constraint Jacobian (c x n)
  Vector g;       ///< constraints, m
  Matrix hess_g;  ///< row i, column j: d^2 g_i / d phi_j^2 (c x n; Hessians are diagonal)
};

/// Evaluates the Kinematic quantities of a pinned chain at q. O(n^2).
Kinematic evaluate(const Chain& chain, const Vector& q);

/// Generalized force of the dead load and the diagonal of its derivative dPhi/dq. O(n).
void load_forces(const Chain& chain, const DeadLoad& load, const Vector& q, Vector& phi,
                 Vector& dphi_diag);

/// Tangent of the inertia terms at (q, v, qdd): d(M qdd + xi)/dq and d xi/dv. O(n^2).
void inertia_tangent(const Kinematic& k, const Vector& v, const Vector& qdd, Matrix& dq,
                     Matrix& dv);

/// Quadratic-velocity vector from S: xi = S v.^2. O(n^2).
Vector quadratic_velocity(const Kinematic& k, const Vector& v);

/// Shortest distance between the centre lines of two non-adjacent segments, over the
/// pairs whose index gap (cyclic) is at least `min_gap`; returns {distance, i, j}. The
/// test rejects pairs by bounding boxes grown by `reach`: only pairs closer than
/// `reach` are measured (others count as `reach`). O(n^2) box tests.
struct ClosestPair {
  double distance = 0.0;
  int i = -1, j = -1;
};
ClosestPair closest_nonadjacent(const Eigen::Matrix2Xd& hinges, int min_gap, double reach);

/// Smallest index gap checked for self-contact so that the undeformed chain is clear of
/// `depth`: 2 + floor(2 depth / l).
int contact_gap(const Chain& chain, double depth);

}  // namespace multibody::detail
