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
// The constraints hold on the positions at every step to round-off (no drift), in
// one of two ways:
//  - newmark: average acceleration, beta = 1/4, gamma = 1/2 (the paper's method),
//    applied as the paper does to its reduced equations (18-20): coordinate
//    partitioning. The c dependent angles are the best-conditioned columns of G at the
//    start of each step (column-pivoted QR), the Newmark formulas act on the others,
//    and g(phi) = 0, G phi' = 0, G phi'' + Gdot phi' = 0 give the dependent positions,
//    velocities and accelerations exactly (Newmark with gamma = 1/2 applied to the
//    index-3 form with multipliers is unstable: Cardona & Geradin 1989). It starts from
//    the accelerations filtered by the first step's Newton matrix, as generalized-alpha's
//    a_0 below.
//  - generalized-alpha: Chung & Hulbert (1993) parameters from rho_inf, on the index-3
//    form with multipliers, as Arnold & Bruls (2007, Multibody Syst. Dyn. 18:185):
//    equilibrium and constraints at t_{n+1}, a pseudo-acceleration a with
//    (1 - alpha_m) a_{n+1} + alpha_m a_n = (1 - alpha_f) phi''_{n+1} + alpha_f phi''_n,
//    consistent initial accelerations phi''_0 (the index-1 problem at t = 0), and a_0
//    from the first step's Newton matrix S: S a_0 = c (M phi''_0) with the constraints,
//    c = (1 - alpha_m) / ((1 - alpha_f) beta h^2); per mode a_0 = c phi''_0 / (c + w^2)
//    (why not a_0 = phi''_0: integrators.hpp, starting_pseudo_acceleration).
// Both solve, per Newton iteration, the saddle-point system [T G^T; G 0] with T the
// analytic tangent of dynamics_model.hpp; rows of g and columns of lambda are scaled by
// max|T_jj| / l (Bottasso, Bauchau & Cardona 2007) so that the conditioning does not grow
// as h -> 0. (For newmark the multipliers follow from the dependent rows and T gains a
// rank-c term, the dependent rates' change with q, applied by Woodbury's formula, so its
// Newton is quadratic too; integrators.hpp.) Both run the one Newton (paths/newton.hpp)
// with its reuse policy: a factorized matrix kept from the previous step serves the first
// iteration of a step and is then refreshed; within a step it is kept while each iteration
// shrinks the correction at least 8-fold (modified Newton) and, for newmark, while the
// corrections stay below 1e-3 rad.
// Predictor: constant velocity. Convergence: correction <= tol_q (rad) and, for the
// index-3 form, |g| <= 1e-12 R. A step whose Newton iteration fails (max_newton
// iterations, a correction > 0.5 rad, a non-finite value) is retried once with a fresh
// matrix, then halved; the step grows back (doubling after two successes) and sub-steps
// end exactly on the recorded grid. Below min_dt an IntegrationFailure is thrown, as it
// is when non-adjacent segments come closer than the section depth (the ring touches
// itself; the model has no contact).
// The Timoshenko chain (ring.theory = "timoshenko", sections.hpp; dense path, newmark and
// generalized-alpha): the unknowns are (phi, gamma), the shear angles with the section's
// rotary inertia rho I l on psi = phi + gamma and the bending springs between the sections'
// rotations; the same integrators and policies run on the 2n unknowns (the constraints do
// not involve gamma; newmark's dependent coordinates are angles phi).
// MultibodyOptions: n, rotary_inertia and method are used; `dependent` is not (the
// partition is chosen by pivoting at every step).
// method (backend.hpp, Analysis::response): the dense backend forms the n x n tangent
// (O(n^2) per Newton iteration, O(n^3) per factorization); the banded one keeps the same
// equations, iterates and policies in O(n) time and memory per iteration
// (dynamics_sparse.hpp) and tests self-contact on a uniform grid. Both implement
// newton_backend.hpp, chosen once per run, and give the same histories to ~1e-12 of the
// peak displacement (tests at n = 40, 160, 1280); the steps are in integrators.hpp.
#pragma once

#include <string>

#include "multibody/linear_model.hpp"
#include "paths/newton.hpp"
#include "paths/time_stepping.hpp"
#include "ring/errors.hpp"
#include "ring/results.hpp"
#include "ring/analysis.hpp"
#include "ring/spec.hpp"

namespace multibody {

/// The integration failure every solver throws (ring/errors.hpp).
using IntegrationFailure = ring::IntegrationFailure;

/// Knobs of the nonlinear solver that a scene does not set (defaults suit the paper).
struct IntegrationControls {
  int max_newton = paths::kNewtonCap;  ///< Newton iterations before a step is rejected (the one cap)
  double min_dt_factor = 1e-6;  ///< smallest step, as a fraction of the requested dt
  /// Newton converged when the correction is <= tol_q (rad) (and, index 3, |g| <= 1e-12 R)
  double tol_q = 1e-9;
  int snapshots = 6;            ///< deformed shapes stored, evenly spaced in [0, t_end]
  /// test non-adjacent segments for contact each step (O(n^2) box loop below 128
  /// segments, a uniform grid above: O(n); same result)
  bool check_contact = true;
};

/// Forced response from rest in the undeformed state (phi = phi0, phi' = 0).
/// Requires a pin (and normally a roller; without one the rigid rotation about the
/// pin is left to the dynamics). Point loads act at points that must be hinges of the
/// chain (as must point masses and supports); the recorded angles must be hinges too.
/// Records one entry per requested step dt (t = 0 first; halved sub-steps are not
/// recorded): displacements of the recorded points (ring-centred frame, m), kinetic
/// energy T, hinge spring energy V, work of the load W (trapezoidal in time), energy
/// balance error T + V + D - W (J; D the energy dissipated by damping, midpoint rule
/// per step), constraint
/// residual max |g| (m), Newton iterations of the step (summed over sub-steps).
/// Cost per step: dense path O(n^2) per Newton iteration plus an O(n^3) factorization
/// whenever the kept Newton matrix is refreshed; sparse path O(n) per iteration; 3 to 4
/// Newton iterations per step (times and counts: docs/measured.md, "multibody: forced
/// response").
/// Throws std::invalid_argument for a spec/options that can never work (no pin, odd
/// n with a roller, dt <= 0, rho_inf outside [0, 1], load not on a hinge) and
/// IntegrationFailure (a ring::NumericalError) when the integration cannot continue.
ring::TimeHistory respond(const ring::RingSpec& spec, const ring::MultibodyOptions& options,
                          const ring::ResponseOptions& response,
                          const IntegrationControls& controls = {});

/// respond() of the Timoshenko chain (spec.theory = timoshenko) with its section constants
/// given instead of Shear::of(spec, l) (for tests and studies: e.g. the section's rotary
/// inertia rho I l off). Same checks and cost.
ring::TimeHistory respond(const ring::RingSpec& spec, const ring::MultibodyOptions& options,
                          const ring::ResponseOptions& response, const IntegrationControls& controls,
                          const Shear& shear);

namespace detail {
/// The time-stepping driver's grid of a response (paths/time_stepping.hpp) under the
/// chain's controls, with `guard` and `who` for the messages.
paths::Grid response_grid(const ring::ResponseOptions& response, const IntegrationControls& controls,
                          ring::EnergyGuard& guard, const std::string& who);
}  // namespace detail

}  // namespace multibody
