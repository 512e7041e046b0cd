// The energy-momentum integrator of the chain (response.integrator = "energy-momentum"):
// the same chain as chain.hpp, rewritten in natural coordinates, integrated by a scheme
// that conserves the energy balance exactly for any dt.
//
// ## The chain in natural coordinates
// Unknowns x = (x_0, y_0, ..., x_{n-1}, y_{n-1}): the hinge positions (ring-centred
// frame), hinge k resting at chain.hinge_rest(k). Segment i joins hinges i and i+1.
//  - Mass: a rigid bar's kinetic energy in its end velocities is
//    m/8 |v_i + v_{i+1}|^2 + Jr/(2 l^2) |v_{i+1} - v_i|^2 (its centre's translation and
//    its rotation; Jr = m l^2/12 with rotary inertia, 0 without), so M is constant and
//    banded (plus the corner that closes the ring).
//  - Constraints, quadratic or linear: link lengths c_i = (|x_{i+1} - x_i|^2 - l^2)/(2 l),
//    the pin (hinge 0 fixed, 2 rows), the roller (hinge r on the line through the pin and
//    its rest position, 1 row).
//  - Springs K/2 (theta_k - 2 pi/n)^2 on the turning angle between neighbouring segments,
//    theta_k = atan2(a x b, a . b) (exact for any rotation below pi between neighbours).
//  - The terms beyond the paper's ring, by hinge as attachments.hpp writes them: point
//    masses m I on their hinge's velocity (M stays constant); the foundation's and the
//    supports' springs u_k^T B_k u_k / 2 (quadratic); kr and the clamp on the mean rotation of
//    the hinge's two links (an angle spring like K's); further pins (2 linear rows each). A
//    point mass's rotary inertia is refused: its hinge rotation is an unknown of the angle
//    paths only (HingeInertias).
//  - The loads times f(t) (loading.hpp): their hinge gradients dPi/dp, constant for point
//    loads, gravity and dead pressure, configuration-dependent for follower and central
//    pressure (with their Jacobian blocks).
//
// ## The scheme (Gonzalez 1996 discrete gradient; Betsch 2005 for the constraints)
//   M (v_{n+1} - v_n) / h = F - grad_d V(x_n, x_{n+1}) - G(x_m)^T lambda,
//   (x_{n+1} - x_n) / h = (v_n + v_{n+1}) / 2,   c(x_{n+1}) = 0,   x_m = (x_n + x_{n+1})/2,
// with grad_d V the sum over springs of each spring's discrete gradient on its own six
// coordinates: grad V_k(y_m) + (V_k(y_{n+1}) - V_k(y_n) - grad V_k(y_m) . dy) dy / |dy|^2
// (for the quadratic terms, their midpoint gradient), and F = -f(t_{n+1/2}) dPi(x_m).
// Then dV = grad_d V . dx exactly, and because c is quadratic G(x_m) dx = c(x_{n+1}) -
// c(x_n) = 0: the constraint forces do no work, and T + V - W is conserved to the Newton
// tolerance for any dt (W summed as F . dx, the scheme's own work). Second
// order. Newton on (x_{n+1}, lambda) with the exact Jacobian (the discrete gradient's
// included): quadratic convergence. Damping is not offered (the scheme's point is the
// undamped balance; use newmark).
//
// ## ring.plastic: the discrete gradient of the incremental potential
// A plastic hinge's spring energy is its incremental potential from the states committed at
// the start of the step (bending.hpp, ring/plastic.hpp): psi(e) = int M de along the return
// map, C1 and piecewise quadratic, whose gradient is the moment. Its discrete gradient makes
// the hinge's work over the step psi(e_{n+1}) - psi(e_n) = (stored energy after the step's
// commit) - (stored before) + (the step's plastic work), so kinetic + stored + dissipated - W
// is conserved to the Newton tolerance: what the discrete gradient means with dissipation is
// that the plastic work of each step is the part of the hinge's work that the committed
// state does not store. The states are committed at accepted steps only.
//
// Cost: per Newton iteration O(n) assembly and one banded LU with a border
// (natural::BandedKkt) of the (3n + supports) KKT matrix: O(n).
#pragma once

#include "multibody/dynamics.hpp"

namespace multibody {

/// Forced response with the energy-momentum scheme (see above); called by respond() for
/// response.integrator = energy_momentum, with the same inputs, checks and output.
/// Throws std::invalid_argument for damping, IntegrationFailure when a step fails even
/// after halving below controls.min_dt_factor dt, a value is not finite, or the ring
/// touches itself.
ring::TimeHistory respond_energy_momentum(const ring::RingSpec& spec, const ring::MultibodyOptions& options,
                                          const ring::ResponseOptions& response,
                                          const IntegrationControls& controls);

}  // namespace multibody
