// The elastic–plastic bending law of `ring.plastic` at one material point: a hinge of a
// chain (strain: the hinge rotation, stiffness EI / l), a node of a frame or a quadrature
// point of a beam (strain: the curvature, stiffness EI). Every solver integrates this one
// point law over its own discretization; the law itself is checked against its closed
// form (tests/ring/test_plastic.cpp).
//
// The law is bilinear: the force (moment) is k (e - e_p), e the strain and e_p its plastic
// part, inside the yield band |M - c| <= r; past the band the tangent is h k, h the scene's
// `hardening` (0: perfectly plastic). With H = h k / (1 - h) the hardening modulus:
//  - kinematic: the band's centre moves, c = H e_p, its half-width stays r = Y (Prager);
//  - isotropic: the band widens, c = 0, r = Y + H a, a the accumulated |de_p|.
// Both give the same monotonic curve; they differ on reversal (kinematic: the reversed
// yield at M - 2Y, the Bauschinger effect; isotropic: at -M).
//
// The state (e_p, a) is path dependent and changes only at a converged step (commit):
// between two committed states, the force at a trial strain e is the return map from the
// committed state (backward Euler, exact for a piecewise linear law), and its integral in
// e, `Point::potential`, is the incremental potential whose gradient is that force. A
// solver that assembles an energy (the FE beam, the chains' discrete gradients) assembles
// this potential in place of the elastic energy; it is C1 and piecewise quadratic in e.
#pragma once

#include <cmath>

namespace ring {

/// `ring.plastic` of a scene.
struct Plastic {
  enum class Law { resultant, fibre };
  enum class Rule { kinematic, isotropic };
  Law law = Law::resultant;
  double moment = 0.0;     ///< resultant law: the plastic moment Mp, N m
  double stress = 0.0;     ///< fibre law: the yield stress sigma_y, Pa
  double hardening = 0.0;  ///< the tangent past yield over the elastic one, [0, 1)
  Rule rule = Rule::kinematic;
};

/// The path-dependent state of one material point.
struct PlasticState {
  double plastic = 0.0;      ///< e_p, the plastic strain (rad for a hinge, 1/m for a curvature)
  double accumulated = 0.0;  ///< a, the accumulated |de_p| (isotropic hardening's variable)
};

/// The bilinear law of one point: stiffness k, yield force Y, hardening h, rule.
class BilinearLaw {
 public:
  BilinearLaw(double stiffness, double yield, double hardening, Plastic::Rule rule)
      : k_(stiffness), yield_(yield), h_(hardening), H_(hardening * stiffness / (1.0 - hardening)),
        kinematic_(rule == Plastic::Rule::kinematic) {}

  /// The force, tangent and incremental potential at the trial strain e from a committed state.
  struct Point {
    double force = 0.0;      ///< M(e), N m
    double tangent = 0.0;    ///< dM/de: k inside the band, h k past it
    double potential = 0.0;  ///< the integral of M from the committed e_p to e, J
    bool yielding = false;   ///< e is past the band: committing it changes the state
  };

  Point at(const PlasticState& s, double e) const {
    const double c = kinematic_ ? H_ * s.plastic : 0.0;
    const double r = yield_ + (kinematic_ ? 0.0 : H_ * s.accumulated);
    const double hi = s.plastic + (c + r) / k_, lo = s.plastic + (c - r) / k_;
    Point p;
    if (e > hi || e < lo) {
      const double edge = e > hi ? hi : lo, f = e > hi ? c + r : c - r, x = e - edge;
      const double y = edge - s.plastic;
      p.force = f + h_ * k_ * x;
      p.tangent = h_ * k_;
      p.potential = 0.5 * k_ * y * y + f * x + 0.5 * h_ * k_ * x * x;
      p.yielding = true;
    } else {
      const double y = e - s.plastic;
      p.force = k_ * y;
      p.tangent = k_;
      p.potential = 0.5 * k_ * y * y;
    }
    return p;
  }

  /// The state after a step converged at strain e.
  PlasticState commit(const PlasticState& s, double e) const {
    const Point p = at(s, e);
    if (!p.yielding) return s;  // elastic: the state stays (e - k (e - e_p) / k would drift by round-off)
    const double plastic = e - p.force / k_;
    return {plastic, s.accumulated + std::abs(plastic - s.plastic)};
  }

  /// The plastic work of the step from the committed state s to the converged strain e,
  /// the integral of M de_p along it (the force moves linearly with e_p while it flows), J.
  double dissipated(const PlasticState& s, double e) const {
    const Point p = at(s, e);
    if (!p.yielding) return 0.0;
    const double plastic = e - p.force / k_;
    const double edge_force = p.force - h_ * k_ * (plastic - s.plastic) / (1.0 - h_);
    return 0.5 * (edge_force + p.force) * (plastic - s.plastic);
  }

  /// The elastic energy stored at strain e in state s (the committed one): M^2 / (2k), J.
  double stored(const PlasticState& s, double e) const {
    const double y = e - s.plastic;
    return 0.5 * k_ * y * y;
  }

  double stiffness() const { return k_; }

 private:
  double k_, yield_, h_, H_;
  bool kinematic_;
};

}  // namespace ring
