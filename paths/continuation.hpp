// The one continuation driver of the nonlinear statics, shared by every solver. It holds
// the policy; a solver supplies its equilibrium through `Equilibrium` (its residual and
// its bordered Jacobian at a point), as the time-stepping driver gets one step through
// `Stepper`:
//
// - **Load stepping** from rest to the full load in `steps` increments, each solved by
//   full Newton at a fixed load factor s. A load level that Newton cannot reach, or
//   whose equilibrium, looked at in the direction of the step, has the load falling
//   (the step jumped over a limit point onto the path beyond it), is retried with half
//   the increment; the increment doubles again after each success, never beyond
//   1 / steps. A level that 1 / 2^max_halvings of the increment cannot pass hands over to
//   the continuation.
// - **Arc-length continuation** (Crisfield 1981, cylindrical: the Euclidean length of
//   the change of the displacement unknowns u per step is fixed, the load factor is an
//   unknown): predictor along the path's tangent, corrector by Newton on the
//   equilibrium bordered by the arc condition c = (|u - u_0|^2 - len^2) / (2 len) = 0.
//   Its Jacobian [J dR/ds; (u - u_0)^T / len 0] is regular at a limit point, where J
//   alone is singular; the solver factorizes it as it can. The length adapts towards
//   five corrector iterations per step (at most doubled or halved), shorter after a
//   load change above one increment, and so that no step moves the model more than its
//   basin (Equilibrium::move); a failed step halves it, 30 failures in a row end the
//   path (stalled). When the path crosses the full load, Newton at s = 1 from the
//   interpolated point finishes it.
// - **The limit point** (the first maximum of s along the path) is located by regula
//   falsi (Illinois) on ds/dtau over the arc step that contains it, to 1e-6 of the step.
// - **Self-contact** is the model's hook (Equilibrium::accept), called for every
//   accepted equilibrium with the one before it: contact ends the path, as a result
//   the caller reports. A model that measures its clearance (Equilibrium::clearance) has
//   the touch located by bisection within the step (to 1e-6 of it), the touching
//   equilibrium being the path's last.
// - **A bifurcation** ends the path where the model says how many directions its
//   equilibria are unstable in (Equilibrium::unstable_directions, the inertia of its
//   tangent on the constraints' tangent space): a change of that count that no limit
//   point explains (a limit point changes it by one, and load stepping never passes one)
//   is a branch point, where the path this driver follows turns unstable while another
//   leaves it (a perfect ring buckling; a double crossing, as under uniform follower
//   pressure, changes it by two, which a determinant's sign would miss). On the load-
//   stepping part it is approached by halving the increment, always from the last
//   accepted equilibrium (so that a Newton that jumped to another branch near it is not
//   taken for it), to 1e-6 of the increment; on the arc it is bracketed by the step.
// - **Branch switching** (Continuation::branch_switch): at a bifurcation the path leaves
//   the one it followed along the model's critical direction (Equilibrium::
//   critical_direction, the tangent's eigenvector of least eigenvalue at the bracket's
//   lower end, on the side Continuation::branch_side names): an arc step of a tenth of the model's basin with that direction as its
//   predictor, whose corrector must land on the branch (its chord at least half along
//   the direction), then arc-length continuation on the branch as above. At most four
//   switches; a switch that does not land ends the path at the bifurcation.
//
// A Newton solve (a load level or an arc step) is the one Newton's (paths/newton.hpp): it
// fails at its cap, on a non-finite value or a failed factorization, or when its iterate
// leaves the basin of
// the point it started from (Equilibrium::move > 1); an arc corrector also fails when it
// moves farther than the step's length from its predicted point (it left for another
// part of the path).
//
// Cost: per Newton iteration one linearization and factorization of the model; one
// more solve with it per accepted step (the tangent).
//
// Usage:
//   class MyEquilibrium : public paths::Equilibrium { ... };
//   paths::Trace t = paths::follow(eq, {.steps = 20});
//   if (t.end != paths::Trace::End::reached) throw ring::NumericalError("x: " + paths::failure_message(t, options));
#pragma once

#include <Eigen/Core>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace paths {

using Vector = Eigen::VectorXd;

/// A point (z, s) of the path: the model's unknowns and the load factor.
struct State {
  Vector z;
  double s = 0.0;
};

/// What an accepted step met: contact, somewhere along the way between two equilibria.
struct Touch {
  double at = 1.0;    ///< where along the step, 0 (its start) to 1 (its end)
  std::string where;  ///< the model's description (which parts, how close, why it ends)
};

/// One discretization's equilibrium R(z, s) = 0 at load factor s. The unknowns
/// z = (u, m): u, the first arc_size() of them, displacements or angles (they measure
/// the arc length), m the rest (constraint multipliers).
class Equilibrium {
 public:
  virtual ~Equilibrium() = default;
  virtual Eigen::Index size() const = 0;
  virtual Eigen::Index arc_size() const { return size(); }
  /// Writes R(x.z, x.s) into r (size()) and factorizes the bordered Jacobian
  ///   B = [dR/dz  dR/ds; (w^T 0)  ws]      (w: arc_size() values, on u only).
  /// False when R is not finite or B cannot be factorized.
  virtual bool linearize(const State& x, const Vector& w, double ws, Vector& r) = 0;
  /// y := B^-1 y (size() + 1 values) with the last factorization; false when the
  /// result is not finite.
  virtual bool solve(Vector& y) = 0;
  /// The size of a change dz of the unknowns against what one step may move (the
  /// basin of a Newton solve: 1 is the most).
  virtual double move(const Vector& dz) const = 0;
  /// Newton's stopping rule after the correction dz that reached x (`iteration` 1, 2,
  /// ...: a rule with memory starts afresh at 1).
  virtual bool converged(const State& x, const Vector& dz, int iteration) = 0;
  /// An accepted equilibrium `to`, reached from the accepted `from`: the model records
  /// it and says whether the ring touched itself on the way.
  virtual std::optional<Touch> accept(const State& from, const State& to) = 0;
  /// A Newton solve from an accepted equilibrium did not converge: a model with internal
  /// variables (paths/internal.hpp) discards their trial values. Default: nothing to do.
  virtual void reject() {}
  /// How many independent directions the equilibrium x is unstable in: the negative
  /// eigenvalues of the tangent stiffness dR/du on the constraints' tangent space.
  /// nullopt (the default): the model does not say, and no bifurcation is detected.
  /// Called for rest and for every accepted equilibrium (and while locating a bifurcation).
  virtual std::optional<int> unstable_directions(const State& x) {
    (void)x;
    return std::nullopt;
  }
  /// How far the ring at x is from touching itself (m; negative: it overlaps), for the
  /// driver to locate the touch within a step. nullopt (the default): the touch is where
  /// accept() says it is.
  virtual std::optional<double> clearance(const State& x) {
    (void)x;
    return std::nullopt;
  }
  /// A direction dz (size() values; multipliers may be zero) in which the tangent at x is
  /// least stable: the eigenvector of the least eigenvalue of dR/du on the constraints'
  /// tangent space. nullopt (the default): no branch switching.
  virtual std::optional<Vector> critical_direction(const State& x) {
    (void)x;
    return std::nullopt;
  }
};

/// The policy knobs.
struct Continuation {
  int steps = 20;            ///< load increments from rest to the full load (>= 1)
  bool from_start = false;   ///< arc-length continuation from rest (no load stepping)
  int max_arc_steps = 2000;  ///< arc steps before the path is declared not to come back
  int max_halvings = 10;     ///< a load increment halved this often hands over to the arc
  bool branch_switch = false;  ///< at a bifurcation, leave onto the branch (the header)
  /// Which side of the critical direction a branch switch takes: +1 the side where the
  /// direction's largest displacement unknown is positive, -1 the other (a pitchfork has
  /// two; the eigenvector's own sign is arbitrary, so it is fixed by that rule).
  int branch_side = 1;
  /// A load history: the load factors visited in turn from rest's, each leg a path of its
  /// own (`steps` increments from one factor to the next, the same events ending it).
  /// Empty: one leg from rest to 1. The legs run the driver on s' = (s - a) / (b - a)
  /// (continuation.cpp, Leg), so unloading and reversed loading are paths like loading.
  std::vector<double> history;
};

/// How a path ended and where.
struct Trace {
  enum class End { reached, contact, arc_steps_exhausted, stalled, bifurcation };
  End end = End::reached;
  State state;     ///< the last accepted equilibrium (reached: at s = 1)
  int steps = 0;   ///< accepted load and arc steps
  int arc_steps = 0;
  int iterations = 0;  ///< Newton iterations of accepted steps and of the limit's location
  bool continuation = false;  ///< the arc-length continuation ran
  double limit = std::numeric_limits<double>::quiet_NaN();  ///< first maximum of s, if met
  /// The equilibrium at `limit` (located to 1e-6 of its arc step), if met; its s is `limit`.
  std::optional<State> limit_state;
  double stepping_stopped = 0.0;  ///< load factor where load stepping handed over
  double end_load = 0.0;          ///< where the path ended (contact: the load factor of the touch)
  std::string contact;            ///< Touch::where
  /// bifurcation: the load factors that bracket it (located: within 1e-6 of a step), and
  /// the unstable directions before and after it.
  double bifurcation_low = 0.0, bifurcation_high = 0.0;
  int unstable_before = 0, unstable_after = 0;
  std::vector<double> branch_points;  ///< load factors where the path switched onto a branch
};

/// Follows the path of `eq` from `rest` (an equilibrium at s = 0) to the full load
/// (s = 1), or through options.history to its last factor, or to an end event; never
/// throws for a path that ends early (see Trace::end).
Trace follow(Equilibrium& eq, const State& rest, const Continuation& options);

/// Why a path that did not reach the full load ended, in one sentence without the
/// solver's name: "past a limit point at load factor 0.94, the equilibrium path ...".
std::string failure_message(const Trace& t, const Continuation& options);

}  // namespace paths
