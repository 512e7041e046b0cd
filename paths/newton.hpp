// The one Newton iteration of the project: every solver's time step (paths/time_stepping.hpp)
// and every load level and arc step of the continuation (paths/continuation.hpp) solve their
// nonlinear equations here. It holds the policy; a solver supplies its system through
// `NewtonSystem` (linearize at the current iterate, solve for the correction, apply it, say
// whether it has settled), as the drivers get steps and equilibria from their models.
//
// The policy:
// - **One cap**: a solve fails after `Rule::cap` iterations (kNewtonCap unless a caller that
//   tests the failure path lowers it).
// - **One basin rule**: a correction whose `move` is above 1 (the model measures it
//   against what one iteration may move: half a link, a segment turned by half a radian) has
//   left the basin of the solution it started from: the solve fails, unless the matrix was
//   kept from an earlier iterate, which is then dropped and the iteration repeated with a
//   fresh one.
// - **One stop rule**: after each applied correction the model settles the iteration, told
//   whether the correction was below `Rule::tolerance` in its own scaled norm (a length
//   relative to the ring's radius, an angle); it adds what only it can check (its
//   constraints hold, a rule with memory at the round-off floor).
// - **One Jacobian-reuse policy** (modified Newton, `Rule::reuse`): a matrix kept from an
//   earlier step serves one iteration (a cheap first correction) and is then refreshed, so
//   that the solve finishes in Newton's quadratic range; one kept within the solve is
//   refreshed when it shrinks the correction by less than 8, and after a correction above
//   `Rule::refresh_above`. Without reuse every iteration linearizes afresh (full Newton).
//
// Internal variables (paths/internal.hpp) are the model's: it evaluates them at every
// iterate from the committed ones, so a failed solve leaves nothing to undo, and the driver
// that accepts the step or the level has the model commit them.
//
// Cost: the model's, per iteration; the policy adds O(1).
//
// Usage:
//   class MyStep : public paths::NewtonSystem { ... };
//   MyStep system(...);
//   const paths::NewtonResult r = paths::newton(system, {.tolerance = 1e-12 * radius});
#pragma once

#include <cmath>
#include <functional>

namespace paths {

/// Iterations before a Newton solve fails: one cap for every solver, time step and load level.
/// Newton converges quadratically in 3-6 iterations from a predictor inside its basin; 25
/// leaves room for the slow start of a step load at large n and for modified Newton's linear
/// contraction before its refresh.
constexpr int kNewtonCap = 25;

/// A correction as the model measures it.
struct Correction {
  double size = 0.0;  ///< in the model's scaled norm, compared with Rule::tolerance
  double move = 0.0;  ///< against the basin: more than 1 has left it
};

/// The model's word on the iterate after a correction was applied.
enum class Verdict { iterate, converged, failed };

/// A nonlinear system R(x) = 0 with its step matrix, one iterate at a time. The iterate, the
/// residual, the factorization and the correction live in the model.
class NewtonSystem {
 public:
  virtual ~NewtonSystem() = default;
  /// The residual at the current iterate and, when `fresh`, the step matrix there, factored
  /// (otherwise the kept factorization serves). False when a value is not finite or the
  /// matrix cannot be factored.
  virtual bool linearize(bool fresh) = 0;
  /// The correction from the residual and the current factorization, not yet applied,
  /// measured into `c`. False when it is not finite.
  virtual bool solve(Correction& c) = 0;
  /// Applies the correction to the iterate.
  virtual void apply() = 0;
  /// After the correction `c` was applied, `small` when c.size <= Rule::tolerance: converged
  /// (the default when small), iterate on, or failed.
  virtual Verdict settle(bool small, const Correction& c) {
    (void)c;
    return small ? Verdict::converged : Verdict::iterate;
  }
  /// True when a factored matrix from an earlier solve may serve its first iteration
  /// (Rule::reuse only; the model judges whether it still fits, e.g. the same step size).
  virtual bool has_matrix() const { return false; }
};

/// A NewtonSystem from functions, for a step whose iterate lives in the caller's locals and
/// lambdas. `settle` empty: converged when small; `kept` empty: no kept matrix.
struct NewtonFunctions : NewtonSystem {
  std::function<bool(bool fresh)> linearize_at;
  std::function<bool(Correction&)> solve_for;
  std::function<void()> apply_correction;
  std::function<Verdict(bool small, const Correction&)> settle_at;
  std::function<bool()> kept;

  bool linearize(bool fresh) override { return linearize_at(fresh); }
  bool solve(Correction& c) override { return solve_for(c); }
  void apply() override { apply_correction(); }
  Verdict settle(bool small, const Correction& c) override {
    return settle_at ? settle_at(small, c) : NewtonSystem::settle(small, c);
  }
  bool has_matrix() const override { return kept && kept(); }
};

/// The policy knobs.
struct Rule {
  double tolerance = 0.0;           ///< the correction size that stops, in the model's norm
  int cap = kNewtonCap;             ///< iterations before the solve fails (>= 1)
  bool reuse = false;               ///< modified Newton: keep the matrix while it contracts
  double refresh_above = HUGE_VAL;  ///< with reuse: refresh after a correction above this
};

/// What a solve reports.
struct NewtonResult {
  bool converged = false;
  int iterations = 0;   ///< spent, converged or not (a repeat after a refresh counts)
  bool reused = false;  ///< the first iteration used a matrix kept from an earlier solve
};

/// Iterates `system` from its current iterate by `rule` (the header).
NewtonResult newton(NewtonSystem& system, const Rule& rule);

}  // namespace paths
