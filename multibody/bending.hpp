// The hinge's bending law, written once for every kernel of the chain: the spring at hinge k
// (chain.hpp) resists the change e of its turning angle from rest (rad) with
//  - elastic: the moment K e, K = EI / l (N m / rad), the potential K e^2 / 2;
//  - `ring.plastic` (the resultant law): ring::BilinearLaw(K, Mp, h, rule) from the hinge's
//    committed ring::PlasticState (ring/plastic.hpp): moment, tangent and the incremental
//    potential whose derivative is the moment, evaluated at a trial e from the committed state.
// The linear O(n) kernels (the Riccati sweep, the position modes, the shifted solve) and the
// elastic energy of the dynamics read only the rest stiffness K() (their law is K e); the
// nonlinear statics assemble at(k, e) and commit the converged strains.
//
// A HingeBending holds the path-dependent state of the n hinges (O(n) memory); it changes only
// in commit(), so that a trial evaluation needs no undo.
#pragma once

#include <optional>
#include <vector>

#include <Eigen/Core>

#include "ring/plastic.hpp"
#include "ring/spec.hpp"

namespace multibody {

class Chain;

/// The rest stiffness of a hinge spring, EI / l (N m / rad): bending from one segment's
/// midpoint to the next over the length l (m). The one place it is spelt.
double hinge_stiffness(const ring::RingSpec& spec, double l);

class HingeBending {
 public:
  /// The law of the n hinges of `chain` under `spec` (elastic without spec.plastic; the
  /// resultant law with it: the fibre law is refused by the scene reader). O(n).
  HingeBending(const ring::RingSpec& spec, const Chain& chain);

  /// The moment (N m), tangent dM/de (N m / rad) and incremental potential (J, zero at the
  /// committed plastic rotation) of hinge k at the trial change e (rad) of its turning angle.
  using Point = ring::BilinearLaw::Point;
  Point at(int k, double e) const;
  double moment(int k, double e) const { return at(k, e).force; }
  double tangent(int k, double e) const { return at(k, e).tangent; }
  double potential(int k, double e) const { return at(k, e).potential; }

  /// Commits the converged changes e (one per hinge, rad): the plastic states move and the
  /// plastic work of the step is added to dissipated(). Nothing for the elastic law. O(n).
  void commit(const Eigen::Ref<const Eigen::VectorXd>& strains);

  /// The hinges' forces on the segment angles q of `chain` (dofs() entries, zero on a free
  /// ring's base): dV/dq_k = M_k - M_{k+1}, M_k at the hinge rotation r_k = theta_k -
  /// theta_{k-1} (Chain::hinge_rotations). O(n).
  Eigen::VectorXd forces_on_angles(const Chain& chain, const Eigen::VectorXd& q) const;
  /// Adds their Jacobian, sum_k tangent_k grad r_k grad r_k^T (the cyclic (2, -1, -1) times K
  /// while elastic), to T (dofs() x dofs()). O(n) entries.
  void add_tangent_on_angles(const Chain& chain, const Eigen::VectorXd& q, Eigen::Ref<Eigen::MatrixXd> T) const;

  int hinges() const { return n_; }
  /// The rest stiffness K = EI / l, N m / rad (hinge_stiffness).
  double K() const { return K_; }
  bool plastic() const { return law_.has_value(); }
  /// The elastic energy stored at e in hinge k's committed state, K (e - e_p)^2 / 2, J.
  double stored(int k, double e) const;
  /// The plastic work of every committed step, J.
  double dissipated() const { return dissipated_; }
  /// The largest |committed plastic rotation| over the hinges, rad.
  double largest_plastic_rotation() const;
  /// The committed state of hinge k.
  const ring::PlasticState& state(int k) const { return states_[k]; }

 private:
  int n_;
  double K_;
  std::optional<ring::BilinearLaw> law_;
  std::vector<ring::PlasticState> states_;  ///< empty for the elastic law
  double dissipated_ = 0.0;
};

}  // namespace multibody
