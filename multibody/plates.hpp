// Internal to multibody/: [plates] (ring::StaticOptions::Plates) in the chain's nonlinear
// statics, the dense path in the segment angles (statics.cpp, AngleStatics). The contact law is
// ring::PlatePair's (ring/analysis.hpp), one for every solver; what is the chain's own:
//
// ## Where the penalty acts
// As the Winkler foundation (attachments.hpp): lumped at the hinges, each standing for its
// share l = 2 pi R / n of ring length, so the penalty's energy is
//
//   E(q, s) = l sum_k sum_p 1/2 k <-g_p(X_k, s)>^2,
//
// at the point X_k of the centroid line that hinge k stands for, moved with the hinge:
// X_k = (R / Rp) P_k + u_k, u_k = p_k(q) - P_k its displacement. The hinges themselves rest on
// the polygon's circumradius Rp = R (1 + pi^2 / 6n^2 + ...) (chain.hpp), which would press the
// plates into the ring at rest by Rp - R (2.6e-4 R at n = 80, a quarter of a 1e-3 R approach);
// X_k rests on the ring of radius R, where PlatePair's gap is zero at the two points of first
// contact. X_k moves as p_k does, so in p_k the gradient is f_k = l sum_p k <-g_p> d_p, the
// Hessian B_k = l k d_0 d_0^T for each plate in_contact (d_1 d_1^T = d_0 d_0^T), and the rate
// d f_k / ds = l sum_p k (travel / 2) d_p where in_contact (the gap falls by travel / 2 per unit
// s), each pulled back to the angles by add_hinge_term (attachments.hpp).
//
// ## The two no-slide rows
// The hinges a (at plates.axis) and b (at axis + 180) keep their place along the plates,
// e . u_a = 0 and e . u_b = 0 with e = (-sin axis, cos axis): one row each, appended after the
// chain's closure rows as a roller's (chain.hpp): G = e^T d p_h / dq, and the row's Hessian
// diagonal in the angles, -l e . e(phi_j) for j < h. The free chain (no supports) carries the
// base (x_0, y_0), so the plates (along d_0) and these rows (along e, and the turning) hold
// every rigid motion while a plate touches.
//
// ## The centre row
// The midpoint of a and b stays on the plates' midline: d . (u_a + u_b) = 0 (d = PlatePair::d),
// one row after the no-slide rows, G = d^T (d p_a / dq + d p_b / dq), its Hessian diagonal
// -l d . e(phi_j) summed over j < a and j < b. By the symmetry of the crushing its multiplier
// stays ~0; it holds the ring along the axis when both gaps open (the plates withdrawn and the
// ring sprung back clear of them), where the contact alone would leave the tangent singular.
//
// ## Results
// The force of plate 0 on the ring, l sum_k k <-g_0(X_k)> (-d_0) (N, x and y), and
// PlatePair::contact_lengths at the points X_k.
#pragma once

#include <Eigen/Dense>
#include <array>
#include <vector>

#include "multibody/chain.hpp"
#include "ring/analysis.hpp"
#include "ring/spec.hpp"

namespace multibody::detail {

class PlateContact {
 public:
  /// Throws std::invalid_argument when plates.axis or axis + 180 is not a hinge of the chain
  /// (the scene reader checks it for scenes). O(1).
  PlateContact(const Chain& chain, const ring::RingSpec& spec, const ring::StaticOptions::Plates& plates);

  /// X_k for every hinge position p_k (2 x n, file comment), m.
  Eigen::Matrix2Xd points(const Eigen::Matrix2Xd& p) const;
  /// The penalty's energy E at the hinge positions p and load factor s, J. O(n).
  double energy(const Eigen::Matrix2Xd& p, double s) const;
  /// The penalty by hinge at the hinge positions p and load factor s (file comment): its gradient
  /// f_k in p_k, its Hessian B_k and its rate d f_k / ds, each resized to n. O(n).
  void by_hinge(const Eigen::Matrix2Xd& p, double s, std::vector<Eigen::Vector2d>& f, std::vector<Eigen::Matrix2d>& B,
                std::vector<Eigen::Vector2d>& rate) const;
  /// The no-slide rows' hinges (at axis, at axis + 180) and the plates' direction e.
  std::array<int, 2> slide_hinges() const { return {a_, b_}; }
  const Eigen::Vector2d& direction() const { return e_; }
  /// The plates' normal d = PlatePair::d (the centre row's direction).
  Eigen::Vector2d normal() const { return {pair_.d[0], pair_.d[1]}; }
  /// Adds the penalty's gradient in the angles q at load factor s to `grad` (dofs), its Hessian to
  /// `*hess` (if not null; dofs x dofs) and its rate d grad / ds to `rate` (dofs). O(n), O(n^2).
  void add(const Vector& q, double s, Vector& grad, Eigen::Ref<Matrix>* hess, Vector& rate) const;
  /// The two no-slide rows and the centre row at q (file comment), with the rows' Hessians as
  /// Chain::ConstraintKinematics'. O(n).
  Chain::ConstraintKinematics slide_rows(const Vector& q) const;
  /// The force of plate 0 on the ring (N, x and y) at the hinge positions p. O(n).
  std::array<double, 2> reaction(const Eigen::Matrix2Xd& p, double s) const;
  /// The contact length on each plate (ring::PlatePair::contact_lengths at X_k), m. O(n).
  std::array<double, 2> contact_lengths(const Eigen::Matrix2Xd& p, double s) const;

 private:
  const Chain& chain_;
  const ring::PlatePair pair_;
  const int a_, b_;           ///< the hinges at plates.axis and axis + 180
  const Eigen::Vector2d e_;   ///< the plates' direction, (-sin axis, cos axis)
  const double scale_;        ///< R / Rp
};

}  // namespace multibody::detail
