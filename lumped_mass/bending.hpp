// The bending law of the lumped models, written once (issue 45, item 2; issue 47): the
// chain's hinge springs (chain.cpp, springs; the response's discrete gradient, step_moment)
// and the frames' element bending (frame.cpp, frame_element) both evaluate their bending
// moment here, elastic or elastic–plastic (`ring.plastic`: ring/plastic.hpp, the resultant
// law; ring/section_law.hpp, the fibre law).
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
// At every point the moment M(e) of the rotation e is the law of a segment of length l at the
// uniform curvature e / l:
//  - elastic (no `ring.plastic`): k e, k = EI / l (ring::BilinearLaw with an infinite yield);
//  - resultant (`moment = Mp`): ring::BilinearLaw on the rotation with the stiffness k, the
//    yield moment Mp and the scene's hardening and rule, one ring::PlasticState per point (its
//    plastic rotation, rad). This is ring::HingeLaw over the resultant ring::SectionLaw (the
//    same law with its strain e / l) rewritten on e, kept so because its arithmetic inside the
//    band is the elastic spring's, k e: Mp -> infinity gives the elastic chain bit for bit
//    (tests/lumped_mass/plastic_test.cpp asserts it; EI (e / l) and (EI / l) e round apart);
//  - fibre (`stress = sigma_y`): ring::HingeLaw(section, l) over the one ring::SectionLaw of
//    the spec, ring::SectionLaw::kFibres states per point (the fibres' plastic strains).
//
// The state (states() ring::PlasticStates per point, point-major) is committed only at an
// accepted equilibrium or time step (commit(), from the statics' paths::Equilibrium::accept
// and the response's accepted steps); every other evaluation is the return map from the
// committed state, so a rejected Newton solve leaves nothing behind. The dissipated energy is
// the sum of the law's plastic work of every committed step.
//
// Cost: O(states()) per point evaluation (1, or 64 fibres), O(points states()) per commit;
// memory O(points states()).
#pragma once

#include <optional>
#include <vector>

#include "ring/plastic.hpp"
#include "ring/section_law.hpp"
#include "ring/spec.hpp"

namespace lumped {

class Bending {
 public:
  Bending() : law_(0.0, 0.0, 0.0, ring::Plastic::Rule::kinematic) {}
  /// \param points the number of material points (hinges or elements), n
  /// \param length the length each point's rotation is measured across, l = 2 pi R / n, m
  /// \param stiffness the moment per rotation, EI / l, N m/rad (the fibre law's is the
  ///        section's EI / l)
  /// ring.plastic (spec.plastic) gives the law; without it the law is linear. The caller has
  /// checked the plastic data (checks.hpp); a fibre law needs a section with a shape.
  Bending(const ring::RingSpec& spec, int points, double length, double stiffness);

  /// The moment at point i at the trial rotation e from the committed state: M (N m), dM/de
  /// (N m/rad) and the incremental potential whose derivative is M (J; 1/2 k e^2 when
  /// elastic from a virgin state).
  ring::BilinearLaw::Point at(int i, double e) const {
    if (section_) return ring::HingeLaw(*section_, length_).at(state(i), e);
    return law_.at(*state(i), e);
  }

  /// The equilibrium with the rotations e (one per point) is accepted: adds the plastic
  /// work of the step and commits every point's state. O(points states()).
  void commit(const std::vector<double>& e);

  /// The elastic energy stored at the rotations e in the committed states, J. O(points states()).
  double stored(const std::vector<double>& e) const;

  bool plastic() const { return plastic_; }
  /// The fibre law: no single plastic rotation per point (plastic(i) is not defined).
  bool fibre() const { return section_.has_value(); }
  /// The committed plastic rotation e_p of point i, rad (elastic or resultant law).
  double plastic(int i) const { return state(i)->plastic; }
  double stiffness() const { return law_.stiffness(); }
  /// The plastic work of every committed step so far, J.
  double dissipated() const { return dissipated_; }
  /// The largest |plastic curvature| over the points at the committed rotations, 1/m
  /// (ring::PathPoint's measure): the resultant law's e_p / l; the fibre law's kappa - M / EI
  /// (the curvature left when the section is unloaded elastically). O(points states()).
  double plastic_curvature() const;

 private:
  const ring::PlasticState* state(int i) const { return &state_[static_cast<std::size_t>(i * states_)]; }
  ring::BilinearLaw law_;                    ///< elastic or resultant, on the rotation
  std::optional<ring::SectionLaw> section_;  ///< the fibre law, on the curvature e / l
  int states_ = 1;
  std::vector<ring::PlasticState> state_;  ///< states_ per point, point-major
  std::vector<double> committed_;          ///< the fibre law: the rotations of the last commit
  double length_ = 0.0;
  bool plastic_ = false;
  double dissipated_ = 0.0;
};

}  // namespace lumped
