// Internal to multibody/: one step of each integrator of the nonlinear response
// (dynamics.hpp explains the methods) and generalized-alpha's starting value, on the
// Newton backend of newton_backend.hpp. respond() (dynamics.cpp) drives them.
#pragma once

#include <vector>

#include "multibody/chain.hpp"
#include "multibody/dynamics.hpp"
#include "multibody/dynamics_model.hpp"
#include "multibody/newton_backend.hpp"
#include "paths/schemes.hpp"
#include "ring/analysis.hpp"

namespace multibody::detail {

/// Integrator coefficients in the Arnold-Bruls form (paths/schemes.hpp); Newmark is
/// alpha_m = alpha_f = 0.
using Coefficients = paths::Scheme;

/// The coefficients of response.integrator (newmark: 0, 0, 1/4, 1/2).
Coefficients coefficients(const ring::ResponseOptions& r);

/// State at an accepted time: positions, velocities, accelerations, the
/// generalized-alpha pseudo-acceleration, multipliers.
struct State {
  double t = 0.0;
  Vector q, v, qdd, a, lambda;
};

/// The whole problem, fixed for a run; its linear algebra is the backend's.
struct Problem {
  const Chain& chain;
  DeadLoad load;
  ring::LoadHistory history;
  /// Loads beyond one point load (loading.hpp; on the O(n) backend the constant ones only); null: `load`.
  const Loading* loading = nullptr;
  /// The foundation, springs and clamp (attachments.hpp), on the dense backend only.
  const Attachments* terms = nullptr;
  /// The Timoshenko chain's sections (sections.hpp), on the dense backend only: the state's
  /// q is then (phi, gamma), the chain's coordinates its head.
  const Sections* sections = nullptr;
  /// The point inertias' hinge rotations (attachments.hpp), on the dense backend only: the
  /// state's q is then (q, chi), the chain's coordinates its head.
  const HingeInertias* hinges = nullptr;
  /// Unknowns of the state: the chain's coordinates, and the shear angles or hinge rotations.
  int size() const { return chain.dofs() + (sections ? sections->n() : 0) + (hinges ? hinges->n() : 0); }
  /// Constraint rows: the chain's and the further pins'.
  int constraint_count() const { return chain.constraint_count() + (terms ? terms->pin_rows() : 0); }
};

/// The constraint kinematics at the state q (Problem::size entries): the chain's rows and the
/// further pins' on its head, with zero columns for the shear angles and hinge rotations,
/// which enter no constraint. O(n).
Kinematic kinematics(const Problem& p, const Vector& q, bool values = true, bool hessian = true);

/// Result of one attempted step.
struct StepOutcome {
  bool converged = false;
  int iterations = 0;
  bool reused = false;  ///< began with a Newton matrix kept from an earlier step
};

/// Starting value of generalized-alpha's pseudo-acceleration a_0 (the acceleration-like
/// sequence of Arnold & Bruls 2007; the true acceleration qdd_0 stays consistent), and
/// of Newmark's acceleration (alpha_m = alpha_f = 0: a_0 = qdd_0 there):
///   [S G^T; G 0] [a_0; mu] = c [f Phi - xi - C v - K theta; -Gdot v],
/// S = c M + c' (C + dxi/dv) + tangent stiffness (springs, load, constraint curvature
/// with the consistent multipliers): the integrator's Newton matrix at t_0 for the step h
/// without the term d(M qdd)/dq,
/// c = (1 - alpha_m) / ((1 - alpha_f) beta h^2), c' = gamma / (beta h). In a linear mode
/// of frequency w this is a_0 = c qdd_0 / (c + w^2): qdd_0 (1 + O(w^2 h^2)) where the
/// step resolves the mode, so the accuracy of the consistent start is kept (second order
/// in q and v: tests/multibody/test_dynamics.cpp), and -> 0 where w h >> 1. Why not
/// a_0 = qdd_0: a mode with w h >> 1 started there leaves the first steps with the
/// velocity ~ h (1 - gamma) qdd_0 instead of ~ qdd_0 / w (the method's velocity
/// overshoot); a point step load gives every mode the acceleration F_k / m_k and the
/// chain's w_max grows like n^2, so fine chains gained energy from the first step; Newmark,
/// which does not overshoot, kept +-qdd_0 in every unresolved mode (docs/measured.md,
/// "Starting acceleration"). Cost: one factorization of the Newton matrix (O(n) sparse,
/// O(n^3) dense).
void starting_pseudo_acceleration(const Problem& p, const Coefficients& co, double h, NewtonBackend& nb,
                                  State& s);

/// One index-3 step of size h from `s0` (generalized-alpha, Arnold-Bruls form); on
/// success writes `s1`. Newton on (q, lambda) with the analytic tangent of
/// dynamics_model.hpp. Cost per iteration: the backend's residual and solve, plus a
/// factorization when the policy refreshes the matrix.
StepOutcome step_index3(const Problem& p, const Coefficients& co, const State& s0, double h,
                        const IntegrationControls& ctl, NewtonBackend& nb, State& s1);

/// One Newmark step in the paper's reduced form (its eqs. 18-20, coordinate
/// partitioning): the c dependent angles are the best-conditioned columns of G(q_n)
/// (column-pivoted QR), the Newmark formulas act on the n - c independent angles z, and
/// the dependent velocities and accelerations follow from G v = 0 and
/// G qdd + Gdot v = 0 (their positions from g(q) = 0 at convergence). The equations are
/// D^T r = 0, D = [I; -G_y^{-1} G_z], with lambda = -G_y^{-T} r_y. Newton runs on all
/// angles and lambda with g(q) as a residual, on the saddle-point matrix of step_index3,
/// made exact by a rank-c term: with E the dependent columns of the identity,
///   J = T + M(q) E V^T,  V^T = -G_y^{-1} [c G + Hess_g qdd - G diag(v^2) + 2 c' H_v + 2 (H_v E) V_v^T],
///   V_v^T = -G_y^{-1} [c' G + H_v],  H_v = Hess_g diag(v)
/// (c = 1 / (beta h^2), c' = gamma / (beta h); the dependent accelerations' change with q
/// that T's c I leaves out). It is applied by Woodbury's formula: c extra solves with each
/// factorization, O(c n) per iteration. (The dependent velocities' share, (dxi/dv + C) E
/// V_v^T, is left out: it changes no iteration count, docs/measured.md.) The rank-c term
/// grows like n, since three angles close a loop of n segments: without it Newton is
/// linear (docs/measured.md, "Newton iterations per step"). Its first iteration
/// applies Newmark's formulas to every angle, as the index-3 form does (no dependent
/// rates): from the predictor the partitioned equations are far from linear at large n
/// (at n = 10^4 their first correction did not shrink the second), the index-3 ones are
/// not. Constraints hold to round-off at the end (positions by solve_dependent,
/// velocities and accelerations by construction); no multiplier oscillates, which is what
/// makes the trapezoidal rule stable here (applied to the index-3 form it is not: Cardona
/// & Geradin 1989). Cost per iteration: as step_index3, plus O(c n).
StepOutcome step_partitioned(const Problem& p, const Coefficients& co, const State& s0, double h,
                             const IntegrationControls& ctl, NewtonBackend& nb, State& s1);

}  // namespace multibody::detail
