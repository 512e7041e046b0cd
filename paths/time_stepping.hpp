// The one time-stepping driver of the forced response, shared by every solver. It holds
// the policy; a solver supplies its model and one step through `Stepper` (the driver asks,
// the model answers, as SUNDIALS' IDA asks its user for residuals and Jacobians):
//
// - the time grid t_k = k dt, k = 0 .. round(t_end / dt), recorded at every grid point;
// - sub-steps when a step fails: the step is halved (down to min_dt_factor dt, below which
//   the run fails with step_too_small) and doubles again after `regrow_after` successes,
//   never beyond dt; sub-steps end exactly on the grid, a remainder between h and 2 h is
//   split in two equal steps and a remainder below 1e-7 dt is round-off;
// - a step that reports `retry` (its Newton matrix was stale) is tried once more at the
//   same size before it is halved;
// - after every accepted sub-step: a non-finite state fails (not_finite), and the
//   contact hook, when the model has one, fails with its message (self_contact);
// - after every grid step: the record (points, energies, constraint residual, Newton
//   iterations), `snapshots` deformed shapes evenly spaced over the grid, and the energy
//   guard (ring/energy_guard.hpp: a gain of T + V - W beyond 1 % of the work and the
//   round-off bound fails with energy_growth), and, every ~1/200 of the run and at least
//   every kProgressInterval of work, the optional progress callback with the fraction of
//   t_end reached;
// - every failure is ring::IntegrationFailure with the history up to the last grid point.
//
// Cost: the steps' own; the driver adds O(points) per grid step and O(nodes) per snapshot.
//
// Usage:
//   class MyStepper : public paths::Stepper { ... };
//   MyStepper s(model, options);
//   ring::TimeHistory h = paths::integrate(s, {dt, t_end}, record_angles);
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "ring/energy_guard.hpp"
#include "ring/results.hpp"

namespace paths {

/// What one attempted step reports.
struct StepOutcome {
  bool converged = false;
  /// Not converged, but worth one more try at the same size (a Newton matrix of an
  /// earlier state was reused; the stepper has dropped it).
  bool retry = false;
  int iterations = 0;  ///< Newton iterations spent, converged or not
  double load_factor = 0.0;  ///< the load factor the step's work used (the energy guard's)
};

/// The accepted state as the driver records it.
struct Sample {
  std::vector<double> ux, uy;      ///< displacement of each recorded point, reporting frame, m
  double kinetic = 0.0;            ///< J
  double strain = 0.0;             ///< J: the elastic energy of the model's springs or beam
  double work = 0.0;               ///< J: work of the external loads since t = 0
  double dissipated = 0.0;         ///< J: energy removed by damping since t = 0
  /// J: the plastic work since t = 0 (ring.plastic; `strain` is then the elastic energy
  /// stored); empty for an elastic model. Recorded as TimeHistory::dissipated, counted in
  /// energy_error, and held by the energy guard as energy the model took in.
  std::optional<double> plastic;
  double constraint_residual = 0.0;///< largest constraint violation, m (0 where there is none)
};

/// A solver's model and integrator, one step at a time.
class Stepper {
 public:
  virtual ~Stepper() = default;
  /// Computes a trial state a step of `h` after the accepted state at time `t`, leaving
  /// the accepted state unchanged.
  virtual StepOutcome try_step(double t, double h) = 0;
  /// The trial state becomes the accepted state, at time `t` (the driver's time, snapped
  /// to the grid at a grid point). Accumulates the work and the dissipated energy.
  virtual void accept(double t) = 0;
  /// The trial state of a step that did not converge is thrown away: a model with internal
  /// variables (paths/internal.hpp) discards their trial values. Default: nothing to do.
  virtual void reject() {}
  /// True when every value of the accepted state is finite.
  virtual bool finite() const = 0;
  /// The accepted state for the record.
  virtual Sample sample() const = 0;
  /// Node positions of the deformed ring (reporting frame, m), for the snapshots.
  virtual void shape(std::vector<double>& x, std::vector<double>& y) const = 0;
  /// The contact hook: a description of where the ring touches itself, if it does.
  virtual std::optional<std::string> contact() const { return std::nullopt; }
};

/// The grid and the policy knobs.
struct Grid {
  double dt = 0.0;             ///< the recorded step, s (> 0)
  double t_end = 0.0;          ///< s (>= dt)
  int snapshots = 6;           ///< deformed shapes stored, evenly spaced over the grid (>= 0)
  double min_dt_factor = 1e-6; ///< smallest sub-step, as a fraction of dt (1: no sub-steps)
  int regrow_after = 2;        ///< successful halved sub-steps before the step doubles
  /// The energy guard (ring/energy_guard.hpp), or null for none; the driver starts it,
  /// feeds it every accepted sub-step and checks it at every grid point.
  ring::EnergyGuard* guard = nullptr;
  bool check_contact = true;   ///< call the contact hook after every sub-step
  std::string energy_hint;     ///< appended to the energy guard's message (what to try instead)
  std::string who;             ///< the solver, named first in every message ("multibody::respond")
  /// Optional: called with the fraction of t_end reached after every `stride`-th grid step
  /// (stride = max(1, steps / 200)), at the end, and after any step attempt that ends
  /// kProgressInterval or more after the last call; empty: never (one test per step). An
  /// exception it throws ends the integration as that exception (an interruption).
  std::function<void(double fraction)> progress;
};

/// Seconds of work after which the driver calls Grid::progress at the latest (once a step
/// attempt ends): the Python module checks for Ctrl-C there, at least every 0.1 s.
constexpr double kProgressInterval = 0.05;

/// The node positions of a state stored as (x_0, y_0, x_1, y_1, ...), n nodes, as
/// Stepper::shape gives them. V: anything with operator[] (an Eigen vector, a std::vector).
template <class V>
void interleaved_shape(const V& state, int n, std::vector<double>& x, std::vector<double>& y) {
  x.resize(n);
  y.resize(n);
  for (int j = 0; j < n; ++j) {
    x[j] = state[2 * j];
    y[j] = state[2 * j + 1];
  }
}

/// Integrates from the stepper's initial (accepted) state at t = 0 over the grid.
/// Returns the history of the recorded points (`record_angles`, degrees). Throws
/// ring::IntegrationFailure (with the partial history) as above.
ring::TimeHistory integrate(Stepper& stepper, const Grid& grid, const std::vector<double>& record_angles);

}  // namespace paths
