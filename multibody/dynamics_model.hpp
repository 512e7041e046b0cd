// Internal to multibody/dynamics.cpp and statics.cpp: the nonlinear residual of the
// constrained chain and its analytic tangent, assembled from multibody::Chain only.
//
//   r(q, v, qdd, lambda, s) = M(q) qdd + xi(q, v) + C v + K theta + G(q)^T lambda - s Phi(q)
//   g(q) = constraints (closure [+ roller]), m
//
// Tangent pieces (derivations in the comments of dynamics_model.cpp, each one checked
// against central differences of the Chain's own functions in test_dynamics_model.cpp):
//   d(M qdd)/dq = S diag(qdd) - diag(S qdd),  S_jk = m l^2 (L^T L)_jk sin(phi_j - phi_k)
//     with m l^2 (L^T L)_jk (j != k) read once from mass_matrix at phi = 0 (where every
//     cosine is 1): the structure mu_jk = m l^2 (L^T L)_jk cos(phi_j - phi_k) of chain.hpp
//   d xi/dq     = diag(M' v^2) - M' diag(v^2),  M' = M with its diagonal removed
//   d xi/dv     = 2 S diag(v)
//   d(G^T lambda)/dq = diag_j(lambda . d^2 g/d phi_j^2): g is a sum of sinusoids
//     l (a cos phi_j + b sin phi_j) of single angles, so its Hessians are diagonal and
//     d^2 g / d phi_j^2 is minus segment j's term (Chain::constraint_kinematics returns
//     them with g and G)
//   d Phi/dq    = diag_j(-l e(phi_j) . F) for the segments before the loaded hinge.
#pragma once

#include <Eigen/Dense>
#include <optional>
#include <string>

#include "multibody/attachments.hpp"
#include "multibody/chain.hpp"

namespace multibody::detail {

/// A dead point load: force F (N, ring-centred frame) at hinge `hinge`.
struct DeadLoad {
  int hinge = 0;
  Eigen::Vector2d force{0.0, 0.0};
};

/// Constant parts of the inertia, read once from the mass matrix at phi = 0 (where every
/// cosine is 1): M_jk = C0_jk cos(phi_j - phi_k) for j != k and M_jj = diag_j, the
/// structure of chain.hpp, which `terms`' point masses share (Attachments::add_mass; both
/// checked in the unit tests). O(n^2).
/// A free chain (no pin) has two more coordinates after its n angles, the first hinge's
/// translation (X, Y): M_XX = M_YY = the whole mass, M_XY = 0, and with an angle j
/// M_Xj = -b_j sin(phi_j), M_Yj = b_j cos(phi_j), b_j = C0_Yj (the cosine structure above
/// does not hold for them).
struct Inertia {
  Matrix C0;    ///< m l^2 (L^T L)_jk (+ the point masses' l^2 sum_{k > max(j,k)} m_k) off the diagonal, zero on it
  Vector diag;  ///< M_jj, constant
  Eigen::Index angles = 0;  ///< the chain's angles; the coordinates after them are the free chain's translation
};
Inertia inertia_constants(const Chain& chain, const Attachments* terms = nullptr);
/// The mass matrix M(q) of the chain's coordinates: the chain's and `terms`' point masses'
/// translations (dofs x dofs). O(n^2).
Matrix mass_matrix(const Chain& chain, const Attachments* terms, const Vector& q);

/// Inertia force and its tangent in one pass over the n x n entries (no M or S formed):
///   r = M(q) qdd + xi(q, v),
///   T += cm M(q) + cv d xi/dv + d(M qdd + xi)/dq   (if T is given),
/// with S_jk = C0_jk sin(phi_j - phi_k), xi = S v.^2, d xi/dv = 2 S diag(v),
/// d(M qdd)/dq = S diag(qdd) - diag(S qdd), d xi/dq = diag(M' v.^2) - M' diag(v.^2)
/// (M' = M off the diagonal). T may be larger than n x n: its top-left block takes it. O(n^2).
void inertia_terms(const Inertia& in, const Vector& q, const Vector& v, const Vector& qdd,
                   double cm, double cv, Vector& r, Matrix* T);

/// Constraint values, Jacobian and Hessian diagonals at q. O(n).
struct Kinematic {
  Matrix G;       ///< constraint Jacobian (c x n)
  Vector g;       ///< constraints, m
  Matrix hess_g;  ///< row i, column j: d^2 g_i / d phi_j^2 (c x n; Hessians are diagonal)
};
/// G always; g when asked; with hess_g, all three from one pass of sines and cosines
/// (Chain::constraint_kinematics).
Kinematic evaluate(const Chain& chain, const Vector& q, bool values = true, bool hessian = true);

/// Generalized force of the dead load and (if asked) the diagonal of dPhi/dq. O(n).
void load_forces(const Chain& chain, const DeadLoad& load, const Vector& q, Vector& phi,
                 Vector* dphi_diag);

/// Shortest distance between the centre lines of two non-adjacent segments, over the
/// pairs whose index gap (cyclic) is at least `min_gap`; returns {distance, i, j}. The
/// test rejects pairs by bounding boxes grown by `reach`: only pairs closer than
/// `reach` are measured (others count as `reach`). O(n^2) box tests.
struct ClosestPair {
  double distance = 0.0;
  int i = -1, j = -1;
};
/// "segments i and j cross" or "segments i and j are d m apart".
/// Distance between the segments [a, b] and [c, d] (0 when they cross). O(1).
double segment_distance(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c,
                        const Eigen::Vector2d& d);

std::string describe_contact(const ClosestPair& cp);
/// `closed` = false: an arch's open chain, hinges.cols() - 1 segments and no cyclic gap.
ClosestPair closest_nonadjacent(const Eigen::Matrix2Xd& hinges, int min_gap, double reach, bool closed = true);

/// Smallest index gap checked for self-contact so that the undeformed chain is clear of
/// `depth`: 2 + floor(2 depth / l).
int contact_gap(const Chain& chain, double depth);

/// A Newton correction that turns a segment by more than this (rad) has left the basin
/// of attraction: statics and dynamics, angle and hinge-position paths alike reject it
/// and cut the load or time step.
constexpr double kBasin = 0.5;

}  // namespace multibody::detail
