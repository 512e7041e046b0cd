// The hinge's bending law, written once for every kernel of the chain: the spring at hinge k
// (chain.hpp) resists the change e of its turning angle from rest (rad) with
//  - elastic: the moment K e, K = EI / l (N m / rad), the potential K e^2 / 2;
//  - `ring.plastic`, either law: ring::HingeLaw(section, l) (ring/section_law.hpp) on one
//    ring::SectionLaw for the spec: the section's law at the uniform curvature e / l of the
//    segment the hinge stands for, from the hinge's committed ring::PlasticStates
//    (resultant, `moment = Mp`: one state, the plastic curvature; fibre, `stress =
//    sigma_y`: SectionLaw::kFibres states, one per fibre of the section's shape): moment,
//    tangent and the incremental potential whose derivative is the moment, evaluated at a
//    trial e from the committed states. Inside its band the resultant law's moment and
//    potential are spelt K (e - l kappa_p) and K (e - l kappa_p)^2 / 2, the elastic spring's
//    arithmetic (HingeLaw's values to one rounding), so that a plastic moment never reached
//    is the elastic chain bit for bit.
// The linear O(n) kernels (the Riccati sweep, the position modes, the shifted solve) read
// only the rest stiffness K() (their law is K e); the nonlinear statics and the angle
// integrators' response assemble at(k, e) and commit the converged strains.
//
// A HingeBending holds the path-dependent states of the n hinges: O(n states()) memory
// (states() = 1 or SectionLaw::kFibres), O(n states()) per evaluation of every hinge; they
// change only in commit(), so that a trial evaluation needs no undo, and a step or load
// level that is thrown away leaves nothing behind (paths/internal.hpp).
#pragma once

#include <optional>
#include <vector>

#include <Eigen/Core>

#include "ring/plastic.hpp"
#include "ring/section_law.hpp"
#include "ring/spec.hpp"

namespace multibody {

class Chain;

/// The rest stiffness of a hinge spring, EI / l (N m / rad): bending from one segment's
/// midpoint to the next over the length l (m). The one place it is spelt.
double hinge_stiffness(const ring::RingSpec& spec, double l);

/// Refuses (ring::InputError, key ring.plastic.stress) the fibre law of spec.plastic on a
/// section given by {area, inertia}, which has no shape to put fibres in; nothing otherwise.
/// The scene reader refuses it too; this holds for a library caller's spec. O(1).
void check_section_law(const ring::RingSpec& spec);

class HingeBending {
 public:
  /// The law of the n hinges of `chain` under `spec`: elastic without spec.plastic, either
  /// law of ring.plastic with it. Throws ring::InputError (key ring.plastic.stress) for the
  /// fibre law on a section given by {area, inertia}: it has no shape to put fibres in.
  /// O(n states()).
  HingeBending(const ring::RingSpec& spec, const Chain& chain);

  /// The moment (N m), tangent dM/de (N m / rad) and incremental potential (J, zero at the
  /// committed plastic rotation) of hinge k at the trial change e (rad) of its turning angle.
  using Point = ring::BilinearLaw::Point;
  Point at(int k, double e) const;
  double moment(int k, double e) const { return at(k, e).force; }
  double tangent(int k, double e) const { return at(k, e).tangent; }
  double potential(int k, double e) const { return at(k, e).potential; }

  /// Commits the converged changes e (one per hinge, rad): the plastic states move and the
  /// plastic work of the step is added to dissipated(). Nothing for the elastic law. O(n states()).
  void commit(const Eigen::Ref<const Eigen::VectorXd>& strains);
  /// The plastic work that commit(strains) would add, J (0 for the elastic law). O(n states()).
  double dissipated_by(const Eigen::Ref<const Eigen::VectorXd>& strains) const;

  /// The hinges' forces on the segment angles q of `chain` (dofs() entries, zero on a free
  /// ring's base; an arch's springs are at hinges 1 .. n-1 only, Chain::first_spring):
  /// dV/dq_k = M_k - M_{k+1}, M_k at the hinge rotation r_k = theta_k -
  /// theta_{k-1} (Chain::hinge_rotations). O(n states()).
  Eigen::VectorXd forces_on_angles(const Chain& chain, const Eigen::VectorXd& q) const;
  /// Adds their Jacobian, sum_k tangent_k grad r_k grad r_k^T (the cyclic (2, -1, -1) times K
  /// while elastic), to T (dofs() x dofs()). O(n states()) work, O(n) entries.
  void add_tangent_on_angles(const Chain& chain, const Eigen::VectorXd& q, Eigen::Ref<Eigen::MatrixXd> T) const;
  /// The hinges' elastic energy stored at the segment angles q from the committed states,
  /// sum_k stored(k, r_k), J. O(n states()).
  double stored_on_angles(const Chain& chain, const Eigen::VectorXd& q) const;

  int hinges() const { return n_; }
  /// The rest stiffness K = EI / l, N m / rad (hinge_stiffness).
  double K() const { return K_; }
  bool plastic() const { return section_.has_value(); }
  /// PlasticStates per hinge: 0 (elastic), 1 (resultant), SectionLaw::kFibres (fibre).
  int states() const { return section_ ? section_->states() : 0; }
  /// The elastic energy stored at e in hinge k's committed state, J: M^2 / (2K) for the
  /// resultant law, the fibres' sum of l sigma^2 a / (2E) for the fibre law, K e^2 / 2 elastic.
  double stored(int k, double e) const;
  /// The plastic work of every committed step, J.
  double dissipated() const { return dissipated_; }
  /// The largest |plastic curvature| over the hinges at their committed strains, 1/m: the
  /// curvature left when the section is unloaded elastically, kappa - M / EI (the resultant
  /// law's committed state itself; exactly 0 where no state has yielded).
  double largest_plastic_curvature() const;
  /// The same times the segment length: the hinge's plastic rotation, rad.
  double largest_plastic_rotation() const { return largest_plastic_curvature() * l_; }
  /// Hinge k's committed state i (i < states(); the resultant law's one: the plastic
  /// curvature, 1/m, and its accumulated |change|).
  const ring::PlasticState& state(int k, int i = 0) const { return states_[static_cast<std::size_t>(k) * m_ + i]; }

 private:
  ring::HingeLaw law() const { return ring::HingeLaw(*section_, l_); }
  const ring::PlasticState* states(int k) const { return &states_[static_cast<std::size_t>(k) * m_]; }

  int n_;
  double K_, EI_, l_;
  std::optional<ring::SectionLaw> section_;  ///< ring.plastic's law; empty: elastic
  std::size_t m_ = 0;                         ///< states per hinge
  std::vector<ring::PlasticState> states_;   ///< n m committed states, hinge by hinge
  std::vector<double> strains_;              ///< the committed strains (rad), for the plastic curvature
  double dissipated_ = 0.0;
};

}  // namespace multibody
