// The bending law of the lumped models, written once (issue 45, item 2): the chain's hinge
// springs (chain.cpp, springs) and the frames' element bending (frame.cpp, frame_element)
// both evaluate their bending moment here, elastic or elastic–plastic (`ring.plastic`,
// ring/plastic.hpp, the resultant law).
//
// Both models bend through a rotation measured across one length l = 2 pi R / n:
//  - chain, point j = hinge j: the turning angle between the links j-1 and j minus its rest
//    value 2 pi / n;
//  - frames, point j = element j (node j to j + 1): the section rotation difference
//    th_{j+1} - th_j, linear in the unknowns. The element's bending energy 1/2 t^T Kb t
//    (t the end rotations relative to the chord, frame.hpp) splits, Kb having equal diagonal
//    terms, into the constant-curvature mode u = t2 - t1 = th_{j+1} - th_j with the stiffness
//    (Kb00 - Kb01) / 2 = EI / l for every variant (the shear does not enter a pure bending
//    mode) and the linearly varying mode v = t1 + t2 with (Kb00 + Kb01) / 2 (3 EI / l for
//    the Hermite element, 3 EI / ((1 + phi) l) for Przemieniecki's), which carries the shear
//    and stays elastic. So u / l is the element's mean curvature, its law the moment at the
//    element's midpoint: the law at one point per element. The frames take the elastic law
//    only for now: checks.cpp (check_plastic) says why a plastic one would be wrong there.
// At every point the moment M(e) of the rotation e is ring::BilinearLaw with the stiffness
// k = EI / l (moment per rotation, N m/rad), the yield moment Mp and the scene's hardening and
// rule: e / l is the curvature, k l = EI. Without `ring.plastic` the yield is infinite and
// the law is k e (nothing changes).
//
// The state (one ring::PlasticState per point) is committed only at an accepted equilibrium
// (commit(), from the statics' paths::Equilibrium::accept); every other evaluation is the
// return map from the committed state, so a rejected Newton solve leaves nothing behind.
// The dissipated energy is the sum of the law's plastic work of every committed step.
//
// Cost: O(1) per point evaluation, O(points) per commit; memory O(points).
#pragma once

#include <vector>

#include "ring/plastic.hpp"
#include "ring/spec.hpp"

namespace lumped {

class Bending {
 public:
  Bending() : law_(0.0, 0.0, 0.0, ring::Plastic::Rule::kinematic) {}
  /// \param points the number of material points (hinges or elements), n
  /// \param length the length each point's rotation is measured across, l = 2 pi R / n, m
  /// \param stiffness the moment per rotation, EI / l, N m/rad
  /// ring.plastic (spec.plastic) gives Mp, the hardening and the rule; without it the law is
  /// linear. The caller has checked the plastic data (checks.hpp).
  Bending(const ring::RingSpec& spec, int points, double length, double stiffness);

  /// The moment at point i at the trial rotation e from the committed state: M (N m), dM/de
  /// (N m/rad) and the incremental potential whose derivative is M (J; 1/2 k e^2 when
  /// elastic from a virgin state).
  ring::BilinearLaw::Point at(int i, double e) const { return law_.at(state_[static_cast<std::size_t>(i)], e); }

  /// The equilibrium with the rotations e (one per point) is accepted: adds the plastic
  /// work of the step and commits every point's state. O(points).
  void commit(const std::vector<double>& e);

  /// The elastic energy stored at the rotations e in the committed states, J. O(points).
  double stored(const std::vector<double>& e) const;

  bool plastic() const { return plastic_; }
  /// The committed plastic rotation e_p of point i, rad.
  double plastic(int i) const { return state_[static_cast<std::size_t>(i)].plastic; }
  double stiffness() const { return law_.stiffness(); }
  /// The plastic work of every committed step so far, J.
  double dissipated() const { return dissipated_; }
  /// The largest |plastic rotation| / l over the points, 1/m (ring::PathPoint's measure).
  double plastic_curvature() const;

 private:
  ring::BilinearLaw law_;
  std::vector<ring::PlasticState> state_;
  double length_ = 0.0;
  bool plastic_ = false;
  double dissipated_ = 0.0;
};

}  // namespace lumped
