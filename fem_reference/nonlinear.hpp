// Geometrically exact FE beam of the ring: nonlinear statics and forced response on
// deal.II. NO deal.II includes here (see modes.hpp).
//
// ## Formulation (planar extensible Kirchhoff rod; no small-rotation assumption anywhere)
// The mesh, the fields and the constraints are the linear model's on the exact circle
// (modes.hpp): tangential u (degree p+1) and radial w (degree p) as functions of the polar
// angle theta, so the current centreline is x(theta) = X(theta) + u t0 + w n0 with
// X = R n0, n0 = (cos, sin) theta, t0 = (-sin, cos) theta. The polar basis is fixed in
// time, so the kinetic energy rho A/2 int |x_t|^2 ds0 gives the linear model's constant
// consistent mass matrix. With ' = d/dtheta and s0 = R theta the rest arc length,
//   a = dx/ds0 = (1 + (u' + w)/R) t0 + ((w' - u)/R) n0 =: a_t t0 + a_n n0   (exact),
//   stretch |a|, axial strain eps = |a| - 1,
//   tangent angle phi = atan2(-a_n, a_t) (counter-clockwise from t0),
//   curvature change kappa = dphi/ds0 = (a_n a_t' - a_t a_n') / (R |a|^2).
// Strain energy  V = int (EA/2 eps^2 + EI/2 kappa^2) ds0
//                  + sum_vertices ( {EI kappa} [[phi]] + sigma EI / (2 h) [[phi]]^2 ),
// the symmetric interior penalty of the linear model written on the exact rotation jump
// [[phi]] = phi_right - phi_left: the angle between the two cells' tangents at a vertex,
// measured from the same t0, so the 2 pi the tangent angle gains around the ring never
// enters (phi is never unwrapped). No shear: the rod is Euler-Bernoulli (shear-rigid);
// linearized about the rest state V is exactly the linear model's energy, so the tangent
// at rest is its stiffness and the small-load limit is its modal superposition.
// Internal force and consistent tangent are the exact gradient and Hessian of V (closed
// forms in ring_beam.cpp, checked against finite differences in the tests).
// Inextensible option (fem.extensible = false): EA -> beta EI / R^2; statics extrapolate
// the displacements from beta = 1e6 and 2e6 (error O(1/beta^2)), the response uses 1e7.
//
// ## Timoshenko (ring.theory = "timoshenko": the Reissner beam, reissner_beam.cpp)
// The linear Timoshenko model's mesh, fields and constraints (modes.hpp, "Timoshenko";
// timoshenko_model.hpp): u, w and the section's rotation psi, C0 FE_Q of degree p, psi
// counter-clockwise from the rest direction (the same sense as phi above, so that the
// linearized psi - phi is the linear model's shear gamma). With a = a_t t0 + a_n n0 as
// above (exact) and the directors d1 = cos psi t0 - sin psi n0 (the section's tangent),
// d2 = sin psi t0 + cos psi n0 (its normal), the strains of Reissner's (Simo's) rod:
//   axial G1 = a . d1 - 1 = a_t cos psi - a_n sin psi - 1,
//   shear G2 = a . d2 = a_t sin psi + a_n cos psi,
//   bending K = psi'/R (the director angle theta + psi, minus the rest curvature 1/R);
// each invariant under a rigid rotation (a turns, psi grows by the same angle).
// Linearized: G1 = (u' + w)/R = eps, G2 = psi + (w' - u)/R = gamma, K = kappa: the linear
// model's strains. Strain energy V = int (EA/2 G1^2 + kGA/2 G2^2 + EI/2 K^2) ds0 with the
// linear model's selective reduced integration: membrane and shear with p Gauss points,
// bending with p + 1 (exact), so the tangent at rest is exactly the linear model's
// stiffness (the second-order parts of G1, G2 meet G = 0 there) and the beam does not
// lock (measured: the same fitted order at d/R = 1e-3 and 0.1, fem_reissner_test).
// H1 fields, no interior penalty. Gradient and Hessian are closed forms in
// g = (a_t, a_n, psi) per reduced point (reissner_beam.cpp), checked against finite
// differences. Terms: a pin is u = w = 0, a clamp also psi = 0 (exact at any motion); kr
// of a spring acts on psi at the vertex, kr/2 psi^2 (exact); springs kx, ky, the
// foundation and every load are the Euler beam's code below (BeamPotential) on the
// model's rows of (x, a), integrated with p + 1 Gauss points (the linear foundation's).
// Mass: the linear model's, constant and exact: rho A on u, w, rho I on psi (the polar
// basis does not move, psi_t is the section's angular velocity), point masses m on the
// vertex's translation and J on its psi. Statics, response, linear buckling (buckling.hpp)
// and modes under load (preload.hpp) run the same drivers on the same tangent as the Euler
// beam (make_beam picks the model). The unknowns mix lengths (u, w) and angles (psi): the
// statics' basin (R/10 per step) and Newton's stop (1e-12 R), and the buckling's path step,
// count psi as the length R psi (BeamModel::lengths); the continuation's arc norm
// (paths/continuation.hpp) takes the unknowns as they are.
// Measured (tests/fem_reference/fem_reissner_test.cpp): see docs/measured.md, "fem_reference: the
// Reissner beam".
// Inextensible (fem.extensible = false) needs beta >> kGA R^2 / EI (about 4 (R/d)^2 for
// steel); otherwise the extrapolation error can exceed the shear correction.
//
// ## Terms and loads (beam_potential.hpp: one piece of code, used by statics and response)
// The equations are those of the total potential Pi(q; s) = V(q) - s Phi(q): V the stored
// energy, Phi the loads' potential at load factor 1 (statics: s the load factor;
// response: s = g(t)). Residual grad V - s grad Phi, tangent hess V - s hess Phi (the
// load stiffness -hess Phi of follower and central pressure included: Newton converges
// quadratically, and the tangent is symmetric because every load here has a potential).
// Every point lies on a vertex; every distributed term is integrated with the beam's own
// Gauss rule (p + 2 points per cell) in the local variables (x_t, x_n, a_t, a_n) of the
// current position x = u t0 + (R + w) n0 and the stretch a = dx/ds0 in the rest frame.
// Supports (RingModel's constraints, the linear model's, exact at any displacement):
//  - pin, further pins: u = w = 0 at the vertex; roller: the vertex stays on the line
//    through the pin and its rest position;
//  - clamp: the linear model's two rows phi = (u - w')/R = 0 on both cells' ends; at a
//    pinned vertex that is a_n = 0, i.e. the exact tangent angle atan2(-a_n, a_t) = 0.
// Stored energy V:
//  - the beam (above);
//  - springs: kx/2 Ux^2 + ky/2 Uy^2 on the vertex's Cartesian displacement (a spring to
//    the ground that keeps its global direction), kr/2 {phi}^2 with {phi} the mean of the
//    two cells' exact tangent angles at the vertex (phi_left + [[phi]]/2, the jump reduced
//    to (-pi, pi], as in the interior penalty); linearized, the linear model's terms;
//  - foundation: k_r/2 w^2 + k_t/2 u^2 per undeformed length, u and w the displacement
//    along the undeformed point's fixed tangential and radial directions (exact in the
//    polar fields: the same energy as the linear model's, at any displacement).
// Loads Phi (p the pressure, positive inward; ring::Pressure):
//  - point loads F at vertices and the point masses' weight m g: fixed forces, Phi = F . U;
//  - gravity on the beam: rho A g per undeformed length, Phi = int rho A g . U ds0;
//  - follower pressure, p per deformed length along the deformed inward normal: the force
//    p (R90 a) ds0, a = dx/ds0 turned by +90 deg (the inward normal times |a| on the
//    counter-clockwise ring). It is conservative on the closed ring: Phi = -p (A - A0),
//    A = 1/2 int (x cross a) ds0 = 1/2 int ((R + w) a_t - u a_n) ds0 the enclosed area,
//    whose first variation is int dx cross a ds0 after an integration by parts with no
//    boundary terms (x is continuous and periodic): exactly the force above. A is
//    quadratic in the fields: the load stiffness p hess A is constant and symmetric, and
//    the Gauss rule integrates A and its derivatives exactly;
//  - dead pressure: p n0 per undeformed length along the undeformed inward normal,
//    Phi = -p int w ds0;
//  - central pressure: p per undeformed length toward the centre from the deformed point,
//    -p x/|x| ds0: Phi = -p int (|x| - R) ds0, load stiffness p (I/|x| - x x^T/|x|^3).
// The mass matrix is the linear model's: the beam's consistent mass and the point masses
// (m on the vertex's Cartesian velocity: exact; J on the rate of the linear rotation
// {phi} = (u - w')/R, the rest linearization of the exact one: a constant mass matrix, exact
// for small rotations of the vertex, not for large ones).
// Measured against closed forms in tests/fem_reference/fem_loads_test.cpp: the shrunk
// circle of a pinned ring under follower and dead pressure (1.7e-13), the axisymmetric ring
// on a foundation under all three kinds (3e-13), spring reactions = the weight (1e-14), the
// inextensible ring's Fourier series under its weight, hung on a pin and clamped under a
// sideways weight (order 3.96 in elements at p = 3; 1e-7 at p = 6, the nonlinearity of the
// small load), the breathing under sudden pressure (3e-14).
//
// Record points must be vertices.
//
// ## Statics
// The equilibrium path from rest, s the load factor (loads s times statics.loads, full
// load at s = 1), with supports that hold every rigid motion (a regular tangent at rest),
// followed by the shared continuation driver (paths/continuation.hpp: load stepping,
// Crisfield's cylindrical arc length through limit points, the limit point located,
// self-contact as an end event). The beam supplies (static_path.cpp):
//  - the residual grad V(q) - s F(q), F = grad Phi, and the bordered tangent
//    [K - s hess Phi, -F; w^T ws], factorized as
//    a whole by UMFPACK: it is regular at a limit point, where K alone is singular
//    (block elimination with K^-1 would lose all digits there); q holds displacements
//    only, so the arc norm has one unit;
//  - its basin: no value of q moves more than R/10 in a step (near a limit point Newton
//    can otherwise land on a distant branch; and a maximum and a minimum of s are never
//    skipped together); Newton converged at a correction below 1e-12 R;
//  - self-contact along the chord between accepted equilibria (below).
// A path that does not reach the full load is a ring::NumericalError (self-contact, but a
// result with static.path; no return within 2000 arc steps, a stalled continuation); past
// a limit point the message reads "past a limit point at load factor L, the equilibrium
// path (arc-length continuation) ..." (every solver's wording: the driver's).
// Displacement control (static.displacement; no loads with it): the vertex at `at` is held
// at s times `value` by two Lagrange multipliers lambda on its Cartesian displacement G q
// (G^T f = BeamModel::vertex_force(k, f)): R = (grad V - G^T lambda, s v - G q), the bordered
// matrix's load column dR/ds = (0, v), lambda the force on the ring there (the result's and
// every path point's `reaction`); the arc measures q only, and the inertia and the critical
// direction are taken with the vertex's u and w held (the constraints' tangent space).
// Either beam, ring.plastic (its laws), static.path and static.history, fem.extensible = false
// and fem.reference (without static.path; the reference also watches the reaction).
// static_path.cpp (BeamEquilibrium) says why multipliers and not an inhomogeneous constraint.
// Rigid plates ([plates]; no loads, no supports): the penalty of ring::PlatePair is a term of
// the potential (BeamPotential: energy, pressure, tangent, dR/ds), and the two points of first
// contact keep their place along the plates by the same two multipliers (v = 0); the reaction
// is the force of the plate at plates.axis. Measured: tests/fem_reference/fem_plates_test.cpp
// (README, "Rigid plates"), which also says what is refused.
// Measured: tests/fem_reference/fem_driven_test.cpp (README, "Displacement control").
// Self-contact, after every accepted step: the deformed centreline, sampled at most
// depth/2 apart, as a closed polygon; two edges whose nearest ends are at least 2 depths
// apart along the ring and closer than the section depth (or crossing) have touched.
// The chord between two consecutive equilibria is checked at sub-steps that move no
// point by more than depth/2, so no part can pass through another unseen. The beam has
// no contact model: the path stops there.
// Inextensible (fem.extensible = false): both beta paths are traced; the result and the
// limit load factor are extrapolated in 1/beta.
// Measured (tests/fem_reference/fem_continuation_test.cpp), the paper's ring on a pin
// at 180 deg and a roller at 0 deg pressed at its crown (90 deg) toward the centre with
// P R^2/EI = 8: load stepping stops at s = 0.9523 (40 cubic elements), the continuation
// passes the limit (the crown 11.5 m down) and follows the crown down onto the bottom
// of the ring (contact at s = 0.8895, the crown 17.5 m down). Limit load factor, inextensible: 0.9541865 (p = 3), 0.9517778 (p = 4),
// 0.95176374 (p = 5), 0.95176371 (p = 6) on 40 elements; the multibody chain
// Richardson-extrapolated from n = 80, 160, 320: 0.9517637 (P R^2/EI = 7.6141);
// extensible (p = 5, 6): 0.9517406, 2.4e-5 lower. Where load stepping alone works
// (P R^2/EI = 7), continuation from rest reaches the same equilibrium to 2e-13 of the
// displacement.
// Cost: per Newton iteration an assembly and a sparse LU of the bordered matrix; per
// accepted step one more solve (the tangent) and a self-contact check, O(2 pi R / depth)
// expected (a uniform grid of buckets).
// Bifurcations: the count of the tangent's negative eigenvalues on the free unknowns
// (modal::frontal_inertia, O(N) per step; a dense count up to 1500 unknowns should the front
// outgrow its bound, static_path.cpp) lets the driver end a path at a bifurcation with its
// bracket: without static.path the continuation follows limit points on the primary path
// and ends at a bifurcation. With static.path (fem.reference and fem.extensible = false
// refused) the path switches branch along the least eigenvector of the tangent (dense, up to
// 1500 unknowns; above, the path ends at the bifurcation), the clearance of non-neighbouring
// parts of the centreline lets the driver bisect the touch, every accepted equilibrium is a
// ring::PathPoint, and a touch ends the path as a result (end = "contact: ...", end_load).
//
// ## Plasticity (ring.plastic: the resultant and the fibre law; statics and response)
// Euler-Bernoulli beam only (the Reissner beam refuses it by the key ring.plastic;
// plastic_points.hpp says why); the fibre law needs the section's shape (a section given by
// {area, inertia} is refused by ring.plastic.stress). At every bending point, the p + 1
// Gauss-Lobatto points of a cell, ends included (the membrane stays on the p + 2 Gauss points;
// plastic_points.hpp says why), the energy density EI/2 kappa^2 becomes the incremental
// potential of the section law (ring::SectionLaw: the resultant law's one state, or the fibre
// law's 64 fibres through the depth, each with its state) from the point's committed states,
// kappa the exact curvature change above: the internal force is M dkappa, the tangent
// dM/dkappa dkappa dkappa^T + M d2kappa (C1 and piecewise smooth in q: Newton converges in a
// few iterations past each change of the yielding set). The membrane strain stays elastic
// (the fibres see the bending strain y kappa only: SectionLaw has no axial strain). The
// interior penalty takes the law's moment at the two cells' end points ({M} [[phi]]) and is
// itself a hinge of stiffness P = sigma EI / h that yields at the section's fully plastic
// moment (Mp; the fibre law's sigma_y Z): a point load's plastic hinge is a jump of the
// rotation at its vertex, and the fibre law's curvature peak under a load near collapse is
// carried there too (plastic_points.hpp, measured).
// Statics: the continuation evaluates every trial from the committed states, the statics
// commit them at every accepted equilibrium (BeamEquilibrium::accept) and add the step's
// plastic work, sum weight law.dissipated: the result's dissipated; its plastic_curvature is
// the largest |kappa - M / EI| of a bending point (a hinge: its plastic rotation over the cell
// length).
// Response: the states are internal variables of the time step (BeamStepper): Newton
// evaluates the law at the generalized midpoint from the committed states, and accept()
// commits them at the step's end q_1 with the step's plastic work; a rejected attempt leaves
// nothing behind (every evaluation starts from the committed states). The record's
// `dissipated` is the plastic work from rest, `strain` V at the committed states (the elastic
// energy stored) and energy_error = T + V + D - W with D the damping's dissipation plus the
// plastic work. A plastic run halves a step whose Newton fails, down to dt / 64 (the elastic
// beam takes no sub-steps; nonlinear.cpp, respond_once, says what was measured). Linear
// buckling and the modes under load take no plastic law (check_buckling,
// check_preloaded_modes refuse ring.plastic).
// Measured (tests/fem_reference/fem_plastic_test.cpp, fem_plastic_response_test.cpp): see
// docs/measured.md, "fem_reference: the pinched plastic ring", and the tests' comments.
//
// ## Dynamics
// M a + C v + grad V(q) = g(t) grad Phi(q) from rest, C = a M + b K0 (Rayleigh, K0 the
// linear model's stiffness at rest, its terms included). Newmark average acceleration (the
// paper's; a_{n+1} at t_{n+1}) or generalized-alpha (Chung & Hulbert 1993, rho_inf; the
// loads at the generalized midpoint with g there); full Newton per step. Recorded per
// step: kinetic 1/2 v^T M v, strain V(q) (beam, springs, foundation), work
// sum g_mean (Phi(q_1) - Phi(q_0)) of every load (exact for a load factor constant over
// the step, since every load has a potential; the trapezoidal rule of g otherwise), the energy
// balance T + V + dissipated - work, constraint residual 0 (the constraints are linear
// and hold exactly), Newton iterations. A run whose T + V - W grows by more than 1 % of
// the largest work plus the round-off bound (ring/energy_guard.hpp, the rule of every
// solver's response; damped runs too) is a failed integration (ring::IntegrationFailure),
// as a Newton failure or a non-finite state is. Newmark starts from the consistent
// acceleration M qdd_0 = F g(0); generalized-alpha from the acceleration its first step's
// Newton matrix filters (nonlinear.cpp), as the multibody chain's integrators do. `energy-momentum` and hinge damping are not offered
// (std::invalid_argument): the FE beam has no hinges. A step whose Newton fails ends the run
// (step_too_small): there is no halving, and the reference refines dt itself.
//
// ## Converged references (fem.reference = true)
// Statics: the degree is raised (then cells split) until the recorded displacements (and a
// driven point's reaction) change by less than fem.tolerance relative to the largest. Response: the degree is
// raised and dt halved together until the peak |u| of every recorded point changes by
// less than fem.response_tolerance relative to the largest peak; error_estimate is the
// last change.
//
// Cost: per Newton iteration O(cells (p+2) (2p+3)^2) assembly and a sparse LU of the
// (banded + periodic corner) tangent, O(N p) with N = (2p+1) cells unknowns.
#pragma once

#include <array>
#include <limits>
#include <string>
#include <vector>

#include "paths/continuation.hpp"
#include "ring/analysis.hpp"
#include "ring/results.hpp"
#include "ring/spec.hpp"

namespace fem {

/// Static equilibrium under statics.loads: the end of the equilibrium path at the full
/// load, through limit points if the path comes back to it (file comment, "Statics").
/// Requires supports that hold every rigid motion, curved geometry, load and record points
/// on vertices (check_static). Throws std::invalid_argument for input that can never work and
/// ring::NumericalError when the path does not reach the full load (self-contact unless
/// statics.path: then the result's end, end_load and path; no return past a limit point, a stall).
ring::StaticResult solve_static(const ring::RingSpec& spec, const ring::FemOptions& options,
                                const ring::StaticOptions& statics);

/// Forced response from rest (see the file comment). Requires a pin (or supports that
/// hold every rigid motion), curved geometry,
/// load and record points on vertices, no fem.rotary_inertia (the Timoshenko theory has
/// the section's rotary inertia by definition). Throws std::invalid_argument
/// for input that can never work and ring::IntegrationFailure (with the history so far)
/// when a step fails or the energy balance grows.
ring::TimeHistory respond(const ring::RingSpec& spec, const ring::FemOptions& options,
                          const ring::ResponseOptions& response);

// ---- Internal: the traced equilibrium path (tests and diagnostics; NOT in the plug-in
// ABI, plugin.hpp, and not used by the ringvib command). ----

/// How solve_static's continuation runs (defaults: what solve_static does; `steps`
/// comes from statics.steps).
using ContinuationOptions = paths::Continuation;

/// The equilibrium path of one discretization, from rest, in path order.
struct StaticPath {
  struct Point {
    double load_factor = 0.0;                   ///< s: the load is s times statics.loads
    /// of the path's point (the first point load's; without one, the first record point's,
    /// else vertex 0), ring-centred frame, m
    std::array<double, 2> displacement{0, 0};
    /// ring.plastic (0 without): at the equilibrium, the stored (elastic) energy V of the
    /// beam, its springs and foundation, the loads' potential Phi at load factor 1 (so that
    /// the work of the loads along the path is the integral of s dPhi), and the plastic
    /// work done from rest to here, J.
    double stored = 0.0;
    double load = 0.0;
    double dissipated = 0.0;
    /// static.displacement: the force on the ring at the driven point, N, x and y (the
    /// multipliers of its two constraints; 0 without). The path's point is then the driven
    /// point, and stored is filled with or without ring.plastic, so that the rig's work
    /// int reaction . d(displacement) can be set against stored + dissipated.
    std::array<double, 2> reaction{0, 0};
    /// [plates]: `reaction` is the force of the plate at plates.axis on the ring (N, x and y),
    /// the path's point the vertex at plates.axis, `stored` includes the plates' penalty,
    /// contact_length the contact's extent on each plate (m, ring::PlatePair), and no_slide the
    /// multipliers of the two no-slide rows (N along the plates: the friction the ring would
    /// need at the two points of first contact, ~0 by symmetry).
    std::array<double, 2> contact_length{0, 0};
    std::array<double, 2> no_slide{0, 0};
    std::array<double, 2> opposite{0, 0};  ///< [plates]: the opposite plate's force, N
  };
  std::vector<Point> points;  ///< every accepted equilibrium (load steps, then arc steps)
  /// The first maximum of the load factor along the path (a limit point), located to
  /// ~1e-12 (static_path.cpp); NaN when the path met none before it ended.
  double limit_load_factor = std::numeric_limits<double>::quiet_NaN();
  bool continuation = false;  ///< the arc-length continuation took over (or ran from the start)
  int arc_steps = 0;          ///< accepted arc-length steps
  bool reached = false;       ///< the path reached the full load; then `result` holds it
  ring::StaticResult result;
  std::string failure;        ///< otherwise: the message solve_static throws
};

/// solve_static without the reference refinement (fem.reference must be false), keeping
/// the path. Inextensible (fem.extensible = false): the path is the one with
/// EA = 2 beta EI / R^2 (beta = 1e6), while the result and the limit load factor are
/// extrapolated in 1/beta from beta and 2 beta, as solve_static's. Throws
/// std::invalid_argument as solve_static does; a failed path is reported in `failure`.
StaticPath trace_static(const ring::RingSpec& spec, const ring::FemOptions& options, const ring::StaticOptions& statics,
                        const ContinuationOptions& continuation = {});

}  // namespace fem
