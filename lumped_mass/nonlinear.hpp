// Geometrically nonlinear statics and forced response of the lumped-mass `chain`
// (model.hpp), written independently of multibody/: the same physical model as the
// multibody chain without segment rotary inertia, in other coordinates, which makes
// each an exact oracle for the other in continuous time.
//
// ## An arch (ring.arc): the open chain (model.hpp)
// n + 1 nodes from `from` to `to`, n links, springs at the n - 1 interior hinges only (an
// end's hinge has one link: a clamp's half hinge 2 EI/l to the wall, terms.hpp), the masses at
// the n links' midpoints; statics (point loads and gravity; static.path through limit points:
// StaticDetail::limit) and response run as below. A path point's ovalisation is 0 (an arch has
// no opposite hinges); contact is measured between links along the open chain.
//
// ## Model (Cartesian hinge positions, no small-rotation assumption anywhere)
// Unknowns x = (x_0, y_0, ..., x_{n-1}, y_{n-1}): the hinge positions, ring-centred
// frame, hinge k resting at rho (cos a_k, sin a_k) (model.hpp's n-gon, a_k from the pin).
//  - Rigid links: c_j(x) = (|x_{j+1} - x_j|^2 - l^2) / (2 l) = 0, j = 0..n-1 (quadratic).
//  - Supports: model.hpp's rows S on the displacements, S (x - X) = 0 (linear): every pinned
//    point (pin, pins) 2 rows, the roller 1 row (its hinge on the line through the pin and
//    its rest position).
//  - Springs k = EI / l at every hinge on the turning angle between neighbouring links,
//    theta_j = atan2(a x b, a . b), a = x_j - x_{j-1}, b = x_{j+1} - x_j (exact for any
//    rotation below pi between neighbours): V = k/2 sum_j (theta_j - 2 pi / n)^2.
//  - The spec's terms (terms.hpp, the same code as the linear model's): elastic supports
//    kx, ky, kr, the clamp (4 EI/l on the rotation of the tangent), the Winkler foundation
//    (fixed directions of the undeformed point), point masses (m on the hinge; J, statics
//    aside, on the hinge's own rotation chi, below).
//  - Point masses m = rho A l at the link midpoints: T = m/2 sum_j |(v_j + v_{j+1})/2|^2,
//    so the mass matrix M is constant (block-tridiagonal plus the closing corners).
//  - Loads (loads.hpp), all scaled by the load factor (statics: s; response: f(t)): point
//    loads at hinges, uniform pressure (follower, dead, central) and gravity on the links'
//    and the point masses' weight, each a potential P(x) with its load stiffness.
//
// ## Statics: grad V(x) + G(x)^T lambda + s grad P(x) = 0, c(x) = 0, s: 0 -> 1
// Followed from rest by the shared continuation driver (paths/continuation.hpp: load
// stepping with full Newton, Crisfield's arc length through limit points, the limit
// point located), on (x, lambda) with the tangent k sum (grad theta grad theta^T +
// (theta - theta0) Hess theta) plus the terms' Hessian, s Hess P (the follower and central
// pressures' load stiffness) and sum lambda_j Hess c_j, bordered for the arc and
// factorized as one sparse LU. The arc length is measured on the hinge positions; a step
// turns no link by more than half a radian; converged when no hinge moves by more than
// 1e-12 R and the links hold to 1e-10 R. Self-contact (the centre lines of non-neighbouring
// links within the section depth) ends the path; under static.path it is the result, located
// within the step (ChainStatics::clearance), and a bifurcation is passed by branch switching
// up to n = 200 (the dense least stable direction).
//
// ## Displacement control (static.displacement)
// No loads; the driven hinge's two rows S_d (x - rest) - s value = 0 join the support rows
// (chain.hpp, drive()), so the load column dR/ds of the bordered matrix is -value there, and
// the stability count and branch switching hold the point as a pin. The rig's force on the
// ring (PathPoint::reaction, StaticResult::reaction) is minus those rows' multipliers; its work
// (trapezoidal rule over the accepted steps) is StaticDetail::work. A driven plastic chain is
// followed by arc length from rest (nonlinear.cpp, follow_statics, says why). The frames the
// same on their rows (frame_nonlinear.cpp).
//
// ## Rigid plates ([plates], ring::PlatePair)
// No loads and no supports: the plates' penalty is lumped at the nodes as the Winkler foundation
// is (each node for its ring length l), with the gap at the node's place on the centroid line
// (chain.hpp, hold_plates: the ring's point at rest moved by the node's displacement), in the
// energy, the gradient and the tangent (tangent(): l k d_p d_p^T where in_contact), and its
// change with s, l k (travel / 2) d_p, in the load column. The two points of first contact keep
// their place along the plates by one roller-like row each, e . (x - rest) = 0, and their
// midpoint stays on the plates' midline, d_0 . (u_a + u_b) = 0 (S's last three;
// StaticDetail::no_slide and ::centre their multipliers, ~0 by symmetry): without that row a
// ring that springs back clear of both plates on unloading (static.history) is free along d_0.
// The plates' advance a = s travel / 2 is one more unknown, measured by the arc with the
// positions, so that the arc can step on while such a ring stands still. The path is followed by
// load stepping that hands over to the arc, elastic and plastic (nonlinear.cpp, follow_statics,
// says why not from rest by arc as a driven point); the reaction is the force of the plate at
// plates.axis on the ring, the plates' work their pressure times their advance (trapezoidal
// rule), and the stored energy counts the penalty's. The frames (elastic, without static.path)
// take the same penalty and rows on their translations (frame_nonlinear.cpp).
//
// ## ring.plastic in the statics (bending.hpp)
// The hinge springs' law is ring.plastic's resultant law on the hinge rotation (stiffness EI/l,
// yield Mp, the scene's hardening and rule), its potential in V from the committed states.
// The statics' equilibrium holds its own copy of the chain whose states accept() commits at
// every accepted equilibrium (static.history's legs included); every linearization, tangent
// and stability count between two is the return map from the last committed states. The
// result carries the plastic work and the largest plastic curvature (StaticResult, PathPoint),
// StaticDetail the loads' work and the stored energy. Known limit: the driver calls accept()
// before its bifurcation test, so a path that ends at (or, with static.path, switches at) a
// bifurcation has committed the states of the bracket's upper end. Only the chain takes the
// law (checks.hpp); the frames evaluate the same Bending, elastic.
//
// ## Dynamics: the implicit midpoint rule with constraint forces at the midpoint
//   M (v_{n+1} - v_n) / h = -f(t_{n+1/2}) grad P(x_m) - grad V(q_m) - C v_m - G(x_m)^T lambda,
//   (q_{n+1} - q_n) / h = (v_n + v_{n+1}) / 2,   c(x_{n+1}) = 0,   q_m = (q_n + q_{n+1}) / 2,
// on q = (x, chi): the positions, then the rotation chi of every hinge with a point inertia
// (terms.hpp, Terms::hinge_rotations: the linear modes' unknowns), whose mass is J and whose
// springs are the hinge's split springs, 2K (m_h - chi)^2 + kr chi^2 / 2 (Terms::split) in
// place of the statics' condensed kr. M is constant on q.
// Second order; for a linear system it is the average-acceleration Newmark scheme
// (the paper's). Because the constraints are quadratic, c(x_{n+1}) - c(x_n) =
// G(x_m)(x_{n+1} - x_n) exactly, so the constraint forces do no work and the
// constraints hold to round-off at every step; the energy balance error comes only
// from the midpoint rule on the non-quadratic energies (springs, the clamp's and kr's
// rotation and the split springs' m_h, follower and central pressure: O(h^2), no drift for
// undamped runs; the kinetic energy, J w^2 / 2 of the hinge rotations included, is quadratic
// and exact). The work W of the loads is -sum f(t_m) (P(x_{n+1}) - P(x_n)), exact for a
// constant load factor; V counts the terms' energy (foundation, springs, clamp, split springs). Offered for response.integrator = "midpoint" and "newmark" (the same
// scheme); "energy-momentum" (the name of a scheme that conserves energy, which this one
// does not) and "generalized-alpha" are refused (std::invalid_argument, checks.hpp).
// Damping: Rayleigh C = a M + b K0 (M and K0, the stiffness at rest, on q) and hinge dampers c on
// the turning rate, both at the midpoint velocity; the dissipated energy is summed.
//
// ## The Timoshenko frame (lumped.variant = "timoshenko-frame", frame.hpp)
// solve_static, solve_static_detail and respond also take the corotational Timoshenko frame:
// unknowns (x, y, theta) per node, no link constraints, the support rows only; the same
// terms, loads, continuation driver and midpoint rule (frame_nonlinear.cpp). Its statics end
// at a bifurcation (dense count up to n = 133, none above) and have no branch switching and
// no static.path (refused); its response no hinge dampers (refused).
// Buckling and modes under load remain the chain's.
//
// Cost: per Newton iteration one sparse LU (Eigen SparseLU, COLAMD) of the
// (3n + supports) KKT matrix, whose pattern is banded plus the closing corners: O(n)
// time and memory.
#pragma once

#include <array>
#include <limits>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "paths/continuation.hpp"
#include "ring/analysis.hpp"
#include "ring/results.hpp"
#include "ring/spec.hpp"

namespace lumped {

/// Static equilibrium of the chain (or a corotational frame, frame.hpp) under `statics.loads`
/// (full load). Requires supports and terms that leave no rigid motion (RingSpec::rigid_modes() == 0; a
/// pin, unless the foundation or springs hold the ring), and the load and record points on
/// hinges.
/// Throws std::invalid_argument for inputs that can never work and ring::NumericalError
/// when the equilibrium path does not reach the full load (the ring touches itself; no
/// return past a limit point).
ring::StaticResult solve_static(const ring::RingSpec& spec, const ring::LumpedOptions& options,
                                const ring::StaticOptions& statics);

/// solve_static's result and what the ground exerts on the ring at the equilibrium: the
/// supports' reactions (the multipliers of their rows) and the forces of the elastic supports
/// and the foundation, summed, N (x, y). At equilibrium it balances the loads' resultant
/// (the weight under gravity alone; under static.displacement, minus the reaction).
/// `work`: the loads' work along the path (static.displacement: the rig's; [plates]: the
/// plates'), the trapezoidal
/// rule over the accepted steps (exact for a path linear in the load factor, O(steps^-2)
/// otherwise), J; `stored`: the elastic
/// energy at the end (the bending law's and the terms'; the frames' axial and shear too; the
/// plates' penalty), J.
/// The energy identity: work = stored + result.dissipated.
/// `limit`: the path's first limit point (the first maximum of the load factor, located by the
/// continuation driver to 1e-6 of its arc step), NaN when the path met none.
struct StaticDetail {
  ring::StaticResult result;
  std::array<double, 2> ground_force{0.0, 0.0};
  double work = 0.0, stored = 0.0;
  double limit = std::numeric_limits<double>::quiet_NaN();
  /// [plates]: the multipliers of the two no-slide rows (at plates.axis, then opposite), N (the
  /// force along the plates that holds each point; ~0 under a symmetric crushing), and the
  /// total pressure of each plate on the ring, N; `centre`: the centre row's multiplier (the
  /// force along d_0 that keeps the two points' midpoint on the plates' midline; ~0), N.
  std::array<double, 2> no_slide{0.0, 0.0}, plate_loads{0.0, 0.0};
  double centre = 0.0;
};
/// How the statics count an equilibrium's unstable directions for the continuation
/// driver's bifurcation test (stability.hpp): automatic (dense up to n = 200, an O(n)
/// frontal LDL^T up to n = 10^4, none above), or one route forced (for the tests that
/// compare them).
enum class InertiaRoute { automatic, dense, frontal };

StaticDetail solve_static_detail(const ring::RingSpec& spec, const ring::LumpedOptions& options,
                                 const ring::StaticOptions& statics,
                                 InertiaRoute route = InertiaRoute::automatic);

struct Chain;
class ChainLoads;

namespace detail {

/// The statics' equilibrium at the end of their path: what the driver returned, the hinge
/// positions and the multipliers there.
struct StaticState {
  paths::Trace trace;              ///< how the path ended, its steps and Newton iterations
  Eigen::VectorXd x;               ///< hinge positions (2n, chain.hpp's order), m
  Eigen::VectorXd lambda;          ///< multipliers (links, then supports), N: tangent()'s lambda
  std::vector<ring::PathPoint> path;  ///< the recorded path (only with `record`), rest first
  std::vector<ring::PathPoint> limits;  ///< the located limit points (only with `record`)
  double dissipated = 0.0;         ///< ring.plastic: the plastic work along the path, J
  double plastic_curvature = 0.0;  ///< the largest |plastic hinge rotation| / l at the end, 1/m
  double work = 0.0;               ///< the loads' work along the path (StaticDetail), J
  double stored = 0.0;             ///< the elastic energy at the end (StaticDetail), J
  std::array<double, 2> reaction{0.0, 0.0};  ///< static.displacement: the rig's force at the end, N
  std::array<double, 2> contact_length{0.0, 0.0};  ///< [plates]: at the end, m
};

/// Follows the chain's static equilibrium under `loads` (chain.hpp, loads.hpp) from rest to
/// the full load of `statics` (static.steps) with the continuation driver: the one path of
/// solve_static and of the modes under load (preload.hpp). With `record` (static.path): branch
/// switching at bifurcations, every accepted equilibrium recorded at those hinges, and the
/// touch a result; without it the path must reach the full load on the branch it starts on.
/// Throws ring::NumericalError("`who`: why") when it does not. The caller has run the checks
/// (check_static) and built `c` and `loads` from the same spec. Cost: the statics' (above).
StaticState follow_statics(const Chain& c, const ChainLoads& loads, const ring::RingSpec& spec,
                           const ring::StaticOptions& statics, const std::vector<int>* record, InertiaRoute route,
                           const std::string& who);

}  // namespace detail

/// Forced response from rest in the undeformed state (see above). Requires a variant with
/// rotary inertia (not "frame"), a pin (or terms that hold every rigid motion), load and record points on hinges.
/// Records every requested step as
/// ring::TimeHistory (energies, constraint residual max |c_j|, Newton iterations, six
/// snapshots). Throws ring::IntegrationFailure (with the history so far) when Newton
/// fails at a step that cannot be halved further, a value is not finite, the ring
/// touches itself, or T + V - W grows by more than 1 % of the largest work plus the
/// round-off bound of ring/energy_guard.hpp (the rule of every solver's response).
ring::TimeHistory respond(const ring::RingSpec& spec, const ring::LumpedOptions& options,
                          const ring::ResponseOptions& response);

}  // namespace lumped
