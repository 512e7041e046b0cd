#include "paths/time_stepping.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>

#include "ring/errors.hpp"

namespace paths {
namespace {

std::string seconds(double t) {
  std::ostringstream s;
  s.precision(6);
  s << t;
  return s.str();
}

/// The grid steps at which a snapshot is stored: `count` evenly spaced over 0 .. steps.
std::vector<long> snapshot_steps(long steps, int count) {
  std::vector<long> v;
  for (int i = 0; i < count; ++i)
    v.push_back(count == 1 ? steps : std::lround(double(steps) * i / (count - 1)));
  return v;
}

}  // namespace

ring::TimeHistory integrate(Stepper& stepper, const Grid& grid, const std::vector<double>& record_angles) {
  using Reason = ring::IntegrationFailure::Reason;
  ring::TimeHistory th;
  th.record_angles = record_angles;
  th.ux.assign(record_angles.size(), {});
  th.uy.assign(record_angles.size(), {});
  const long steps = std::lround(grid.t_end / grid.dt);
  const std::vector<long> snaps = snapshot_steps(steps, grid.snapshots);

  auto record = [&](double t, int iterations, long k) {
    const Sample s = stepper.sample();
    th.t.push_back(t);
    for (std::size_t i = 0; i < record_angles.size(); ++i) {
      th.ux[i].push_back(s.ux.at(i));
      th.uy[i].push_back(s.uy.at(i));
    }
    th.kinetic.push_back(s.kinetic);
    th.strain.push_back(s.strain);
    th.work.push_back(s.work);
    th.energy_error.push_back(s.kinetic + s.strain + s.dissipated + s.plastic.value_or(0.0) - s.work);
    if (s.plastic) th.dissipated.push_back(*s.plastic);
    th.constraint_residual.push_back(s.constraint_residual);
    th.newton_iterations.push_back(iterations);
    if (std::find(snaps.begin(), snaps.end(), k) != snaps.end()) {
      th.snapshot_t.push_back(t);
      th.snapshot_x.emplace_back();
      th.snapshot_y.emplace_back();
      stepper.shape(th.snapshot_x.back(), th.snapshot_y.back());
    }
    return s;
  };
  auto fail = [&](Reason why, const std::string& msg) {
    throw ring::IntegrationFailure(why, th.t.empty() ? 0.0 : th.t.back(), th, grid.who + ": " + msg);
  };

  const Sample s0 = record(0.0, 0, 0);
  if (grid.guard) grid.guard->start(s0.kinetic, s0.strain, s0.work);
  const double min_dt = grid.min_dt_factor * grid.dt;
  double t = 0.0, h = grid.dt;
  int successes = 0;
  const long stride = std::max(1L, steps / 200);
  // Also after every kProgressInterval of work, so that a caller who checks for an
  // interruption there (the Python module's Ctrl-C) hears from a long run often enough.
  using Clock = std::chrono::steady_clock;
  auto last_progress = Clock::now();
  double last_fraction = 0.0;  // never reported lower: a drop would read as a new run
  auto report = [&](double fraction) {
    last_fraction = std::max(last_fraction, fraction);
    grid.progress(last_fraction);
    last_progress = Clock::now();
  };
  auto report_if_due = [&](double fraction) {
    if (grid.progress && Clock::now() - last_progress >= std::chrono::duration<double>(kProgressInterval))
      report(fraction);
  };
  for (long k = 1; k <= steps; ++k) {
    const double t_target = grid.dt * double(k);
    int iterations = 0;
    bool retried = false;
    // Sub-steps end exactly on the grid; a remainder below 1e-7 dt is round-off. Never
    // a sliver: accelerations come from (x - x_hat) / (beta h^2), so a step of 1e-9 dt
    // would turn round-off into garbage; a remainder between h and 2 h is split in two.
    while (t_target - t > 1e-7 * grid.dt) {
      const double remaining = t_target - t;
      const bool last = remaining <= h * (1.0 + 1e-9);
      const double hs = last ? remaining : (remaining < 2.0 * h ? 0.5 * remaining : h);
      const StepOutcome o = stepper.try_step(t, hs);
      iterations += o.iterations;
      report_if_due(t / (grid.dt * double(steps)));
      if (!o.converged) {
        stepper.reject();
        if (o.retry && !retried) {
          retried = true;
          continue;
        }
        retried = false;
        h = 0.5 * hs;
        successes = 0;
        if (h < min_dt)
          fail(Reason::step_too_small,
               grid.min_dt_factor >= 1.0
                   ? "Newton did not converge at t = " + seconds(t) + " s in a step of " + seconds(hs) +
                         " s (this solver does not shorten its steps; try a smaller response.dt)"
                   : "Newton did not converge at t = " + seconds(t) + " s even with the step halved to " +
                         seconds(h) + " s (minimum " + seconds(min_dt) + " s)");
        continue;
      }
      retried = false;
      t = last ? t_target : t + hs;  // no round-off drift of the sub-steps
      stepper.accept(t);
      if (grid.guard) grid.guard->step(hs, o.load_factor);
      if (!stepper.finite()) fail(Reason::not_finite, "a non-finite state at t = " + seconds(t) + " s");
      if (grid.check_contact)
        if (const auto where = stepper.contact())
          fail(Reason::self_contact, "the ring touches itself at t = " + seconds(t) + " s: " + *where +
                                         "; the model does not include contact");
      if (h < grid.dt && ++successes >= grid.regrow_after) {
        h = std::min(2.0 * h, grid.dt);
        successes = 0;
      }
    }
    t = t_target;
    const Sample s = record(t, iterations, k);
    if (grid.guard) {
      const auto v = grid.guard->check(s.kinetic, s.strain + s.plastic.value_or(0.0), s.work);
      if (v.gained) fail(Reason::energy_growth, ring::describe(v, t) + grid.energy_hint);
    }
    if (grid.progress && (k % stride == 0 || k == steps)) report(double(k) / double(steps));
  }
  return th;
}

}  // namespace paths
