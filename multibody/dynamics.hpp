// Geometrically nonlinear forced response of the rigid-segment chain (the paper's
// section 5, its equations 20 and 29), by implicit time integration of the index-3
// differential-algebraic equations
//
//   M(phi) phi'' + xi(phi, phi') + C phi' + K theta + G(phi)^T lambda = Phi(phi, t),
//   g(phi) = 0,
//
// phi the n segment angles, theta = phi - phi0, M the mass matrix of eq. (12),
// xi its quadratic velocity terms, K the cyclic hinge springs, C optional damping
// (Rayleigh a M0 + b K about the undeformed chain, plus dampers c at every hinge),
// Phi the generalized force of a dead point load, and g the closure (13) plus,
// with a roller, the condition that the roller point stays on the line through the
// pin and itself (29). All kinematics come from multibody/chain.hpp unchanged.
//
// The constraints are imposed on the positions at every step (index 3, Lagrange
// multipliers; Newton drives g(phi_{n+1}) to round-off, no drift). Integrators:
//  - newmark: average acceleration, beta = 1/4, gamma = 1/2 (the paper's method;
//    conserves energy for linear systems, keeps spurious high-frequency oscillation);
//  - generalized-alpha: Chung & Hulbert (1993) parameters from rho_inf, in the form
//    of Arnold & Bruls (2007, Multibody Syst. Dyn. 18:185) for index-3 DAEs:
//    equilibrium and constraints at t_{n+1}, a pseudo-acceleration a with
//    (1 - alpha_m) a_{n+1} + alpha_m a_n = (1 - alpha_f) phi''_{n+1} + alpha_f phi''_n,
//    and consistent initial accelerations (the index-1 problem at t = 0).
// The constraint rows of the Newton matrix are scaled by 1/(beta h^2) (Bottasso,
// Bauchau & Cardona 2007) so that its conditioning does not grow as h -> 0.
// A step whose Newton iteration fails is rejected and halved (and the step grows
// back, at most doubling, after successes); below `min_dt` an IntegrationFailure is
// thrown, as it is when non-adjacent segments intersect (the ring touches itself).
#pragma once

#include <string>

#include "ring/errors.hpp"
#include "ring/results.hpp"
#include "ring/scene.hpp"
#include "ring/spec.hpp"

namespace multibody {

/// A time integration that could not go on; carries what was computed up to the
/// failure (exit code 3 through ring::NumericalError).
class IntegrationFailure : public ring::NumericalError {
 public:
  enum class Reason { step_too_small, self_contact, not_finite };
  IntegrationFailure(Reason reason, double t_reached, ring::TimeHistory partial,
                     const std::string& what)
      : ring::NumericalError(what), reason_(reason), t_(t_reached), partial_(std::move(partial)) {}
  Reason reason() const { return reason_; }
  /// Time of the last accepted step, s.
  double t_reached() const { return t_; }
  /// The history up to t_reached (every accepted step).
  const ring::TimeHistory& partial() const { return partial_; }

 private:
  Reason reason_;
  double t_;
  ring::TimeHistory partial_;
};

/// Knobs of the nonlinear solver that a scene does not set (defaults suit the paper).
struct IntegrationControls {
  int max_newton = 12;          ///< Newton iterations before a step is rejected
  double min_dt_factor = 1e-6;  ///< smallest step, as a fraction of the requested dt
  /// Convergence: |increment| <= tol_q (rad) and |g| <= tol_g (m, scaled by the segment)
  double tol_q = 1e-9;
  int snapshots = 6;            ///< deformed shapes stored, evenly spaced in [0, t_end]
  bool check_contact = true;    ///< test non-adjacent segments for intersection each step
};

/// Forced response from rest in the undeformed state (phi = phi0, phi' = 0).
/// Requires a pin (and normally a roller; without one the rigid rotation about the
/// pin is left to the dynamics). The load acts at `response.load.angle`, which must be
/// a hinge of the chain; the recorded angles must be hinges too.
/// Records one entry per requested step dt (t = 0 first; halved sub-steps are not
/// recorded): displacements of the recorded points (ring-centred frame, m), kinetic
/// energy T, hinge spring energy V, work of the load W (trapezoidal in time), energy
/// balance error T + V + D - W (J; D the energy dissipated by damping), constraint
/// residual max |g| (m), Newton iterations of the step (summed over sub-steps).
/// Cost per step: O(n^3) for the dense Newton solve times the iterations (about 3).
/// Throws std::invalid_argument for a spec/options that can never work (no pin, odd
/// n with a roller, dt <= 0, rho_inf outside [0, 1], load not on a hinge) and
/// IntegrationFailure (a ring::NumericalError) when the integration cannot continue.
ring::TimeHistory respond(const ring::RingSpec& spec, const ring::MultibodyOptions& options,
                          const ring::ResponseOptions& response,
                          const IntegrationControls& controls = {});

}  // namespace multibody
