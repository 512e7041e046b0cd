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
// Supports: pin at vertex 0, roller (the roller vertex stays on the line through the pin
// and its rest position: a linear constraint, exact at any displacement). Loads are dead
// forces at vertices; record points must be vertices.
//
// ## Statics
// Load stepping s = k / steps with full Newton on the consistent tangent (UMFPACK), the
// increment halved when Newton fails (25 iterations, a non-finite value); a load level
// that cannot be passed even with 1/1024 of an increment is reported as a limit point
// (ring::NumericalError naming the load reached): there is no arc-length continuation.
//
// ## Dynamics
// M a + C v + f(q) = F g(t) from rest, f = grad V, C = a M + b K0 (Rayleigh, K0 the
// tangent at rest). Newmark average acceleration (the paper's; a_{n+1} at t_{n+1}) or
// generalized-alpha (Chung & Hulbert 1993, rho_inf); full Newton per step. Recorded per
// step: kinetic 1/2 v^T M v, strain V(q), work (trapezoidal sum of F g . dq), the energy
// balance T + V + dissipated - work, constraint residual 0 (the constraints are linear
// and hold exactly), Newton iterations. Undamped, a run that gains more than 1 % of the
// largest work (energy balance > 0.01 max |work|) is a failed integration (ring::IntegrationFailure), as a Newton failure
// or a non-finite state is. `energy-momentum` and hinge damping are not offered
// (std::invalid_argument): the FE beam has no hinges.
//
// ## Converged references (fem.reference = true)
// Statics: the degree is raised (then cells split) until the recorded displacements
// change by less than fem.tolerance relative to the largest. Response: the degree is
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

#include "ring/analysis.hpp"
#include "ring/results.hpp"
#include "ring/spec.hpp"

namespace fem {

/// Static equilibrium under statics.load (full load at the end of the load steps).
/// Requires a pin and a roller on FE vertices, curved geometry, load and record points
/// on vertices. Throws std::invalid_argument for input that can never work and
/// ring::NumericalError for a failed solve or a limit point.
ring::StaticResult solve_static(const ring::RingSpec& spec, const ring::FemOptions& options,
                                const ring::StaticOptions& statics);

/// Forced response from rest (see the file comment). Requires a pin, curved geometry,
/// load and record points on vertices, no rotary inertia. Throws std::invalid_argument
/// for input that can never work and ring::IntegrationFailure (with the history so far)
/// when a step fails or the energy balance grows.
ring::TimeHistory respond(const ring::RingSpec& spec, const ring::FemOptions& options,
                          const ring::ResponseOptions& response);

// ---- Internal: the traced equilibrium path (tests and diagnostics; NOT in the plug-in
// ABI, plugin.hpp, and not used by the ringvib command). ----

/// How solve_static's continuation runs (defaults: what solve_static does).
struct ContinuationOptions {
  /// Skip load stepping: arc-length continuation from the rest state (for tests: the same
  /// equilibrium must come out either way).
  bool from_start = false;
  /// Arc-length steps allowed before the path is declared not to return to the full load.
  int max_arc_steps = 2000;
};

/// The equilibrium path of one discretization, from rest, in path order.
struct StaticPath {
  struct Point {
    double load_factor = 0.0;                   ///< s: the load is s * statics.load.force
    std::array<double, 2> displacement{0, 0};   ///< of the loaded point, ring-centred frame, m
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
