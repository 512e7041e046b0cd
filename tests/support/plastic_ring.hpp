// The thin ring pinched by two opposite point loads P, elastic–perfectly plastic with the
// resultant law (plastic moment Mp, ring.plastic.moment, hardening 0), at small
// displacement: classical limit analysis with the unit-load theorem (Hodge, "Plastic
// Analysis of Structures", 1959, ch. 3; the elastic part is Roark's ring case 1).
//
// A quarter from the load (theta = 0) to the line of the other diameter (theta = pi/2)
// carries M(theta) = M0 - (P R / 2) sin(theta); symmetry keeps both ends from rotating.
//  - Elastic: int M dtheta = 0 over the quarter gives M0 = P R / pi, largest at the loads,
//    so the first hinges form under the loads at P_y = pi Mp / R. The closing of the two
//    load points is delta = (pi/4 - 2/pi) P R^3 / EI.
//  - With hinges under the loads M0 = Mp, and the unit-load theorem with the released
//    quarter's virtual moment m = -(R/2) sin(theta) (zero at the hinge, so the hinge's
//    rotation does no virtual work) gives delta = (2 R^2 / EI)(pi P R / 8 - Mp), until
//    M(pi/2) = Mp - P R / 2 reaches -Mp: the four-hinge mechanism at P_c = 4 Mp / R.
//  - The hinges' rotation: each quarter's end sections stay parallel, so half a hinge's
//    rotation balances the quarter's bending, phi / 2 + (R / EI) int M dtheta = 0, giving
//    phi = (R / EI)(P R - pi Mp); the plastic work of the two hinges is 2 Mp phi.
//  - Unloading from P* is elastic: the residual closing is delta(P*) - (pi/4 - 2/pi) P* R^3 / EI
//    and the residual moment under the loads Mp - P* R / pi.
// Geometrically exact models deviate from these by O(delta / R): keep Mp R / EI small.
#pragma once

#include <cmath>
#include <optional>
#include <utility>
#include <vector>

#include "ring/analysis.hpp"
#include "support/paper.hpp"

namespace ringtest {

struct PinchedPlasticRing {
  double R, EI, Mp;
  double first_yield() const { return M_PI * Mp / R; }  ///< P_y, N
  double collapse() const { return 4.0 * Mp / R; }      ///< P_c, N
  double elastic_closing(double P) const { return (M_PI / 4.0 - 2.0 / M_PI) * P * R * R * R / EI; }
  /// The closing of the load points under P in [0, P_c], m.
  double closing(double P) const {
    return P <= first_yield() ? elastic_closing(P) : 2.0 * R * R / EI * (M_PI * P * R / 8.0 - Mp);
  }
  /// The rotation of each hinge under the loads at P in [P_y, P_c], rad.
  double hinge_rotation(double P) const { return P <= first_yield() ? 0.0 : R / EI * (P * R - M_PI * Mp); }
  /// The plastic work done when loaded to P in [0, P_c] (unloading adds none), J.
  double dissipated(double P) const { return 2.0 * Mp * hinge_rotation(P); }
  /// The closing left after loading to P* (<= P_c) and unloading, m.
  double residual_closing(double P) const { return closing(P) - elastic_closing(P); }
  /// The moment left under the loads after loading to P* (in [P_y, P_c]) and unloading, N m.
  double residual_moment(double P) const { return Mp - P * R / M_PI; }
  /// Past collapse, at large deflection, rigid–plastic: the four hinges stay where they formed
  /// (under the loads and on the other diameter) and each quarter turns rigidly by phi about
  /// its hinge on the other diameter. The closing is c = 2 R (1 - cos phi + sin phi), each
  /// hinge turns by 2 phi, and virtual work P dc = 8 Mp dphi gives the falling mechanism load
  ///   P(c) = 4 Mp / (R sqrt(2 - (1 - c / (2 R))^2)),
  /// P_c at c = 0 and P_c / sqrt(2) at c = 2 R (the mechanism of point loads; DeRuntz & Hodge's
  /// plates make hinges that travel instead). The elastic–plastic ring's curve is this one moved
  /// right by its elastic closing at collapse (of order Mp R^2 / EI): on a falling load, just above
  /// it (measured 1e-5 of P_c above it in the FE beam and the lumped chain at Mp R / EI = 1e-4).
  double mechanism_load(double c) const {
    const double a = 1.0 - c / (2.0 * R);
    return 4.0 * Mp / (R * std::sqrt(2.0 - a * a));
  }
  /// Crushed between two rigid, frictionless plates instead (DeRuntz & Hodge, "Crushing of a tube
  /// between rigid plates", J. Appl. Mech. 30, 1963), rigid–plastic at large deflection: each
  /// quarter is flat on its plate from the contact's middle to a travelling hinge, then a rigid
  /// arc of radius R and angle alpha (pi/2 at rest) down to a stationary hinge on the other
  /// diameter, which lies R (1 - cos alpha) below the plate: the plates' approach is
  /// c = 2 R cos alpha (c / D = cos alpha, D = 2 R). A hinge travelling over the arc dissipates Mp / R per length
  /// flattened, R |d alpha| per quarter, and the stationary hinge Mp |d alpha| per quarter, so
  /// P dc = 8 Mp |d alpha| gives
  ///   P(c) = (4 Mp / R) / sqrt(1 - (c / D)^2),
  /// rising from P_c (a point load's mechanism falls instead), and each plate touches the ring
  /// over the flat length 2 R asin(c / D).
  double plates_load(double c) const {
    const double x = c / (2.0 * R);
    return 4.0 * Mp / (R * std::sqrt(1.0 - x * x));
  }
  double plates_contact_length(double c) const { return 2.0 * R * std::asin(c / (2.0 * R)); }
};

/// The paper ring pinned at 270 deg and driven at 90 deg (static.displacement): the pinch by
/// displacement control, with the resultant law's Mp = mp EI / R, perfectly plastic (none:
/// elastic). The driven point holds the ring as a second pin.
inline ring::RingSpec driven_plastic_ring(std::optional<double> mp) {
  ring::RingSpec s = pinned_ring(270.0);
  if (mp) {
    s.plastic = ring::Plastic{};
    s.plastic->moment = *mp * s.EI() / s.radius;
  }
  return s;
}

/// The statics of the driven pinch: the point at 90 deg moved down by `closing` (m), the
/// points at 90 and 0 deg recorded, along `history` (default: to the full closing), `steps`
/// increments per leg. The reaction there is (0, -P), P the pinching force.
inline ring::StaticOptions driven_pinch(double closing, std::vector<double> history = {}, int steps = 20) {
  ring::StaticOptions st;
  st.displacement = ring::StaticOptions::Displacement{90.0, {0.0, -closing}};
  st.record = {90.0, 0.0};
  st.history = std::move(history);
  st.path = true;
  st.steps = steps;
  return st;
}

/// The paper ring pinned at 0 and on a roller at 180 (the pinch's supports), with the resultant
/// law's Mp = mp EI / R, perfectly plastic, kinematic (none: elastic).
inline ring::RingSpec pinched_plastic_ring(std::optional<double> mp) {
  ring::RingSpec s = pinned_ring(0.0);
  s.supports.roller = 180.0;
  if (mp) {
    s.plastic = ring::Plastic{};
    s.plastic->moment = *mp * s.EI() / s.radius;
  }
  return s;
}

/// The statics of the pinch: P (N) toward the centre at 90 and 270 deg, both recorded, along
/// `history` (default: loaded and unloaded) in `steps` increments per leg.
inline ring::StaticOptions pinch(double P, std::vector<double> history = {1.0, 0.0}, int steps = 20) {
  ring::StaticOptions st;
  st.loads.points = {{90.0, {0.0, -P}}, {270.0, {0.0, P}}};
  st.record = {90.0, 270.0};
  st.history = std::move(history);
  st.steps = steps;
  return st;
}

}  // namespace ringtest
